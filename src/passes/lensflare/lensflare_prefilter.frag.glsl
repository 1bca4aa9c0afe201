// Lens flare source (a post pass driven by the bright parts of the HDR image, decoupled from
// bloom): the exposed scene, reduced to a small buffer with a 2x2 bilinear box (4 taps = 4x4 texels), keeping
// only what exceeds the flare threshold (a hard threshold; the ghosts are blurred, so no knee is needed).
#include "passes/common/exposure.h.glsl"

layout(binding = 0) uniform sampler2D uScene;
// Mirrors photopic::LensFlarePrefilterParameters (passes/lensflare/LensFlarePass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform LensFlarePrefilterParameters {
    vec2 uTargetTexel; // 1 / flare buffer size
    vec2 uSourceStep;  // UV offset of the 4 taps: a quarter of a target texel
    float uThreshold;
};

layout(location = 0) out vec4 oColor;

void main() {
    vec2 uv = gl_FragCoord.xy * uTargetTexel;
    vec3 c = textureLod(uScene, uv + vec2(-uSourceStep.x, -uSourceStep.y), 0.0).rgb +
             textureLod(uScene, uv + vec2(uSourceStep.x, -uSourceStep.y), 0.0).rgb +
             textureLod(uScene, uv + vec2(-uSourceStep.x, uSourceStep.y), 0.0).rgb +
             textureLod(uScene, uv + vec2(uSourceStep.x, uSourceStep.y), 0.0).rgb;
    c *= 0.25 * gExposure.exposure;
    oColor = vec4(max(c - vec3(uThreshold), vec3(0.0)), 1.0);
}
