// Depth of field, step 1: each pixel's signed circle of confusion (full resolution, pixels; < 0 near, > 0
// far) from its linear depth, by the thin lens (r = K (z - F) / z, core/DepthOfField.h) or the artistic
// focal distance and range.
#include "passes/dof/dof_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1, r32f) uniform readonly image2D uLinearDepth; // R32F, +inf: sky
layout(binding = 0, r16f) uniform writeonly image2D uCoc;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(uFullSize)))) {
        return;
    }
    imageStore(uCoc, p, vec4(cocRadius(imageLoad(uLinearDepth, p).r)));
}
