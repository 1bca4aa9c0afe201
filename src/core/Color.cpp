#include "core/Color.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace photopic {

namespace {
// IEC 61966-2-1 constants.
constexpr float kSrgbLinearBreak = 0.0031308f; // linear value where the curve turns from linear to power
constexpr float kSrgbEncodedBreak = 0.04045f;  // the same point, encoded
constexpr float kSrgbSlope = 12.92f;
constexpr float kSrgbScale = 1.055f;
constexpr float kSrgbOffset = 0.055f;
constexpr float kSrgbGamma = 2.4f;
} // namespace

float luma709(glm::vec3 linearRgb) noexcept {
    return 0.2126f * linearRgb.r + 0.7152f * linearRgb.g + 0.0722f * linearRgb.b;
}

float srgbEncode(float linear) noexcept {
    const float x = std::clamp(linear, 0.0f, 1.0f);
    if (x <= kSrgbLinearBreak) {
        return kSrgbSlope * x;
    }
    return kSrgbScale * std::pow(x, 1.0f / kSrgbGamma) - kSrgbOffset;
}

float srgbDecode(float encoded) noexcept {
    if (encoded <= kSrgbEncodedBreak) {
        return encoded / kSrgbSlope;
    }
    return std::pow((encoded + kSrgbOffset) / kSrgbScale, kSrgbGamma);
}

glm::vec3 srgbEncode(glm::vec3 linear) noexcept {
    return {srgbEncode(linear.r), srgbEncode(linear.g), srgbEncode(linear.b)};
}

glm::vec3 srgbDecode(glm::vec3 encoded) noexcept {
    return {srgbDecode(encoded.r), srgbDecode(encoded.g), srgbDecode(encoded.b)};
}

float ev100FromCamera(float aperture, float shutterSeconds, float iso) noexcept {
    // EV100 = log2(N^2 / t) - log2(S / 100) (Frostbite notes, section 5.1).
    return std::log2(aperture * aperture / shutterSeconds * 100.0f / iso);
}

float ev100FromLuminance(float avgLuminance, float iso, float K) noexcept {
    // EV100 = log2(L * S / K); K = 12.5 is the reflected-light meter calibration constant (ISO 2720).
    const float luminance = std::max(avgLuminance, std::numeric_limits<float>::min());
    return std::log2(luminance * iso / K);
}

float exposureFromEv100(float ev100) noexcept {
    // Saturation-based speed (ISO 12232): Lmax = 78 / (q * S) * 2^EV100 * (S / 100); with q = 0.65 that is
    // 1.2 * 2^EV100, independent of S.
    return 1.0f / (1.2f * std::exp2(ev100));
}

} // namespace photopic
