// The "uber" pass, fused to save full-resolution traffic: composite, colour grading in HDR, then the single
// tone mapping of the frame with the sRGB output transform and dither.
// Reads the scene-referred colour, multiplies by the frame's exposure (GPU exposure state), composites bloom
// (BLOOM: the bloom chain's result, already exposed; energy-conserving mix or threshold add),
// grades (core/ColorGrading.cpp is the CPU reference), applies the curve
// (passes/tonemap/tonecurves.h.glsl mirrors core/ToneCurves.cpp), encodes sRGB, dithers by +-1 LSB (TPDF).
// With OUTPUT_SCENE defined it stops before the curve and writes the graded scene-referred value (EXR output).
// Variants are #defines, never uniform branches (TonemapPass.h: llvmpipe runs every case of a uniform switch):
// TONEMAP_MODE (static_cast<int>(ToneMapper)), BLOOM, GLOW (the legacy tier's glow), GRADE, OUTPUT_SCENE,
// DISPLAY_16 (RGBA16 display storage).
// A compute pass (8x8 groups, rows of 64 on a software renderer; one pixel each; image store into RGBA8 or
// RGBA16, or RGBA32F for OUTPUT_SCENE): on GPUs whose raster units are a small part of the chip a full-screen
// triangle runs far below the memory's pace.
#include "passes/common/color.h.glsl"
#include "passes/common/display_format.h.glsl"
#include "passes/common/exposure.h.glsl"
#include "passes/common/invocation.h.glsl"
#include "passes/common/noise.h.glsl"
#include "passes/common/sanitize.h.glsl"
#include "passes/tonemap/tonecurves.h.glsl"

#include "passes/common/pixel_group.h.glsl"

layout(binding = 0) uniform sampler2D uScene;
#ifdef OUTPUT_SCENE
layout(binding = 0, rgba32f) uniform writeonly image2D uOutput;
#else
layout(binding = 0, DISPLAY_FORMAT) uniform writeonly image2D uOutput;
#endif
#ifdef BLOOM
layout(binding = 1) uniform sampler2D uBloom;
#endif
// Mirrors photopic::TonemapParameters (passes/tonemap/TonemapPass.h), std140. One layout for every variant:
// the bloom, glow and grading members are read only where BLOOM, GLOW and GRADE are defined.
layout(std140, binding = BINDING_PARAMETERS) uniform TonemapParameters {
    float uWhitePoint;
    int uAgxLook;
    int uDither;
    uint uFrame;
    int uBloomAdditive; // 0: mix(scene, bloom, intensity); 1: scene + intensity * bloom; 2: glare (below)
    float uBloomIntensity;
    mat3 uWhiteBalance; // core/ColorGrading.cpp whiteBalanceMatrix
    float uContrast;
    float uSaturation;
    float uGlowThreshold; // exposed scene-linear: only what lies above glows
    float uGlowIntensity; // additive gain
    float uGlowRadius;    // px
    vec3 uLift;
    vec3 uInvGamma; // 1 / gamma, per channel
    vec3 uGain;
    uvec2 uDitherSeeds; // the dither's two per-frame seeds (noise.h.glsl triangularNoise3)
};

const float kMiddleGrey = 0.18; // core/ColorGrading.h kGradingMiddleGrey

#ifdef BLOOM
// The bloom image is half or a quarter of the frame and already blurred by the chain's tent upsamples: one
// bilinear tap brings it up. A 3x3 tent here (9 taps per full-resolution pixel) cost 86 of the pass's 135 ms
// on llvmpipe at 1920x1080 and only widened a glow that is smooth at this scale anyway.
vec3 bloomAt(vec2 uv) {
    return textureLod(uBloom, uv, 0.0).rgb;
}
#endif

#ifdef GLOW
// The legacy tier's single cheap glow (for hardware that cannot afford the chain: a glow without blur): no
// mip chain and no extra target, 12 bilinear taps of the exposed input's part above the threshold on two
// hexagonal rings (the outer one at half weight, rotated 30 degrees), added to the pixel. A wide-radius
// approximation, not a blur.
vec3 brightAt(vec2 p) {
    vec3 c = sanitize(textureLod(uScene, p / vec2(textureSize(uScene, 0)), 0.0).rgb) * gExposure.exposure;
    return max(c - vec3(uGlowThreshold), vec3(0.0));
}

vec3 glowAt(vec2 p) {
    const vec2 kHex[6] = vec2[](vec2(1.0, 0.0), vec2(0.5, 0.8660254), vec2(-0.5, 0.8660254), vec2(-1.0, 0.0),
                                vec2(-0.5, -0.8660254), vec2(0.5, -0.8660254));
    vec3 s = vec3(0.0);
    for (int i = 0; i < 6; ++i) {
        vec2 inner = kHex[i] * (0.5 * uGlowRadius);
        vec2 outer = vec2(kHex[i].x * 0.8660254 - kHex[i].y * 0.5, kHex[i].x * 0.5 + kHex[i].y * 0.8660254) *
                     uGlowRadius;
        s += brightAt(p + inner) + 0.5 * brightAt(p + outer);
    }
    return s * (1.0 / 9.0);
}
#endif

