#pragma once
// CPU references of the display-effects pass (passes/display/display_effects.comp.glsl), for tests.

namespace photopic {

/// Vignette multiplier in linear light at image UV (u, v): 1 - intensity * r^falloff, r = distance from the
/// centre normalised to 1 at the corners.
[[nodiscard]] float vignetteFactor(float u, float v, float intensity, float falloff) noexcept;

/// Dazzle amount in [0, strength]: clamp(max(0, appliedLog2 - targetLog2) / rangeEV, 0, 1) * strength.
[[nodiscard]] float dazzleAmount(float appliedLog2, float targetLog2, float rangeEV, float strength) noexcept;

} // namespace photopic
