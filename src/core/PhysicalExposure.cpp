#include "core/PhysicalExposure.h"

#include "core/Color.h"
#include "core/DepthOfField.h"

#include <algorithm>
#include <cmath>

namespace photopic {

float cameraEv100(const Lens& lens, float dt) noexcept {
    const float t = std::max(shutterTime(lens, dt), 1e-6f);
    return ev100FromCamera(lens.fNumber, t, lens.iso);
}

float cameraExposureLog2(const Lens& lens, float dt) noexcept {
    return std::log2(exposureFromEv100(cameraEv100(lens, dt)));
}

PhysicalExposureInputs physicalExposure(const AutoExposureSettings& autoExposure, float manualEV,
                                        const Lens& lens, float dt) noexcept {
    return physicalExposure(autoExposure, manualEV, cameraExposureLog2(lens, dt));
}

PhysicalExposureInputs physicalExposure(const AutoExposureSettings& autoExposure, float manualEV,
                                        float camera) noexcept {
    PhysicalExposureInputs out{autoExposure, manualEV};
    if (!std::isfinite(camera)) {
        return out;
    }
    out.manualEV = manualEV + camera;
    // target = log2(key) - log2(L) + compensation, clamped: with L the camera-exposed luminance
    // (L 2^camera), the target is the correction on top of the camera's exposure.
    out.autoExposure.compensationEV = autoExposure.compensationEV - camera;
    return out;
}

} // namespace photopic
