#pragma once
// CPU side of the bloom pass (passes/bloom/): the soft-knee constants the prefilter shader needs and the
// chain's shape, computed and tested here, without a GPU.
//
// The chain sums, level by level, the frame blurred by Gaussians whose widths double (the pyramid of
// Jimenez, "Next Generation Post Processing in Call of Duty: Advanced Warfare", SIGGRAPH 2014, with each
// level's kernel made Gaussian so the sum is radially symmetric: docs/architecture.md, "Bloom"); the
// quadratic soft-knee threshold of Unity's and Bevy's bloom prefilter.

#include <array>
#include <span>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace photopic {

/// Soft-knee threshold constants, packed for one vec4 uniform:
/// x = threshold T, y = T - knee, z = 2 knee, w = 1 / (4 knee), with knee = T * k + 1e-5.
[[nodiscard]] glm::vec4 bloomKneeConstants(float threshold, float kneeFraction) noexcept;

/// Fraction of a colour with max channel `brightness` that passes the threshold (the shader's factor):
/// max(rq, br - T) / max(br, 1e-4) with rq = clamp(br - (T - knee), 0, 2 knee)^2 / (4 knee).
[[nodiscard]] float bloomPrefilterFactor(float brightness, const glm::vec4& knee) noexcept;

/// Levels the chain gets for an image: `wanted` (>= 1), fewer when the image is too small for them. Level 0
/// is the image divided by `firstDivisor` (2 or 4); each further level halves it; a level past the first
/// keeps at least 4 texels on its short side: a coarser one would draw its Gaussian from a texel or two,
/// and bilinear reads of so few texels give a glow with corners.
[[nodiscard]] int bloomMipCount(glm::ivec2 size, int firstDivisor, int wanted) noexcept;

/// Size of level `level` of the chain: max(1, size / (firstDivisor * 2^level)).
[[nodiscard]] glm::ivec2 bloomMipSize(glm::ivec2 size, int firstDivisor, int level) noexcept;

/// Texels of guard band every level keeps on each side of the frame's region. The source outside the frame
/// is black, so a level's downsampled texels are zero more than a texel past the frame, and its blurred and
/// upsampled texels need computing only as far out as the next finer level's bilinear reads reach (one
/// texel): with this band, the glow of a light near the border is the glow it has in the middle, cut by the
/// frame, instead of being folded back in (clamp to edge) or faded out (a zero border on blurred levels).
inline constexpr int kBloomMargin = 2;

/// Frame pixels per texel of level `level`: firstDivisor * 2^level.
[[nodiscard]] int bloomLevelScale(int firstDivisor, int level) noexcept;

/// Texels of level `level` that cover the frame: ceil(size / bloomLevelScale), at least 1. The level's
/// texture holds kBloomMargin more on every side; the chain's result (level 0) is this region alone.
[[nodiscard]] glm::ivec2 bloomLevelFrame(glm::ivec2 size, int firstDivisor, int level) noexcept;

/// The Gaussian every level is blurred with, in that level's texels: sigma 2, cut at 4 sigma (17 texels).
inline constexpr float kBloomBlurSigma = 2.0f;
inline constexpr int kBloomBlurReach = 8;

/// The level blur's weights along an axis, of the texel itself (0) and of its neighbours 1 .. 8 texels away
/// on either side: the Gaussian cut at kBloomBlurReach and renormalised, so the 17 weights sum to 1.
[[nodiscard]] std::array<float, kBloomBlurReach + 1> bloomBlurWeights() noexcept;

/// The prefilter's weights along an axis over the frame texels under one level-0 texel and around it:
/// [1 3 3 1] / 8 for a first divisor of 2 (frame texels 2t - 1 .. 2t + 2 of level texel t), the same
/// binomial at twice the spacing convolved with it, [1 3 6 10 12 12 10 6 3 1] / 64, for 4 (texels
/// 4t - 3 .. 4t + 6). Every later level takes [1 3 3 1] / 8 of the one above.
[[nodiscard]] std::span<const float> bloomPrefilterWeights(int firstDivisor) noexcept;

/// Weight of each level in the final bloom when every level keeps (1 - radius) and hands `radius` on to the
/// wider ones; the last level keeps what reaches it. The weights sum to 1 (energy is conserved).
[[nodiscard]] float bloomLevelWeight(float radius, int level, int levels) noexcept;

} // namespace photopic
