// Lens flare source (a post pass driven by the bright parts of the HDR image, decoupled from
// bloom): the exposed scene, reduced to a small buffer with a 2x2 bilinear box (4 taps = 4x4 texels), keeping
// only what exceeds the flare threshold (a hard threshold; the ghosts are blurred, so no knee is needed),
// capped so that a sun's ghosts stay within a few times white.
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

const float kSourceCap = 16.0;

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
    c = max(c - vec3(uThreshold), vec3(0.0));
    // A source many times white (a sun) is scaled down to kSourceCap, hue kept: a lens's ghosts are faint
    // copies of the aperture, and a ghost thousands of times white would show the buffer's texels as
    // saturated blocks however it is filtered.
    float peak = max(c.r, max(c.g, c.b));
    c *= kSourceCap / max(kSourceCap, peak);
    imageStore(uTarget, p, vec4(c, 1.0));
}
