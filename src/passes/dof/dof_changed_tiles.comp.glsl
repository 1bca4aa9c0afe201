// Depth of field, step 5a: the 8x8 tiles of the image the composite changes, listed for it. A pixel keeps
// its sharp value exactly unless its own CoC passes half a pixel (the far field's blend) or the near field's
// coverage is above zero at one of the four half-resolution texels its bilinear lookup reads; a tile where
// no pixel does either is the sharp image, which an image copy gives. One invocation a tile; NaN CoCs and
// coverages count as changing (the composite decides what they do). The last tile classified looks at the
// count: over three quarters of the tiles, the composite over every pixel costs less than the listed one
// (whose work groups each look their tile up) on top of the copy, and runs instead.
#include "passes/dof/dof_common.h.glsl"
#define DOF_TILES_WRITE
#include "passes/dof/dof_changed_tiles.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1, r16f) uniform readonly image2D uCoc;  // signed, full-resolution pixels
layout(binding = 2, rgba16f) uniform readonly image2D uNear; // half resolution, rgb + coverage (the near gather's output)

void main() {
    ivec2 tile = ivec2(gl_GlobalInvocationID.xy);
    ivec2 tiles = compositeTileCount();
    if (any(greaterThanEqual(tile, tiles))) {
        return;
    }
    ivec2 first = tile * kCompositeTile;
    ivec2 last = min(first + kCompositeTile - 1, ivec2(uFullSize) - 1);
    bool changed = false;
    for (int y = 0; y < kCompositeTile; ++y) {
        for (int x = 0; x < kCompositeTile; ++x) {
            changed = changed || !(imageLoad(uCoc, min(first + ivec2(x, y), last)).r <= 0.5);
        }
    }
    // The half-resolution texels the tile's bilinear lookups read (the composite's coordinates: uv x size -
    // 0.5), at most 6 x 6.
    vec2 low = (vec2(first) + 0.5) / uFullSize * uHalfSize - 0.5;
    vec2 high = (vec2(last) + 0.5) / uFullSize * uHalfSize - 0.5;
    ivec2 lastTexel = ivec2(uHalfSize) - 1;
    ivec2 from = clamp(ivec2(floor(low)), ivec2(0), lastTexel);
    ivec2 to = clamp(ivec2(floor(high)) + 1, ivec2(0), lastTexel);
    for (int y = 0; y < 6; ++y) {
        for (int x = 0; x < 6; ++x) {
            changed = changed || !(imageLoad(uNear, min(from + ivec2(x, y), to)).a <= 0.0);
        }
    }
    if (changed) {
        changedTiles[atomicAdd(changedArgs[2], 1u)] = uint(tile.y * tiles.x + tile.x);
    }
    // Every append is made visible before the tile counts as done, so the last one sees the final count.
    memoryBarrierBuffer();
    uint total = uint(tiles.x * tiles.y);
    if (atomicAdd(tilesDone, 1u) == total - 1u) {
        uint listedCount = atomicAdd(changedArgs[2], 0u);
        if (4u * listedCount > 3u * total) {
            atomicExchange(changedArgs[2], 0u);
            atomicExchange(fullArgs[2], 1u);
        }
    }
}
