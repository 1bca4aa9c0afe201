// The depth pyramid the hierarchical march reads (Uludag, "Hi-Z Screen-Space Cone-Traced Reflections", GPU
// Pro 5): level 0 is linearDepth, padded to a multiple of the coarsest cell with the sky; each further level
// keeps the nearest (r) and the farthest (g) depth of the 2 x 2 cells below it, so a ray in front of a cell's
// nearest depth is in front of every surface in the cell, and a ray behind its farthest depth by more than the
// thickness is behind every surface there by more than that. Broken depths (NaN, zero, negative) are the sky
// here: they hide nothing; the sky has no farthest depth (0: nothing to pass behind). Level 0's extent is a
// multiple of the coarsest cell (2^(levels - 1)), so every level halves exactly and a cell inside a level has
// its 2 x 2 cells below inside the level below. The levels share one image (ssr_pyramid.h.glsl).
//
// With PYRAMID_ONE_DISPATCH (sharedMemoryTiles(): a GPU) every level comes from one dispatch: a work group
// owns a 64 x 64 tile of level 0; each invocation reduces its 4 x 4 block to levels 1 and 2 itself, and the
// group reduces its 16 x 16 level-2 cells to level 6 in shared memory. Without it, a dispatch a level
// (uLevel 0 copies linearDepth, uLevel > 0 reduces level uLevel - 1): a software renderer runs that faster.
// Both give the same values (a minimum and a maximum are exact).
#include "passes/ssr/ssr_common.h.glsl" // validDepth (its parameter block is not used here)
#include "passes/ssr/ssr_pyramid.h.glsl"

layout(binding = 1, r32f) uniform readonly image2D uLinearDepth;
layout(location = 1) uniform ivec2 uSize0; // level 0's extent

// A pixel's (nearest, farthest): its depth twice, or the sky's (+inf, 0) for NaN, zero, negative and +inf.
vec2 sanitized(float z) { return validDepth(z) ? vec2(z) : vec2(infinity(), 0.0); }

// The pair of two cells together.
vec2 merged(vec2 a, vec2 b) { return vec2(min(a.x, b.x), max(a.y, b.y)); }

#if PYRAMID_ONE_DISPATCH
layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = 0, rg32f) uniform writeonly image2D uPyramid;
layout(location = 0) uniform int uLevelCount; // 1 to 7

shared vec2 sBounds[16][16];

// Cell c of level `level`, when the pyramid has that level and c lies inside it.
void storeLevel(int level, ivec2 c, vec2 z) {
    if (level < uLevelCount && all(lessThan(c, uSize0 >> level))) {
        imageStore(uPyramid, pyramidLevelOrigin(uSize0, level) + c, vec4(z, 0.0, 0.0));
    }
}

void main() {
    ivec2 local = ivec2(gl_LocalInvocationID.xy);
    ivec2 c2 = ivec2(gl_WorkGroupID.xy) * 16 + local; // this invocation's level-2 cell: a 4 x 4 block
    ivec2 depthSize = imageSize(uLinearDepth);
    vec2 z2 = sanitized(infinity());
    for (int j = 0; j < 4; ++j) {
        ivec2 c1 = 2 * c2 + ivec2(j & 1, j >> 1);
        vec2 z1 = sanitized(infinity());
        for (int k = 0; k < 4; ++k) {
            ivec2 p = 2 * c1 + ivec2(k & 1, k >> 1);
            vec2 z = sanitized(all(lessThan(p, depthSize)) ? imageLoad(uLinearDepth, p).r : infinity());
            storeLevel(0, p, z);
            z1 = merged(z1, z);
        }
        storeLevel(1, c1, z1);
        z2 = merged(z2, z1);
    }
    storeLevel(2, c2, z2);
    // Levels 3 to 6: the group's 16 x 16 cells halve each step, the lower-left invocations reducing them.
    vec2 z = z2;
    for (int level = 3, n = 8; level <= 6; ++level, n >>= 1) {
        sBounds[local.y][local.x] = z;
        barrier(); // the level below, complete in shared memory
        if (all(lessThan(local, ivec2(n)))) {
            ivec2 s = 2 * local;
            z = merged(merged(sBounds[s.y][s.x], sBounds[s.y][s.x + 1]),
                       merged(sBounds[s.y + 1][s.x], sBounds[s.y + 1][s.x + 1]));
            storeLevel(level, ivec2(gl_WorkGroupID.xy) * n + local, z);
        }
        barrier(); // every read of this level before the next is written over it
    }
}
#else
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0, rg32f) uniform image2D uPyramid;
layout(location = 0) uniform int uLevel;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uSize0 >> uLevel))) {
        return;
    }
    vec2 z;
    if (uLevel == 0) {
        z = sanitized(all(lessThan(p, imageSize(uLinearDepth))) ? imageLoad(uLinearDepth, p).r : infinity());
    } else {
        ivec2 q = pyramidLevelOrigin(uSize0, uLevel - 1) + 2 * p;
        z = merged(merged(imageLoad(uPyramid, q).rg, imageLoad(uPyramid, q + ivec2(1, 0)).rg),
                   merged(imageLoad(uPyramid, q + ivec2(0, 1)).rg, imageLoad(uPyramid, q + ivec2(1, 1)).rg));
    }
    imageStore(uPyramid, pyramidLevelOrigin(uSize0, uLevel) + p, vec4(z, 0.0, 0.0));
}
#endif
