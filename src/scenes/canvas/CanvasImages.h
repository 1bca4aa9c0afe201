#pragma once
// The canvas scene's CPU-side content: a painting (linear colour) and its material map (encoding in
// CanvasMaterial.h), either procedural or loaded from files, always at the render size.

#include "core/Image.h"
#include "scenes/canvas/CanvasMaterial.h"

#include <cstdint>
#include <filesystem>

namespace photopic {

struct CanvasImages {
    ImageF color;    ///< scene-linear Rec.709 albedo, rows top to bottom
    Image8 material; ///< same size as colour; see CanvasMaterial.h for the channels
};

struct ProceduralCanvasInfo {
    int width = 0;
    int height = 0;
    int tileSize = 256;     ///< px: material is laid on whole tiles of this grid
    double occupancy = 0.5; ///< [0, 1]: exactly round(occupancy * tiles) tiles get material
    std::uint32_t seed = 3; ///< picks the strokes, the glitter facets and the tiles
};

/// A landscape painted in brush strokes: swirling sky, a sun, hills, and water whose strokes (with the sun's)
/// carry glitter. Specular varnish and glitter lie only on the chosen tiles; the strokes' impasto normals are
/// everywhere (they shape the diffuse light too). Deterministic for a given info.
CanvasImages makeProceduralCanvas(const ProceduralCanvasInfo& info);

/// The painting's colour from a file (any format readImage takes; a PNG is sRGB-decoded), resampled
/// bilinearly to width x height. Throws IoError naming the file.
ImageF loadCanvasColor(const std::filesystem::path& path, int width, int height);

/// A material map from an RGBA PNG, stored values, resampled nearest-neighbour to width x height. Throws
/// IoError naming the file when it cannot be read or is not a valid material map (a normal outside the unit
/// disc).
Image8 loadCanvasMaterial(const std::filesystem::path& path, int width, int height);

} // namespace photopic
