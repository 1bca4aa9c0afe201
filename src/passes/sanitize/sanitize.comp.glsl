// Sanitise the host's HDR colour once, where the pipeline first reads it (the first step of the frame order,
// docs/architecture.md).
#include "passes/common/sanitize.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D uInput;
layout(binding = 0, rgba16f) writeonly uniform image2D uOutput;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(uOutput)))) {
        return;
    }
    imageStore(uOutput, p, vec4(sanitize(texelFetch(uInput, p, 0).rgb), 1.0));
}
