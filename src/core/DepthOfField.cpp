#include "core/DepthOfField.h"

#include <algorithm>
#include <cmath>

namespace photopic {

float CocModel::radius(float z) const noexcept {
    float r = 0.0f;
    if (artistic) {
        if (std::isinf(z)) {
            r = bokehRadius;
        } else {
            r = bokehRadius * std::clamp((z - focalDistance) / focalRange, -1.0f, 1.0f);
        }
    } else {
        r = std::isinf(z) ? bias : scale / z + bias;
    }
    if (std::isnan(r)) {
        return 0.0f;
    }
    return std::clamp(r, -maxRadius, maxRadius);
}

CocModel cocModel(const DofSettings& s, const Lens& lens, int imageHeight) noexcept {
    CocModel m;
    m.maxRadius = s.maxCocRadius;
    m.artistic = s.mode == DofMode::Artistic;
    m.focalDistance = s.focalDistance;
    m.focalRange = s.focalRange;
    m.bokehRadius = s.bokehRadius;
    const double f = double(lens.focalLengthMm) * 1e-3; // metres (scene units)
    const double focus = std::max(double(lens.focusDistance), 1.001 * f);
    const double k = f * f * double(imageHeight) /
                     (2.0 * double(lens.fNumber) * (focus - f) * double(lens.sensorHeightMm) * 1e-3);
    m.bias = float(k);
    m.scale = float(-k * focus);
    return m;
}

float shutterTime(const Lens& lens, float dt) noexcept {
    if (lens.exposureTimeS > 0.0f) {
        return lens.exposureTimeS;
    }
    return std::max(dt, 0.0f) * lens.shutterAngleDeg / 360.0f;
}

float shutterFraction(const Lens& lens, float dt) noexcept {
    if (!(dt > 0.0f)) {
        return std::clamp(lens.shutterAngleDeg / 360.0f, 0.0f, 1.0f);
    }
    return std::clamp(shutterTime(lens, dt) / dt, 0.0f, 1.0f);
}

} // namespace photopic
