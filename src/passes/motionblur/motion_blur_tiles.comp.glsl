// Motion blur, step 2 (McGuire et al. 2012, TileMax): the longest velocity in each tileSize x tileSize tile.
// One invocation per tile.
#include "passes/motionblur/motion_blur_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1, rg16f) uniform readonly image2D uVelocity;
layout(binding = 0, rg16f) uniform writeonly image2D uTileMax;

void main() {
    ivec2 tile = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(tile, uTileCount))) {
        return;
    }
    ivec2 size = ivec2(uFullSize);
    ivec2 first = tile * uTileSize;
    ivec2 last = min(first + uTileSize, size);
    vec2 m = vec2(0.0);
    for (int y = first.y; y < last.y; ++y) {
        for (int x = first.x; x < last.x; ++x) {
            m = longer(m, imageLoad(uVelocity, ivec2(x, y)).rg);
        }
    }
    imageStore(uTileMax, tile, vec4(m, 0.0, 0.0));
}
