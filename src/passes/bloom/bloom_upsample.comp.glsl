// Bloom upsample: level i of the result = mix(the level's row-blurred texels blurred along columns, the
// result of level i + 1 brought up by one bilinear tap, radius). Mixing (instead of adding) keeps the
// weights of all levels summing to 1 (core/Bloom.h bloomLevelWeight), so bloom moves energy around without
// adding any. Without COARSE (the coarsest level) the result is the column blur alone. The last step writes
// the chain's result, which covers the frame's region only (uTargetOffset: the band's width). Runs of kRun
// texels a column per invocation (bloom_step.h.glsl blurRun); stores past the edge have no effect.
#include "passes/common/pixel_group.h.glsl"

layout(binding = 0) uniform sampler2D uSource; // the level, blurred along rows
#ifdef COARSE
layout(binding = 1) uniform sampler2D uCoarse; // the result of level i + 1
#endif
layout(binding = 0, rgba16f) uniform writeonly image2D uTarget;
#include "passes/bloom/bloom_step.h.glsl"

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy) * ivec2(1, kRun);
    vec4 sums[kRun];
    blurRun(uSource, p + uTargetOffset, ivec2(0, 1), sums);
    for (int r = 0; r < kRun; ++r) {
        vec4 value = sums[r];
#ifdef COARSE
        vec2 coarse = vec2(p + uTargetOffset + ivec2(0, r)) * 0.5 + uCoarseOrigin;
        value = mix(value, textureLod(uCoarse, (coarse + 0.5) * uCoarseTexel, 0.0), uRadius);
#endif
        imageStore(uTarget, p + ivec2(0, r), value);
    }
}
