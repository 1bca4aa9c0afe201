#pragma once
// Internal to the core library: the ACES 1.x curve of toneMap (ToneMapper::Aces), in ToneCurvesAces.cpp.

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace photopic::detail {

/// ACES 1.x RRT + sRGB 100-nit dim ODT of exposed linear Rec.709 clamped to [0, 65504]: display-linear
/// Rec.709 in [0, 1].
glm::vec3 aces(glm::vec3 rgb);

} // namespace photopic::detail
