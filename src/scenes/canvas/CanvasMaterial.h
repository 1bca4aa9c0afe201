#pragma once
// The canvas scene's material map and tile occupancy (per-pixel material, sparkle, tiles with material),
// GL-free: the encoding of the material texture, the tile grid, which tiles hold material, and a CPU
// reference of the per-pixel shading that the GPU paths are tested against.
//
// Material map, 8-bit RGBA, stored values (no sRGB decoding):
//   R, G  normal x, y in [-1, 1] as (v + 1) / 2 (z = sqrt(1 - x^2 - y^2), towards the viewer); on glitter
//   pixels
//         this is the facet normal
//   B     shininess: 0 = no specular (matte); otherwise Blinn-Phong exponent n = 2^(11 B / 255), ~1 to 2048
//   A     glitter mask: >= 128 the pixel is a glitter facet, < 128 it is not
// A pixel "has material" when B > 0 or A >= 128; a tile has material when any of its pixels has.

#include "core/Image.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace photopic {

/// Glitter sparkle: sparkle = pow(max(dot(facetNormal, L), 0), 128), added when > 0.9.
inline constexpr float kSparkleExponent = 128.0f;
inline constexpr float kSparkleGate = 0.9f;
/// Largest shininess exponent the material encodes (B = 255 -> 2^11).
inline constexpr float kMaxShininessLog2 = 11.0f;

/// cos of the widest angle between facet normal and light that still sparkles: 0.9^(1/128) (about 2.3
/// degrees).
float sparkleCosine();

glm::vec3 decodeMaterialNormal(std::uint8_t r, std::uint8_t g);
/// Encodes a normal's x, y (z is implied); rounds to the nearest code.
void encodeMaterialNormal(glm::vec3 n, std::uint8_t& r, std::uint8_t& g);
/// 0 for B = 0 (no specular), else 2^(11 B / 255).
float decodeShininess(std::uint8_t b);
inline bool hasMaterial(const std::uint8_t* rgba) {
    return rgba[2] > 0 || rgba[3] >= 128;
}

/// Square tiles over the image, counted from the texture's origin (bottom-left, GL texel space), so that the
/// GPU's tile (gl_WorkGroupID-based) and the CPU's are the same; the last column and top row may be partial.
struct TileGrid {
    int tileSize = 256; ///< px
    int tilesX = 0;
    int tilesY = 0;
    [[nodiscard]] int count() const { return tilesX * tilesY; }
    /// Tile index (row-major from the bottom-left) of image pixel (x, y), y counted top-down in an image of
    /// `height` rows.
    [[nodiscard]] int tileOfImagePixel(int x, int y, int height) const {
        return ((height - 1 - y) / tileSize) * tilesX + x / tileSize;
    }
};
TileGrid makeTileGrid(int width, int height, int tileSize);

/// Exactly round(fraction * count) tiles flagged 1, picked in a hashed order from `seed` (deterministic,
/// spread over the image).
std::vector<std::uint8_t> chooseTiles(const TileGrid& grid, double fraction, std::uint32_t seed);
/// hasMaterial per tile of `material` (the occupancy map that tiled shading reads).
std::vector<std::uint8_t> tileOccupancy(const Image8& material, const TileGrid& grid);

/// Everything a pixel's shading needs besides its textures (mirrors canvas_shade.comp.glsl's uniforms).
struct CanvasLighting {
    glm::vec3 light{0, 0,
                    1}; ///< canvasLightDirection(): unit, towards the lamp, canvas frame (z to the viewer)
    glm::vec3 lightColor{1, 1, 1};
    float ambient = 0.25f;        ///< fraction of the lamp reaching the canvas as fill
    float specular = 1.0f;        ///< Blinn-Phong strength ks
    float sparkleExposure = 4.0f; ///< exposure multiplying the sparkle
    float viewDistance = 1.5f;    ///< eye distance from the canvas centre, in image heights
};

/// Position of pixel (x, y) (texel space, y up, centres at +0.5) on the canvas in image heights, centre
/// origin.
glm::vec3 canvasPosition(float x, float y, float width, float height);

/// CPU reference of the shading: base * lamp * (ambient + N.L) + ks (N.H)^n + gated sparkle * exposure.
glm::vec3 shadeCanvasPixel(glm::vec3 base, const std::uint8_t* material, glm::vec3 position,
                           const CanvasLighting& lighting);

} // namespace photopic
