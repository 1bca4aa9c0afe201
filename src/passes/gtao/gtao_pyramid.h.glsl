#ifndef PHOTOPIC_GTAO_PYRAMID_H_GLSL
#define PHOTOPIC_GTAO_PYRAMID_H_GLSL

// The surface pyramid (ssao.sampleMips): levels 1-4 of the surface texture, each texel one real pixel of its
// 2^L x 2^L block, so the horizon search's far steps read a coarser level (XeGTAO's depth MIP chain: the
// samples of neighbouring pixels share cache lines) and still get a depth and a normal that belong together.
// One image, level 0 at the origin and level L >= 1 to its right: x from the full width, y below the levels
// before it (surfaceLevelOrigin). The pixel a cell keeps is picked by a hash of the cell and the level, not a
// fixed corner, so the coarse levels carry no systematic half-block shift; its place in the block rides in the
// depth's low 8 mantissa bits (x in bits 0-3, y in 4-7; a relative depth error under 3e-5), so a step finds
// the pixel's position without working the hash out again. The sky's texels keep their bits (+inf, not NaN).
// The pixel is decimated, not filtered (XeGTAO averages depths): the search's tangent-plane cut needs a depth
// and a normal of the same point.
#ifndef GTAO_SURFACE_LEVELS
#error GTAO_SURFACE_LEVELS: the coarse levels above level 0, from the host (GtaoPass::kSurfaceLevels)
#endif
const int kSurfaceLevels = GTAO_SURFACE_LEVELS;

ivec2 surfaceLevelOrigin(int level, ivec2 full) {
    // Bands of the height rounded up to 16 rows, halved level by level: level L starts at the band's
    // 1 - 2^(1-L) and its ceil(height / 2^L) rows fit before level L + 1 does. No table and no branch a step.
    int band = (full.y + 15) & ~15;
    return level == 0 ? ivec2(0) : ivec2(full.x, band - (band >> (level - 1)));
}

// The full-resolution pixel that level `level`'s cell `cell` keeps (itself at level 0). The block is cut to
// the image at its right and bottom edges; the pick scales 16 hash bits by the block's extent (no integer
// division, which SIMD CPU renderers run a lane at a time).
ivec2 surfacePick(ivec2 cell, int level, ivec2 full) {
    ivec2 corner = cell << level;
    uvec2 extent = uvec2(min(ivec2(1 << level), full - corner));
    uint h = uint(cell.x) * 0x8da6b343u + uint(cell.y) * 0xd8163841u + uint(level) * 0xcb1ab31fu;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    return corner + ivec2(((h & 0xFFFFu) * extent.x) >> 16, ((h >> 16) * extent.y) >> 16);
}

// A coarse level's texel: the surface texel of the pixel its cell keeps, the pixel's place in the block in
// the depth's low mantissa bits (where the depth is a surface's).
uvec2 coarseSurfaceTexel(uvec2 texel, ivec2 place) {
    float z = uintBitsToFloat(texel.x);
    bool surface = !isinf(z) && z > 0.0;
    return uvec2(surface ? (texel.x & 0xFFFFFF00u) | uint(place.x | (place.y << 4)) : texel.x, texel.y);
}

// The full-resolution pixel behind the texel whose depth bits are `depthBits`, at level `level`'s cell `cell`
// (at level 0 the mask drops the depth's own bits).
ivec2 coarseTexelPixel(uint depthBits, ivec2 cell, int level) {
    ivec2 place = ivec2(depthBits & 15u, (depthBits >> 4) & 15u) & ((1 << level) - 1);
    return (cell << level) + place;
}

#endif
