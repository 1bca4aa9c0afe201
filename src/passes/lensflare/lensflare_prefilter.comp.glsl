// Lens flare source (a post pass driven by the bright parts of the HDR image, decoupled from
// bloom): the exposed scene, reduced to a small buffer with a 2x2 bilinear box (4 taps = 4x4 texels), keeping
// only what exceeds the flare threshold (a hard threshold; the ghosts are blurred, so no knee is needed).
#include "passes/common/exposure.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in; // a compute pass: 8x8 groups, image store

layout(binding = 0) uniform sampler2D uScene;
layout(binding = 0, rgba16f) uniform writeonly image2D uTarget;
// Mirrors photopic::LensFlarePrefilterParameters (passes/lensflare/LensFlarePass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform LensFlarePrefilterParameters {
    vec2 uTargetTexel; // 1 / flare buffer size
    vec2 uSourceStep;  // UV offset of the 4 taps: a quarter of a target texel
    float uThreshold;
};

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(uTarget)))) {
        return;
    }
    vec2 uv = (vec2(p) + 0.5) * uTargetTexel;
    vec3 c = textureLod(uScene, uv + vec2(-uSourceStep.x, -uSourceStep.y), 0.0).rgb +
             textureLod(uScene, uv + vec2(uSourceStep.x, -uSourceStep.y), 0.0).rgb +
             textureLod(uScene, uv + vec2(-uSourceStep.x, uSourceStep.y), 0.0).rgb +
             textureLod(uScene, uv + vec2(uSourceStep.x, uSourceStep.y), 0.0).rgb;
    c *= 0.25 * gExposure.exposure;
    imageStore(uTarget, p, vec4(max(c - vec3(uThreshold), vec3(0.0)), 1.0));
}
