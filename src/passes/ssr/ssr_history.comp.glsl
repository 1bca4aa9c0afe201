// Keeps the frame's finished HDR image (after TAA) as next frame's reflection source: level 0 of a mip
// chain whose further levels the glossy cones read.
#include "passes/common/sanitize.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1, rgba16f) uniform readonly image2D uScene;
layout(binding = 0, rgba16f) uniform writeonly image2D uHistory;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(uHistory)))) {
        return;
    }
    imageStore(uHistory, p, vec4(sanitize(imageLoad(uScene, p).rgb), 1.0));
}
