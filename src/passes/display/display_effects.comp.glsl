// Display-domain effects fused into one pass (one full-resolution read and write): chromatic aberration, lens
// flare composite, dazzle, vignette, grain, in that order, on the tone-mapped sRGB-encoded image.
//  - Chromatic aberration: lateral colour, red and blue sampled at radially scaled positions (a lens images
//    colours at slightly different magnifications).
//  - Lens flare: the flare pass's HDR buffer joins the display image in linear display light with a
//    saturating add, 1 - (1 - c)(e^-flare), so it can brighten towards white but never past it.
//  - Dazzle: d = clamp(max(0, appliedLog2 - targetLog2) / rangeEV) * strength; the image desaturates towards
//    its luma, takes on the glare of the bloom image and lifts towards white, as an eye does before it has
//    adapted to bright light.
//  - Vignette: light fall-off in linear light, factor 1 - intensity * r^falloff with r the distance from the
//    centre normalised to 1 at the corners (core/DisplayEffects.h vignetteFactor is the CPU reference).
//  - Grain: monochrome triangular hash noise (passes/common/noise.h.glsl), deterministic per frame index,
//    weighted 4 y (1 - y) so it is strongest in the mid-tones and leaves black and white clean.
// A compute pass (8x8 groups, one pixel each, image store), like every full-screen pass.
#include "passes/common/color.h.glsl"
#include "passes/common/display_format.h.glsl"
#include "passes/common/exposure.h.glsl"
#include "passes/common/noise.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uDisplay; // RGBA8 or RGBA16, sRGB-encoded
layout(binding = 0, DISPLAY_FORMAT) uniform writeonly image2D uOutput;
layout(binding = 1) uniform sampler2D uFlareTex;  // exposed HDR flare, or a black texel
layout(binding = 2) uniform sampler2D uGlareTex; // exposed HDR bloom, or a black texel
// Mirrors photopic::DisplayEffectsParameters (passes/display/DisplayEffectsPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform DisplayEffectsParameters {
    vec2 uTexel;
    float uChromaticAberration;
    int uFlare;
    int uDazzle;
    float uDazzleStrength;
    float uDazzleRangeEV;
    int uVignette;
    float uVignetteIntensity;
    float uVignetteFalloff;
    int uGrain;
    float uGrainIntensity;
    uint uFrame;
};

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(uOutput)))) {
        return;
    }
    vec2 uv = (vec2(p) + 0.5) * uTexel;
    vec2 d = uv - 0.5;
    vec3 c;
    if (uChromaticAberration > 0.0) {
        c.r = textureLod(uDisplay, 0.5 + d * (1.0 - uChromaticAberration), 0.0).r;
        c.g = texelFetch(uDisplay, p, 0).g;
        c.b = textureLod(uDisplay, 0.5 + d * (1.0 + uChromaticAberration), 0.0).b;
    } else {
        c = texelFetch(uDisplay, p, 0).rgb;
    }
    vec3 lin = srgbDecode(c);

    if (uFlare != 0) {
        vec3 flare = textureLod(uFlareTex, uv, 0.0).rgb;
        lin = 1.0 - (1.0 - lin) * exp(-flare);
    }
    if (uDazzle != 0) {
        float over = max(0.0, gExposure.appliedLog2 - gExposure.targetLog2);
        float amount = clamp(over / uDazzleRangeEV, 0.0, 1.0) * uDazzleStrength;
        vec3 glare = textureLod(uGlareTex, uv, 0.0).rgb;
        glare = glare / (1.0 + glare);
        lin = mix(lin, vec3(luma709(lin)), 0.7 * amount);
        lin = 1.0 - (1.0 - lin) * (1.0 - amount * glare);
        lin = mix(lin, vec3(1.0), 0.5 * amount);
    }
    if (uVignette != 0) {
        float r = min(length(d) / 0.70710678, 1.0);
        lin *= 1.0 - uVignetteIntensity * pow(r, uVignetteFalloff);
    }
    vec3 encoded = srgbEncode(lin);
    if (uGrain != 0) {
        float y = luma709(encoded);
        encoded += vec3(triangularNoise(p, uFrame, 11u) * uGrainIntensity * 4.0 * y * (1.0 - y));
    }
    imageStore(uOutput, p, vec4(onDisplayCode(encoded), 1.0));
}
