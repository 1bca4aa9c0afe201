// Keeps the frame's finished HDR image (after TAA) as next frame's reflection source: level 0 of a mip chain
// whose further levels the glossy cones read. Level 0 is the sanitised image; a texel of level L is the mean
// of the 2 x 2 texels of level L - 1 below it, so of the 2^L x 2^L block of level 0 (the box filter, whose
// last odd row or column a level's floor(size / 2) leaves out).
// The chain takes as many levels as the texture has (at most six).
//
// With HISTORY_ONE_DISPATCH (sharedMemoryTiles(): a GPU) every level comes from one dispatch: a work group
// owns a 32 x 32 tile of level 0; an invocation stores its 4 x 4 texels and their means (levels 1 and 2), and
// the group reduces its 8 x 8 level-2 texels to level 5 in shared memory. Level L's texels inside the image
// depend on level 0's texels inside it only. Without it, a dispatch a level (uLevel 0 copies the image,
// uLevel > 0 reduces level uLevel - 1): a software renderer runs that faster. The two differ in the last bit
// of a half float where the one-dispatch build keeps a level's mean in full precision for the next.
#include "passes/common/sanitize.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1, rgba16f) uniform readonly image2D uScene;

// The mean of four texels of the level below, as every level computes it.
vec3 mean4(vec3 a, vec3 b, vec3 c, vec3 d) { return 0.25 * (a + b + c + d); }

#if HISTORY_ONE_DISPATCH
// Levels 0 to 5 of the history (a level past the texture's last is bound to level 0 and not written).
layout(binding = 0, rgba16f) uniform writeonly image2D uLevel0;
layout(binding = 2, rgba16f) uniform writeonly image2D uLevel1;
layout(binding = 3, rgba16f) uniform writeonly image2D uLevel2;
layout(binding = 4, rgba16f) uniform writeonly image2D uLevel3;
layout(binding = 5, rgba16f) uniform writeonly image2D uLevel4;
layout(binding = 6, rgba16f) uniform writeonly image2D uLevel5;
layout(location = 0) uniform int uLevels; // levels the texture has, 1 to 6

shared vec3 sMean[8][8];

// Level L's texel t (of a texture whose level 0 is `size0`), when it lies inside the level.
void storeLevel(int level, ivec2 t, ivec2 size0, vec3 c) {
    ivec2 size = max(size0 >> level, ivec2(1));
    if (level >= uLevels || any(greaterThanEqual(t, size))) {
        return;
    }
    vec4 v = vec4(c, 1.0);
    switch (level) {
    case 1: imageStore(uLevel1, t, v); break;
    case 2: imageStore(uLevel2, t, v); break;
    case 3: imageStore(uLevel3, t, v); break;
    case 4: imageStore(uLevel4, t, v); break;
    default: imageStore(uLevel5, t, v); break;
    }
}

void main() {
    ivec2 size0 = imageSize(uScene);
    ivec2 local = ivec2(gl_LocalInvocationID.xy);
    ivec2 t2 = ivec2(gl_WorkGroupID.xy) * 8 + local; // this invocation's level-2 texel: a 4 x 4 block
    vec3 level1[4];
    for (int j = 0; j < 4; ++j) {
        ivec2 t1 = 2 * t2 + ivec2(j & 1, j >> 1);
        vec3 level0[4];
        for (int k = 0; k < 4; ++k) {
            ivec2 p = 2 * t1 + ivec2(k & 1, k >> 1);
            level0[k] = vec3(0.0);
            if (all(lessThan(p, size0))) {
                level0[k] = sanitize(imageLoad(uScene, p).rgb); // half floats already
                imageStore(uLevel0, p, vec4(level0[k], 1.0));
            }
        }
        // The full 2 x 2 wherever the level-1 texel lies inside level 1.
        level1[j] = mean4(level0[0], level0[1], level0[2], level0[3]);
        storeLevel(1, t1, size0, level1[j]);
    }
    vec3 mean = mean4(level1[0], level1[1], level1[2], level1[3]);
    storeLevel(2, t2, size0, mean);
    // Levels 3 to 5: the group's 8 x 8 means halve each step, the lower-left invocations computing them.
    for (int level = 3, n = 4; level <= 5; ++level, n >>= 1) {
        sMean[local.y][local.x] = mean;
        barrier(); // the level below, complete in shared memory
        if (all(lessThan(local, ivec2(n)))) {
            ivec2 s = 2 * local;
            mean = mean4(sMean[s.y][s.x], sMean[s.y][s.x + 1], sMean[s.y + 1][s.x], sMean[s.y + 1][s.x + 1]);
            storeLevel(level, ivec2(gl_WorkGroupID.xy) * n + local, size0, mean);
        }
        barrier(); // every read of this level before the next is written over it
    }
}
#else
layout(binding = 2, rgba16f) uniform readonly image2D uBelow; // level uLevel - 1 (uLevel > 0)
layout(binding = 0, rgba16f) uniform writeonly image2D uTarget; // level uLevel
layout(location = 0) uniform int uLevel;

void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, imageSize(uTarget)))) {
        return;
    }
    vec3 c;
    if (uLevel == 0) {
        c = sanitize(imageLoad(uScene, t).rgb);
    } else {
        ivec2 q = 2 * t;
        c = mean4(imageLoad(uBelow, q).rgb, imageLoad(uBelow, q + ivec2(1, 0)).rgb,
                  imageLoad(uBelow, q + ivec2(0, 1)).rgb, imageLoad(uBelow, q + ivec2(1, 1)).rgb);
    }
    imageStore(uTarget, t, vec4(c, 1.0));
}
#endif
