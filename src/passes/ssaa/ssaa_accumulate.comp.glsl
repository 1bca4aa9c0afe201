// Supersampling: one jittered sub-frame of the host's HDR colour folded into the frame's running weighted mean,
// in scene-referred linear light (before metering and tone mapping, so the average is of light, not of
// display values): mean_i = mean_(i-1) + (c_i - mean_(i-1)) * w_i / W_i, W_i the sum of the weights so far.
#include "passes/common/sanitize.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uSubframe;
layout(binding = 0, rgba32f) uniform image2D uMean;

// Mirrors photopic::SsaaAccumulateParameters (passes/ssaa/SsaaAccumulator.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform SsaaAccumulateParameters {
    float uFraction; // w_i / W_i; 1 for the first sub-frame
};

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(uMean)))) {
        return;
    }
    vec3 c = sanitize(texelFetch(uSubframe, p, 0).rgb);
    vec3 mean = uFraction >= 1.0 ? c : mix(imageLoad(uMean, p).rgb, c, uFraction);
    imageStore(uMean, p, vec4(mean, 1.0));
}
