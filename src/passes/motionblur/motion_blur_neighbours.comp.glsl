// Motion blur, step 3 (McGuire et al. 2012, NeighborMax): the longest tile velocity among a tile and its
// eight neighbours. A blur radius is at most one tile, so every velocity that can reach a pixel is within
// them. Each tile is listed moving or still for the gather (motion_blur_lists.h.glsl).
#include "passes/motionblur/motion_blur_common.h.glsl"
#define MOTION_BLUR_LISTS_WRITE
#include "passes/motionblur/motion_blur_lists.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1, rg16f) uniform readonly image2D uTileMax;
layout(binding = 0, rg16f) uniform writeonly image2D uNeighbourMax;

void main() {
    ivec2 tile = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(tile, uTileCount))) {
        return;
    }
    vec2 m = imageLoad(uTileMax, tile).rg;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = tile + ivec2(dx, dy);
            if ((dx == 0 && dy == 0) || any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, uTileCount))) {
                continue;
            }
            m = longer(m, imageLoad(uTileMax, q).rg);
        }
    }
    imageStore(uNeighbourMax, tile, vec4(m, 0.0, 0.0));
    uint index = uint(tile.y * uTileCount.x + tile.x);
    if (length(m) >= kStillBelow) {
        listTiles[atomicAdd(movingArgs[2], 1u)] = index;
    } else { // NaN too: the gather copies it
        listTiles[uint(uTileCount.x * uTileCount.y) + atomicAdd(stillArgs[2], 1u)] = index;
    }
}
