#pragma once
// View-space normals as a host hands them octahedral-encoded (NormalEncoding::Octahedral, Cigolle et al.
// 2014), encoded on the CPU so the passes' decoders are checked against an encoder of their own.

#include "core/Image.h"

#include <cmath>

namespace photopic::test {

/// Each pixel's normal (channels 0-2; need not be unit) as its octahedral pair in channels 0-1, [-1, 1]^2.
inline ImageF octahedralEncoded(const ImageF& normals) {
    ImageF encoded(normals.width, normals.height, 0.0f);
    for (int y = 0; y < normals.height; ++y) {
        for (int x = 0; x < normals.width; ++x) {
            const float* n = normals.at(x, y);
            const float l1 = std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]);
            float ex = l1 > 0.0f ? n[0] / l1 : 0.0f;
            float ey = l1 > 0.0f ? n[1] / l1 : 0.0f;
            if (l1 > 0.0f && n[2] < 0.0f) {
                const float fx = (1.0f - std::abs(ey)) * (ex >= 0.0f ? 1.0f : -1.0f);
                const float fy = (1.0f - std::abs(ex)) * (ey >= 0.0f ? 1.0f : -1.0f);
                ex = fx;
                ey = fy;
            }
            encoded.at(x, y)[0] = ex;
            encoded.at(x, y)[1] = ey;
        }
    }
    return encoded;
}

} // namespace photopic::test
