#pragma once
// Oklab (Björn Ottosson, "A perceptual color space for image processing", 2020): linear sRGB -> LMS ->
// cube root -> Lab, with the matrices of that post. Used for hue angles because Oklab's hue lines are close
// to constant perceived hue (unlike CIELAB's blue, which bends towards purple and would blame the curves for
// the metric's own error).

#include <glm/vec3.hpp>

#include <cmath>
#include <numbers>

namespace looks {

/// Linear Rec.709/sRGB (D65) to Oklab (L, a, b). Negative LMS values keep their sign through the cube root.
inline glm::vec3 linearSrgbToOklab(glm::vec3 c) {
    const float l = 0.4122214708f * c.r + 0.5363325363f * c.g + 0.0514459929f * c.b;
    const float m = 0.2119034982f * c.r + 0.6806995451f * c.g + 0.1073969566f * c.b;
    const float s = 0.0883024619f * c.r + 0.2817188376f * c.g + 0.6299787005f * c.b;
    const float l3 = std::cbrt(l), m3 = std::cbrt(m), s3 = std::cbrt(s);
    return {0.2104542553f * l3 + 0.7936177850f * m3 - 0.0040720468f * s3,
            1.9779984951f * l3 - 2.4285922050f * m3 + 0.4505937099f * s3,
            0.0259040371f * l3 + 0.7827717662f * m3 - 0.8086757660f * s3};
}

/// Oklab chroma sqrt(a^2 + b^2).
inline float oklabChroma(glm::vec3 lab) {
    return std::hypot(lab.y, lab.z);
}

/// Oklab hue angle atan2(b, a) in degrees, [0, 360).
inline float oklabHueDeg(glm::vec3 lab) {
    const float h = std::atan2(lab.z, lab.y) * 180.0f / std::numbers::pi_v<float>;
    return h < 0.0f ? h + 360.0f : h;
}

/// to - from, wrapped into (-180, 180]: the shorter way round the hue circle, signed (positive is
/// anticlockwise in the a-b plane: red -> yellow -> green -> blue -> purple -> red).
inline float hueDifferenceDeg(float to, float from) {
    float d = std::fmod(to - from, 360.0f);
    if (d > 180.0f) {
        d -= 360.0f;
    } else if (d <= -180.0f) {
        d += 360.0f;
    }
    return d;
}

} // namespace looks
