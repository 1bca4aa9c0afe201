// Bloom blur, along rows: each level of the chain is blurred by a Gaussian of kBloomBlurSigma of its own
// texels, cut at 4 sigma (core/Bloom.h); the upsample pass blurs the columns. The Gaussian, not the
// resampling filters, gives each level's glow its shape, and a separable Gaussian is round. Runs of kRun
// texels a row per invocation (bloom_step.h.glsl blurRun); stores past the edge have no effect.
#include "passes/common/pixel_group.h.glsl"

layout(binding = 0) uniform sampler2D uSource;
layout(binding = 0, rgba16f) uniform writeonly image2D uTarget;
#include "passes/bloom/bloom_step.h.glsl"

void main() {
    ivec2 first = ivec2(gl_GlobalInvocationID.xy) * ivec2(kRun, 1);
    vec4 sums[kRun];
    blurRun(uSource, first, ivec2(1, 0), sums);
    for (int r = 0; r < kRun; ++r) {
        imageStore(uTarget, first + ivec2(r, 0), sums[r]);
    }
}
