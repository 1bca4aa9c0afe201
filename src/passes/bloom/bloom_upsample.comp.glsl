// Bloom upsample: level i of the result = mix(downsampled level i, tent(result of level i + 1), radius).
// Reference: J. Jimenez, "Next Generation Post Processing in Call of Duty: Advanced Warfare", SIGGRAPH 2014:
// a 3x3 tent [1 2 1; 2 4 2; 1 2 1] / 16 on the coarser level, accumulated level by level, so each level is
// blurred once more per step up and the sum approximates a wide, smooth kernel. Mixing (instead of adding)
// keeps the weights of all levels summing to 1 (core/Bloom.h bloomLevelWeight), so bloom moves energy
// around without adding any: what `energy-conserving` needs and what keeps `threshold` mode predictable.
// A compute pass (8x8 groups, rows of 64 on a software renderer; image store), as the downsample.
#include "passes/common/invocation.h.glsl"

#include "passes/common/pixel_group.h.glsl"

layout(binding = 0) uniform sampler2D uCoarse; // result of level i + 1 (or the smallest downsampled level)
layout(binding = 1) uniform sampler2D uFine;   // downsampled level i
layout(binding = 0, rgba16f) uniform writeonly image2D uTarget; // result of level i
// Mirrors photopic::BloomUpsampleParameters (passes/bloom/BloomPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform BloomUpsampleParameters {
    vec2 uTargetTexel; // 1 / size of level i
    vec2 uCoarseTexel; // 1 / size of level i + 1
    float uRadius;
};

// The tent's three bilinear taps per axis (at -1, 0 and +1 coarse texel, all with the same fraction f) read four
// coarse texels with the weights (1 - f) / 4, 1/2 - f/4, 1/4 + f/4 and f/4. Each pair of neighbours is one
// bilinear tap at the position its two weights say: four taps instead of nine, the same filter (to rounding;
// clamp-to-edge replicates the same border texels). Texture reads are what a CPU rasteriser pays for.
vec2 pairOffset(vec2 w0, vec2 w1) {
    return w1 / (w0 + w1);
}

void main() {
    ivec2 p = clampedInvocationPixel(imageSize(uTarget));
    vec2 uv = (vec2(p) + 0.5) * uTargetTexel;
    vec2 x = uv / uCoarseTexel - 0.5; // in coarse texels, texel centres at integers
    vec2 i = floor(x);
    vec2 f = x - i;
    vec2 wA = 0.75 - 0.5 * f; // texels i - 1 and i
    vec2 wB = 0.25 + 0.5 * f; // texels i + 1 and i + 2
    vec2 a = (i - 0.5 + pairOffset(0.25 - 0.25 * f, 0.5 - 0.25 * f)) * uCoarseTexel;
    vec2 b = (i + 1.5 + pairOffset(0.25 + 0.25 * f, 0.25 * f)) * uCoarseTexel;
    vec3 s = (textureLod(uCoarse, a, 0.0).rgb * wA.x + textureLod(uCoarse, vec2(b.x, a.y), 0.0).rgb * wB.x) * wA.y +
             (textureLod(uCoarse, vec2(a.x, b.y), 0.0).rgb * wA.x + textureLod(uCoarse, b, 0.0).rgb * wB.x) * wB.y;
    vec3 fine = texelFetch(uFine, p, 0).rgb; // the target's own texel: a fetch, not a filtered tap
    imageStore(uTarget, p, vec4(mix(fine, s, uRadius), 1.0));
}