// Same order as core/ColorGrading.cpp gradeColor: white balance, contrast in log2 around middle grey,
// saturation around Rec.709 luma, then gain, lift, gamma (ASC CDL slope, offset, power).
vec3 grade(vec3 c) {
    c = max(uWhiteBalance * c, vec3(0.0));
    c = mix(vec3(0.0), kMiddleGrey * pow(max(c, vec3(1e-30)) / kMiddleGrey, vec3(uContrast)),
            greaterThan(c, vec3(0.0)));
    float y = luma709(c);
    c = max(vec3(y) + (c - vec3(y)) * uSaturation, vec3(0.0));
    c = max(c * uGain + uLift, vec3(0.0));
    return pow(c, uInvGamma);
}

// One pixel: the scene's colour at `source` (the pixel itself, or the edge pixel for a block's pixels past the
// edge), exposed, with `bloom` composited, graded, tone mapped and stored at `p`.
void shade(ivec2 p, ivec2 source, vec3 bloom) {
    vec2 fragCoord = vec2(p) + 0.5;
    // Sanitised here as well: on the LDR path this is where the pipeline first reads the host's colour.
    vec3 c = sanitize(texelFetch(uScene, source, 0).rgb) * gExposure.exposure;
#ifdef BLOOM
    if (uBloomAdditive == 2) {
        // Glare (passes/glare/): the bloom image is the halo's convolution and its alpha the halo's share s
        // of the kernel, the same in every texel; the kernel's centre is the pixel itself, so the glare is
        // mix(c, halo, s) and the composite mix(c, glare, intensity).
        c = mix(c, bloom, uBloomIntensity * texelFetch(uBloom, ivec2(0), 0).a);
    } else {
        c = uBloomAdditive != 0 ? c + uBloomIntensity * bloom : mix(c, bloom, uBloomIntensity);
    }
#endif
#ifdef GLOW
    c += uGlowIntensity * glowAt(fragCoord);
#endif
#ifdef GRADE
    c = grade(c);
#endif
#ifdef OUTPUT_SCENE
    imageStore(uOutput, p, vec4(c, 1.0));
#else
    vec3 display = srgbEncode(toneMap(TONEMAP_MODE, c, uWhitePoint, uAgxLook));
    if (uDither != 0) {
        display += triangularNoise3(p, uDitherSeeds.x, uDitherSeeds.y) * (1.0 / 255.0);
    }
    imageStore(uOutput, p, vec4(onDisplayCode(display), 1.0));
#endif
}

#ifdef BLOOM_BLOCKS
// 4x4 pixels per invocation where the bloom image is exactly half the frame (the host checks; software
// renderers only): pixel 4n + k of a row sits at bloom texel 2n + k/2 - 1/4, between the texels 2n - 1 + kLow[k]
// and the next at the fraction kFraction[k], so the block's 16 bilinear taps read 4x4 bloom texels between them,
// fetched once: 16 fetches instead of 16 filtered taps. The same filter; its float sums may round otherwise.
// Stores past an odd-sized frame's edge have no effect; their scene reads are clamped onto it.
const int kLow[4] = int[](0, 1, 1, 2);
const float kFraction[4] = float[](0.75, 0.25, 0.75, 0.25);

void main() {
    ivec2 block = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uOutput);
    ivec2 bloomSize = textureSize(uBloom, 0);
    ivec2 first = block * 2 - 1;
    vec3 b[16]; // b[4 * row + column]: the bloom texels the block reads
    for (int row = 0; row < 4; ++row) {
        for (int column = 0; column < 4; ++column) {
            ivec2 t = clamp(first + ivec2(column, row), ivec2(0), bloomSize - 1); // clamp to edge
            b[4 * row + column] = texelFetch(uBloom, t, 0).rgb;
        }
    }
    for (int l = 0; l < 4; ++l) {
        for (int k = 0; k < 4; ++k) {
            int i = 4 * kLow[l] + kLow[k];
            vec3 bloom = mix(mix(b[i], b[i + 1], kFraction[k]), mix(b[i + 4], b[i + 5], kFraction[k]),
                             kFraction[l]);
            ivec2 p = block * 4 + ivec2(k, l);
            shade(p, min(p, size - 1), bloom);
        }
    }
}
#else
void main() {
    ivec2 p = clampedInvocationPixel(imageSize(uOutput));
#ifdef BLOOM
    vec3 bloom = bloomAt((vec2(p) + 0.5) / vec2(textureSize(uScene, 0)));
#else
    vec3 bloom = vec3(0.0);
#endif
    shade(p, p, bloom);
}
#endif
