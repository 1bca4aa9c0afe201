// Bloom downsample: one level of the chain from the level above (or, with PREFILTER, from the scene).
// Reference: J. Jimenez, "Next Generation Post Processing in Call of Duty: Advanced Warfare", SIGGRAPH 2014,
// slides 150-163: 13 bilinear taps form five overlapping 2x2 boxes; the centre box weighs 0.5 and the four
// corner boxes 0.125 each, which removes the pulsing of a plain 2x2 box under motion. With KARIS each box is
// weighted by 1 / (1 + luma) and the result renormalised ("Karis average"), so a single firefly cannot
// dominate a whole region; only the first level needs it, the later ones already see averaged colour.
// With PREFILTER the taps are scene colour multiplied by the frame's exposure (bloom works on exposed colour,
// so what blooms does not depend on the scene's absolute level) and, in threshold mode, the soft knee
// (constants from core/Bloom.cpp) keeps only what lies above the threshold. The prefilter may read the host's
// raw colour (the frame skips the sanitize pass when every reader sanitises), so each of the five boxes is
// sanitised: over finite texels in [0, kSanitizeMax] that is the box of the sanitised texels (up to rounding;
// a 32-bit colour is no longer rounded to half first), and a box holding a NaN or an infinity counts as 0, a
// negative texel is clamped with its box instead of alone. Sanitising each tap, or re-reading a non-finite
// tap texel by texel, cost about 4 and 29 ms more at 1920x1080 on llvmpipe (which runs both sides of a branch).
// A compute pass (8x8 groups, one target texel each, image store): on GPUs whose raster units are a small part
// of the chip a full-screen triangle runs far below the memory's pace, and the taps hit the texture cache the
// same way from either stage.
#include "passes/common/color.h.glsl"
#include "passes/common/invocation.h.glsl"
#ifdef PREFILTER
#include "passes/common/exposure.h.glsl"
#include "passes/common/sanitize.h.glsl"
#endif

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uSource;
layout(binding = 0, rgba16f) uniform writeonly image2D uTarget;
// Mirrors photopic::BloomDownsampleParameters (passes/bloom/BloomPass.h), std140. The prefilter and the plain
// downsample share the layout; only the prefilter reads uThreshold and uKnee.
layout(std140, binding = BINDING_PARAMETERS) uniform BloomDownsampleParameters {
    vec2 uTargetTexel; // 1 / target size
    vec2 uSourceStep;  // one source texel in UV (two when level 0 is a quarter of the scene)
    int uThreshold;    // 1: threshold mode
    vec4 uKnee;        // T, T - knee, 2 knee, 1 / (4 knee)
};

vec3 tap(vec2 uv) {
    return textureLod(uSource, uv, 0.0).rgb;
}

// One of the five boxes: the mean of its four taps, sanitised and exposed with PREFILTER (exposed before
// the Karis weights, which must see the luma the viewer will see). Each tap is quartered before the sum, the
// same value to the bit (a power of two), so finite raw values near the float maximum cannot overflow to an
// infinity that sanitize would make 0.
vec3 box(vec3 a, vec3 b, vec3 c, vec3 d) {
#ifdef PREFILTER
    return sanitize(a * 0.25 + b * 0.25 + c * 0.25 + d * 0.25) * gExposure.exposure;
#else
    return (a + b + c + d) * 0.25;
#endif
}

#ifdef KARIS
float karisWeight(vec3 box) {
    return 1.0 / (1.0 + luma709(box));
}
#endif

void main() {
    ivec2 p = clampedInvocationPixel(imageSize(uTarget));
    vec2 uv = (vec2(p) + 0.5) * uTargetTexel;
    vec2 t = uSourceStep;
    vec3 a = tap(uv + t * vec2(-2.0, 2.0));
    vec3 b = tap(uv + t * vec2(0.0, 2.0));
    vec3 c = tap(uv + t * vec2(2.0, 2.0));
    vec3 d = tap(uv + t * vec2(-1.0, 1.0));
    vec3 e = tap(uv + t * vec2(1.0, 1.0));
    vec3 f = tap(uv + t * vec2(-2.0, 0.0));
    vec3 g = tap(uv);
    vec3 h = tap(uv + t * vec2(2.0, 0.0));
    vec3 i = tap(uv + t * vec2(-1.0, -1.0));
    vec3 j = tap(uv + t * vec2(1.0, -1.0));
    vec3 k = tap(uv + t * vec2(-2.0, -2.0));
    vec3 l = tap(uv + t * vec2(0.0, -2.0));
    vec3 m = tap(uv + t * vec2(2.0, -2.0));

    vec3 centre = box(d, e, i, j);
    vec3 topLeft = box(a, b, f, g);
    vec3 topRight = box(b, c, g, h);
    vec3 bottomLeft = box(f, g, k, l);
    vec3 bottomRight = box(g, h, l, m);

#ifdef KARIS
    float wc = 0.5 * karisWeight(centre);
    float w0 = 0.125 * karisWeight(topLeft);
    float w1 = 0.125 * karisWeight(topRight);
    float w2 = 0.125 * karisWeight(bottomLeft);
    float w3 = 0.125 * karisWeight(bottomRight);
    vec3 color = (centre * wc + topLeft * w0 + topRight * w1 + bottomLeft * w2 + bottomRight * w3) /
                  (wc + w0 + w1 + w2 + w3);
#else
    vec3 color = centre * 0.5 + (topLeft + topRight + bottomLeft + bottomRight) * 0.125;
#endif

#ifdef PREFILTER
    if (uThreshold != 0) {
        float br = max(color.r, max(color.g, color.b));
        float rq = clamp(br - uKnee.y, 0.0, uKnee.z);
        rq = rq * rq * uKnee.w;
        color *= max(rq, br - uKnee.x) / max(br, 1e-4);
    }
#endif
    imageStore(uTarget, p, vec4(color, 1.0));
}
