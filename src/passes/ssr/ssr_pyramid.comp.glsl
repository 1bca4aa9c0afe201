// The depth pyramid the hierarchical march reads (Uludag, "Hi-Z Screen-Space Cone-Traced Reflections", GPU
// Pro 5): level 0 is linearDepth, padded to a multiple of the coarsest cell with the sky; each further level
// keeps the nearest depth of the 2 x 2 cells below it, so a ray in front of a cell's value is in front of
// every surface in the cell. Broken depths (NaN, zero, negative) are the sky here: they hide nothing. Level
// 0's extent is a multiple of the coarsest cell (2^(levels - 1)), so every level halves exactly and a cell
// inside a level has its 2 x 2 cells below inside the level below. The levels share one image
// (ssr_pyramid.h.glsl).
//
// With PYRAMID_ONE_DISPATCH (sharedMemoryTiles(): a GPU) every level comes from one dispatch: a work group
// owns a 64 x 64 tile of level 0; each invocation reduces its 4 x 4 block to levels 1 and 2 itself, and the
// group reduces its 16 x 16 level-2 cells to level 6 in shared memory. Without it, a dispatch a level
// (uLevel 0 copies linearDepth, uLevel > 0 reduces level uLevel - 1): a software renderer runs that faster.
// Both give the same values (a minimum is exact).
#include "passes/ssr/ssr_common.h.glsl" // validDepth (its parameter block is not used here)
#include "passes/ssr/ssr_pyramid.h.glsl"

layout(binding = 1, r32f) uniform readonly image2D uLinearDepth;
layout(location = 1) uniform ivec2 uSize0; // level 0's extent

float sanitized(float z) { return validDepth(z) ? z : infinity(); } // NaN, zero, negative, +inf: the sky

#if PYRAMID_ONE_DISPATCH
layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = 0, r32f) uniform writeonly image2D uPyramid;
layout(location = 0) uniform int uLevelCount; // 1 to 7

shared float sNearest[16][16];

// Cell c of level `level`, when the pyramid has that level and c lies inside it.
void storeLevel(int level, ivec2 c, float z) {
    if (level < uLevelCount && all(lessThan(c, uSize0 >> level))) {
        imageStore(uPyramid, pyramidLevelOrigin(uSize0, level) + c, vec4(z));
    }
}

void main() {
    ivec2 local = ivec2(gl_LocalInvocationID.xy);
    ivec2 c2 = ivec2(gl_WorkGroupID.xy) * 16 + local; // this invocation's level-2 cell: a 4 x 4 block
    ivec2 depthSize = imageSize(uLinearDepth);
    float z2 = infinity();
    for (int j = 0; j < 4; ++j) {
        ivec2 c1 = 2 * c2 + ivec2(j & 1, j >> 1);
        float z1 = infinity();
        for (int k = 0; k < 4; ++k) {
            ivec2 p = 2 * c1 + ivec2(k & 1, k >> 1);
            float z = all(lessThan(p, depthSize)) ? sanitized(imageLoad(uLinearDepth, p).r) : infinity();
            storeLevel(0, p, z);
            z1 = min(z1, z);
        }
        storeLevel(1, c1, z1);
        z2 = min(z2, z1);
    }
    storeLevel(2, c2, z2);
    // Levels 3 to 6: the group's 16 x 16 cells halve each step, the lower-left invocations reducing them.
    float z = z2;
    for (int level = 3, n = 8; level <= 6; ++level, n >>= 1) {
        sNearest[local.y][local.x] = z;
        barrier(); // the level below, complete in shared memory
        if (all(lessThan(local, ivec2(n)))) {
            ivec2 s = 2 * local;
            z = min(min(sNearest[s.y][s.x], sNearest[s.y][s.x + 1]),
                    min(sNearest[s.y + 1][s.x], sNearest[s.y + 1][s.x + 1]));
            storeLevel(level, ivec2(gl_WorkGroupID.xy) * n + local, z);
        }
        barrier(); // every read of this level before the next is written over it
    }
}
#else
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0, r32f) uniform image2D uPyramid;
layout(location = 0) uniform int uLevel;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uSize0 >> uLevel))) {
        return;
    }
    float z;
    if (uLevel == 0) {
        z = all(lessThan(p, imageSize(uLinearDepth))) ? sanitized(imageLoad(uLinearDepth, p).r) : infinity();
    } else {
        ivec2 q = pyramidLevelOrigin(uSize0, uLevel - 1) + 2 * p;
        z = min(min(imageLoad(uPyramid, q).r, imageLoad(uPyramid, q + ivec2(1, 0)).r),
                min(imageLoad(uPyramid, q + ivec2(0, 1)).r, imageLoad(uPyramid, q + ivec2(1, 1)).r));
    }
    imageStore(uPyramid, pyramidLevelOrigin(uSize0, uLevel) + p, vec4(z));
}
#endif
