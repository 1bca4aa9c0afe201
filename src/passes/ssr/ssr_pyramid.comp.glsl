// The depth pyramid the hierarchical march reads (Uludag, "Hi-Z Screen-Space Cone-Traced Reflections", GPU
// Pro 5): level 0 is linearDepth, padded to a multiple of the coarsest cell with the sky; each further level
// keeps the nearest depth of the 2 x 2 cells below it, so a ray in front of a cell's value is in front of
// every surface in the cell. Broken depths (NaN, zero, negative) are the sky here: they hide nothing.
// uLevel 0 copies linearDepth; uLevel > 0 reduces level uLevel - 1. The levels share one image
// (ssr_pyramid.h.glsl): a dispatch reads one level's texels and writes another's, never the same texel.
#include "passes/ssr/ssr_common.h.glsl" // validDepth (its parameter block is not used here)
#include "passes/ssr/ssr_pyramid.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uLinearDepth;
layout(binding = 0, r32f) uniform image2D uPyramid;
layout(location = 0) uniform int uLevel;
layout(location = 1) uniform ivec2 uSize0; // level 0's extent

float sanitized(float z) { return validDepth(z) ? z : infinity(); } // NaN, zero, negative, +inf: the sky

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uSize0 >> uLevel))) {
        return;
    }
    float z;
    if (uLevel == 0) {
        ivec2 depthSize = textureSize(uLinearDepth, 0);
        z = all(lessThan(p, depthSize)) ? sanitized(texelFetch(uLinearDepth, p, 0).r) : infinity();
    } else {
        // size0 is a multiple of 2^(levels - 1): the 2 x 2 cells below are all inside level uLevel - 1.
        ivec2 q = pyramidLevelOrigin(uSize0, uLevel - 1) + 2 * p;
        z = min(min(imageLoad(uPyramid, q).r, imageLoad(uPyramid, q + ivec2(1, 0)).r),
                min(imageLoad(uPyramid, q + ivec2(0, 1)).r, imageLoad(uPyramid, q + ivec2(1, 1)).r));
    }
    imageStore(uPyramid, pyramidLevelOrigin(uSize0, uLevel) + p, vec4(z));
}
