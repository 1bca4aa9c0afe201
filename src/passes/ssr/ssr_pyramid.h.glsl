// The depth pyramid's layout, shared by the pass that builds it and the trace that reads it.
//
// All levels live in one single-level R32F texture (an atlas): level 0, the image padded to a whole number of
// the coarsest cells (size0, a multiple of 2^(levels - 1) on both axes), at the origin; level 1 to its right,
// from the bottom; each further level above the one before, in the same column. Level L is size0 >> L.
// Every read is an image load with an in-range coordinate: a mip chain would need a lod that differs between
// neighbouring invocations, which GLSL allows but which implementations that evaluate a texel fetch or a size
// query for a group of invocations at one invocation's lod get wrong (they read another level).
#ifndef PHOTOPIC_SSR_PYRAMID_H_GLSL
#define PHOTOPIC_SSR_PYRAMID_H_GLSL

ivec2 pyramidLevelOrigin(ivec2 size0, int level) {
    return level == 0 ? ivec2(0) : ivec2(size0.x, size0.y - (size0.y >> (level - 1)));
}

#endif
