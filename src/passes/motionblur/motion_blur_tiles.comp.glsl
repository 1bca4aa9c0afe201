// Motion blur, step 2 (McGuire et al. 2012, TileMax): the longest velocity in each tileSize x tileSize tile,
// the first in row order among equally long ones (zero where none is longer than zero).
//
// With TILES_SHARED (sharedMemoryTiles(): a GPU) a work group of 8 x 8 invocations per tile, each scanning
// every eighth row and column of it, their 64 candidates reduced in shared memory; without it one invocation
// per tile scans it all, which a software renderer runs faster. Both pick the same velocity: each candidate
// carries its place in the tile's row order, which breaks ties.
#include "passes/motionblur/motion_blur_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1, rg16f) uniform readonly image2D uVelocity;
layout(binding = 0, rg16f) uniform writeonly image2D uTileMax;

#if TILES_SHARED
shared vec2 sVelocity[64];
shared int sOrder[64];

// Whether candidate (a, its row-order place ia) goes before (b, ib): longer, or as long and earlier.
bool before(vec2 a, int ia, vec2 b, int ib) {
    float la = dot(a, a), lb = dot(b, b);
    return la > lb || (la == lb && ia < ib);
}

void main() {
    ivec2 tile = ivec2(gl_WorkGroupID.xy);
    ivec2 local = ivec2(gl_LocalInvocationID.xy);
    int index = int(gl_LocalInvocationIndex);
    ivec2 first = tile * uTileSize;
    ivec2 last = min(first + uTileSize, ivec2(uFullSize));
    // Zero, placed before every texel: what the single scan starts from and keeps on a tie.
    vec2 m = vec2(0.0);
    int order = -1;
    for (int y = first.y + local.y; y < last.y; y += 8) {
        for (int x = first.x + local.x; x < last.x; x += 8) {
            vec2 v = imageLoad(uVelocity, ivec2(x, y)).rg;
            int o = (y - first.y) * uTileSize + (x - first.x);
            if (before(v, o, m, order)) {
                m = v;
                order = o;
            }
        }
    }
    sVelocity[index] = m;
    sOrder[index] = order;
    for (int n = 32; n > 0; n >>= 1) {
        barrier(); // the candidates of the step before, complete
        if (index < n && before(sVelocity[index + n], sOrder[index + n], sVelocity[index], sOrder[index])) {
            sVelocity[index] = sVelocity[index + n];
            sOrder[index] = sOrder[index + n];
        }
    }
    if (index == 0) {
        imageStore(uTileMax, tile, vec4(sVelocity[0], 0.0, 0.0));
    }
}
#else
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
#endif
