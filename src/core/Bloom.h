#pragma once
// CPU side of the bloom pass (passes/bloom/): the soft-knee constants the prefilter shader needs and the
// chain's shape, computed and tested here, without a GPU.
//
// Reference: J. Jimenez, "Next Generation Post Processing in Call of Duty: Advanced Warfare", SIGGRAPH 2014
// (13-tap downsample, Karis average, tent upsample); the quadratic soft-knee threshold of
// Unity's and Bevy's bloom prefilter.

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
/// is the image divided by `firstDivisor` (2 or 4); each further level halves it; the smallest kept level
/// is at least 2 texels on its short side.
[[nodiscard]] int bloomMipCount(glm::ivec2 size, int firstDivisor, int wanted) noexcept;

/// Size of level `level` of the chain: max(1, size / (firstDivisor * 2^level)).
[[nodiscard]] glm::ivec2 bloomMipSize(glm::ivec2 size, int firstDivisor, int level) noexcept;

/// Weight of each level in the final bloom when every level keeps (1 - radius) and hands `radius` on to the
/// wider ones; the last level keeps what reaches it. The weights sum to 1 (energy is conserved).
[[nodiscard]] float bloomLevelWeight(float radius, int level, int levels) noexcept;

} // namespace photopic
