// Bloom upsample: level i of the result = mix(downsampled level i, tent(result of level i + 1), radius).
// Reference: J. Jimenez, "Next Generation Post Processing in Call of Duty: Advanced Warfare", SIGGRAPH 2014:
// a 3x3 tent [1 2 1; 2 4 2; 1 2 1] / 16 on the coarser level, accumulated level by level, so each level is
// blurred once more per step up and the sum approximates a wide, smooth kernel. Mixing (instead of adding)
// keeps the weights of all levels summing to 1 (core/Bloom.h bloomLevelWeight), so bloom moves energy
// around without adding any: what `energy-conserving` needs and what keeps `threshold` mode predictable.
// A compute pass (8x8 groups, image store), as the downsample.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uCoarse; // result of level i + 1 (or the smallest downsampled level)
layout(binding = 1) uniform sampler2D uFine;   // downsampled level i
layout(binding = 0, rgba16f) uniform writeonly image2D uTarget; // result of level i
// Mirrors photopic::BloomUpsampleParameters (passes/bloom/BloomPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform BloomUpsampleParameters {
    vec2 uTargetTexel; // 1 / size of level i
    vec2 uCoarseTexel; // 1 / size of level i + 1
    float uRadius;
};

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(uTarget)))) {
        return;
    }
    vec2 uv = (vec2(p) + 0.5) * uTargetTexel;
    vec2 t = uCoarseTexel;
    vec3 s = textureLod(uCoarse, uv, 0.0).rgb * 4.0;
    s += (textureLod(uCoarse, uv + vec2(-t.x, 0.0), 0.0).rgb + textureLod(uCoarse, uv + vec2(t.x, 0.0), 0.0).rgb +
          textureLod(uCoarse, uv + vec2(0.0, -t.y), 0.0).rgb + textureLod(uCoarse, uv + vec2(0.0, t.y), 0.0).rgb) *
         2.0;
    s += textureLod(uCoarse, uv - t, 0.0).rgb + textureLod(uCoarse, uv + t, 0.0).rgb +
         textureLod(uCoarse, uv + vec2(-t.x, t.y), 0.0).rgb + textureLod(uCoarse, uv + vec2(t.x, -t.y), 0.0).rgb;
    vec3 fine = textureLod(uFine, uv, 0.0).rgb;
    imageStore(uTarget, p, vec4(mix(fine, s * (1.0 / 16.0), uRadius), 1.0));
}
