// The depth pyramid the hierarchical march reads (Uludag, "Hi-Z Screen-Space Cone-Traced Reflections", GPU
// Pro 5): level 0 is linearDepth, padded to a multiple of the coarsest cell with the sky; each further level
// keeps the nearest depth of the 2 x 2 cells below it, so a ray in front of a cell's value is in front of
// every surface in the cell. Broken depths (NaN, zero, negative) are the sky here: they hide nothing.
// uLevel 0 copies linearDepth; uLevel > 0 reduces level uLevel - 1.
#include "passes/common/inputs.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uLinearDepth;
layout(binding = 0, r32f) uniform readonly image2D uSource;
layout(binding = 1, r32f) uniform writeonly image2D uTarget;
layout(location = 0) uniform int uLevel;

float sanitized(float z) { return z > 0.0 ? z : infinity(); } // NaN and +inf fail or stay: both the sky

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uTarget);
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    float z;
    if (uLevel == 0) {
        ivec2 depthSize = textureSize(uLinearDepth, 0);
        z = all(lessThan(p, depthSize)) ? sanitized(texelFetch(uLinearDepth, p, 0).r) : infinity();
    } else {
        ivec2 q = 2 * p;
        z = min(min(imageLoad(uSource, q).r, imageLoad(uSource, q + ivec2(1, 0)).r),
                min(imageLoad(uSource, q + ivec2(0, 1)).r, imageLoad(uSource, q + ivec2(1, 1)).r));
    }
    imageStore(uTarget, p, vec4(z));
}
