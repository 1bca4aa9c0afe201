#include "core/DisplayEffects.h"

#include <algorithm>
#include <cmath>

namespace photopic {

float vignetteFactor(float u, float v, float intensity, float falloff) noexcept {
    const float r = std::min(std::hypot(u - 0.5f, v - 0.5f) / 0.70710678f, 1.0f);
    return 1.0f - intensity * std::pow(r, falloff);
}

float dazzleAmount(float appliedLog2, float targetLog2, float rangeEV, float strength) noexcept {
    return std::clamp(std::max(0.0f, appliedLog2 - targetLog2) / rangeEV, 0.0f, 1.0f) * strength;
}

} // namespace photopic
