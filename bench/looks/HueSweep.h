#pragma once
// Part 1 of the looks measure: the Oklab hue shift of a colour through a tone curve, over an exposure ramp.

#include "Variants.h"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace looks {

/// A test colour, linear Rec.709.
struct TestColour {
    std::string name;
    glm::vec3 linear;
};

/// The primaries and secondaries at high chroma, and skin and sky (see HueSweep.cpp for the values).
[[nodiscard]] std::vector<TestColour> testColours();
/// A second opinion on the same question: the pure primaries (fixed points of per-channel curves) and the
/// ColorChecker's saturated patches.
[[nodiscard]] std::vector<TestColour> referenceColours();

inline constexpr float kRampFirstEv = -2.0f;
inline constexpr float kRampLastEv = 6.0f;
inline constexpr float kRampStepEv = 0.5f;
/// Points of the ramp count while the output's Oklab chroma is at least this share of its peak on the ramp.
inline constexpr float kCountedChromaShare = 0.10f;

struct HueShift {
    float worstDeg = 0.0f; ///< signed shift of the largest magnitude among the counted points
    float worstAtEv = 0.0f;
    float atMidDeg = 0.0f;            ///< the shift at EV 0 (luminance 0.18)
    float saturationKeptAtMid = 0.0f; ///< Oklab C/L at EV 0 over the input's (the scaled colour shown as is)
    float whiteAtEv = 0.0f; ///< first EV whose chroma is under the counted share (kRampLastEv + step: never)
};

/// Runs `colour` scaled to luminance 0.18 * 2^EV for EV over the ramp through the CPU curve of `variant`.
[[nodiscard]] HueShift measureHueShift(const Variant& variant, glm::vec3 colour);

/// Throws std::runtime_error when the Oklab implementation misses published reference values.
void checkOklab();

} // namespace looks
