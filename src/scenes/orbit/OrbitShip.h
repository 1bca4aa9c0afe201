#pragma once
// The orbit scene's default ship, built in code as the same Model a glTF file loads into (GltfModel.h), so
// one upload and one material shader serve both. Its parts are chosen to exercise a metallic-roughness
// renderer: painted hull panels (base colour, normal, occlusion and metal-rough textures), gold MLI foil
// (a coloured metal with a crinkled normal map), solar arrays (a dielectric cell texture behind a glossy
// cover), engine bells (rough dark metal, seen inside and out), a polished docking ring, thin truss rods
// that alias without anti-aliasing, and window lights (an emissive texture). No GL here.

#include "scenes/orbit/GltfModel.h"

namespace photopic::orbit {

/// The ship's mesh instances, in Model::meshes order (object id = ids::kFirstShip + index).
enum class ShipPart : int { Hull, Foil, SolarArrays, Truss, EngineBells, DockingRing, Lights, Count };

/// The ship, centred near the origin, its long axis along z (nose towards +z), about 27 m across the solar
/// arrays. Deterministic.
[[nodiscard]] Model buildShip();

} // namespace photopic::orbit
