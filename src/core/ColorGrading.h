#pragma once
// CPU side of colour grading (in the tone-map pass): the white-balance matrix, computed once per frame here
// and handed to the shader as a mat3, plus a CPU reference of the whole grade for tests.
//
// White balance: a von Kries adaptation in Bradford cone space (Lam 1985; Hunt, "The Reproduction of Colour",
// 6th ed., ch. 13) from an assumed scene white to D65. The assumed white moves along the daylight locus with
// `temperature` and across it with `tint`, as in Unity's post-processing stack (ColorUtilities
// .ComputeColorBalance, which uses CAT02 instead of Bradford). Linear Rec.709 <-> XYZ: ITU-R BT.709 / sRGB
// primaries with D65 white.

#include "core/settings/ColorGradingSettings.h"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace photopic {

/// Linear Rec.709 -> linear Rec.709 matrix of the white balance; identity when temperature = tint = 0.
[[nodiscard]] glm::mat3 whiteBalanceMatrix(float temperature, float tint) noexcept;

/// The full grade on one colour, as the shader runs it: white balance, contrast (log2 around 0.18),
/// saturation (around Rec.709 luma), then gain, lift, gamma (ASC CDL order: slope, offset, power).
[[nodiscard]] glm::vec3 gradeColor(glm::vec3 c, const ColorGradingSettings& s) noexcept;

inline constexpr float kGradingMiddleGrey = 0.18f;

} // namespace photopic
