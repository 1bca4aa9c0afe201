#pragma once
// Anti-aliasing's measure against the testbed's truth: the settings both go through, the pixels on object
// edges (from the ray tracer's object ids) and the display-referred RMSE over them.

#include "core/Image.h"
#include "core/Settings.h"

#include <cmath>
#include <vector>

namespace photopic::test {

/// Display settings for measuring: fixed exposure, no bloom, no dither, so the truth and the renders go
/// through the same curve.
inline Settings aaMeasuringSettings(AntiAliasing aa) {
    Settings s;
    s.tonemapping.mode = ToneMapper::AcesFitted;
    s.tonemapping.exposure = -1.0f;
    s.autoExposure.enabled = false;
    s.bloom.enabled = false;
    s.output.dither = false;
    s.aa.mode = aa;
    return s;
}

/// Pixels whose 3x3 neighbourhood in the ray tracer's object ids holds more than one object.
inline std::vector<bool> edgePixels(const ImageF& ids) {
    const int w = ids.width;
    const int h = ids.height;
    std::vector<bool> edge(std::size_t(w) * std::size_t(h), false);
    for (int y = 1; y < h - 1; ++y) {
        for (int x = 1; x < w - 1; ++x) {
            for (int d = 0; d < 9 && !edge[std::size_t(y * w + x)]; ++d)
                edge[std::size_t(y * w + x)] = ids.at(x + d % 3 - 1, y + d / 3 - 1)[0] != ids.at(x, y)[0];
        }
    }
    return edge;
}

/// RMSE of the sRGB codes (over 255) of `a` against `b` over the pixels `mask` holds.
inline double edgeRmse(const Image8& a, const Image8& b, const std::vector<bool>& mask) {
    double sum = 0.0;
    long n = 0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            if (!mask[std::size_t(y * a.width + x)])
                continue;
            for (int c = 0; c < 3; ++c) {
                const double d = (double(a.at(x, y)[c]) - double(b.at(x, y)[c])) / 255.0;
                sum += d * d;
            }
            ++n;
        }
    }
    return std::sqrt(sum / double(3 * n));
}

} // namespace photopic::test
