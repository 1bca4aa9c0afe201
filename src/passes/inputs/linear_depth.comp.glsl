// The host's depth, any kind, as positive linear view depth in scene units (R32F; +inf for the sky), so every
// 3D pass reads one convention.
#include "passes/common/inputs.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uDepth;
layout(binding = 0, r32f) uniform writeonly image2D uLinear;

// Mirrors photopic::LinearDepthParameters (passes/inputs/InputPasses.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform LinearDepthParameters {
    int uKind; // DepthKind
    float uNear;
    float uFar;
};

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uLinear);
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    float d = texelFetch(uDepth, p, 0).r;
    float z = linearViewDepth(d, uKind, uNear, uFar);
    // A NaN depth (a broken host buffer) reads as sky rather than spreading through every consumer.
    imageStore(uLinear, p, vec4(isnan(z) || z < 0.0 ? infinity() : z));
}
