// Bloom downsample: one level of the chain from the level above, or with PREFILTER from the frame.
// Each target texel is the binomial [1 3 3 1] / 8 per axis of the 4x4 source texels around it (four
// bilinear taps, each between two texel pairs at the 1:3 point): the narrowest filter whose repeated
// application tends to a Gaussian, so that the chain's kernels stay round (docs/architecture.md, "Bloom").
// A weighted mean of a footprint (no Karis average: bloom reads colour after temporal anti-aliasing, and a
// weight of 1 / (1 + luma) per tap caps every partly covered texel of a small light, which squares its glow
// and loses its energy).
// With PREFILTER the same weights fall on the frame's texels one by one (QUARTER, level 0 a quarter of the
// frame: [1 3 6 10 12 12 10 6 3 1] / 64 over 10 texels a side), and each texel is sanitised (a NaN or an
// infinity counts as 0, negative values as 0), multiplied by the frame's exposure (bloom works on exposed
// colour, so what blooms does not depend on the scene's absolute level) and, in threshold mode, passed
// through the soft knee (constants from core/Bloom.cpp) before it is weighed: a threshold on a mean would
// keep more of a light's texels along the axes than along the diagonals and square a small light's glow.
// Alpha holds the share of the footprint's weight inside the frame: the chain carries it to the result,
// where the energy-conserving composite uses it (tonemap.comp.glsl). Invocations take 2x2 blocks of targets
// there (stores past the edge have no effect), one target a level further down.
#include "passes/common/invocation.h.glsl"
#ifdef PREFILTER
#include "passes/common/exposure.h.glsl"
#include "passes/common/sanitize.h.glsl"
#endif
#include "passes/common/pixel_group.h.glsl"

layout(binding = 0) uniform sampler2D uSource;
layout(binding = 0, rgba16f) uniform writeonly image2D uTarget;
#include "passes/bloom/bloom_step.h.glsl"

#ifdef QUARTER
const int kTexels = 10;
const float kTexelWeight[kTexels] =
    float[](1.0 / 64.0, 3.0 / 64.0, 6.0 / 64.0, 10.0 / 64.0, 12.0 / 64.0, 12.0 / 64.0, 10.0 / 64.0, 6.0 / 64.0,
            3.0 / 64.0, 1.0 / 64.0);
#else
const int kTexels = 4;
const float kTexelWeight[kTexels] = float[](0.125, 0.375, 0.375, 0.125);
#endif

#ifdef PREFILTER
// One frame texel as it enters the glow: sanitised, exposed (clamped again: a half float past its maximum
// would store an infinity) and, in threshold mode, only its part above the knee.
vec3 prefiltered(ivec2 t, ivec2 size) {
    if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, size))) {
        return vec3(0.0); // outside the frame: nothing
    }
    vec3 color = min(sanitize(texelFetch(uSource, t, 0).rgb) * gExposure.exposure, vec3(kSanitizeMax));
    if (uThreshold != 0) {
        float br = max(color.r, max(color.g, color.b));
        float rq = clamp(br - uKnee.y, 0.0, uKnee.z);
        rq = rq * rq * uKnee.w;
        color *= max(rq, br - uKnee.x) / max(br, 1e-4);
    }
    return color;
}

// The share of the footprint's weight along one axis on frame texels inside [0, size).
float insideShare(int first, int size) {
    float share = 0.0;
    for (int k = 0; k < kTexels; ++k) {
        share += (first + k >= 0 && first + k < size) ? kTexelWeight[k] : 0.0;
    }
    return share;
}

// Frame texels per level-0 texel along an axis (the footprints of neighbouring targets are this far apart).
#ifdef QUARTER
const int kStep = 4;
#else
const int kStep = 2;
#endif
const int kSpan = kTexels + kStep; // frame texels a side under a 2x2 block of targets

// Each invocation computes a 2x2 block of targets, whose footprints overlap: the kSpan x kSpan texels under
// the block are fetched and prefiltered once each (9 a target where one target alone takes 16). Each row is
// weighed for the block's two columns, and the rows for its two rows.
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy) * 2;
    // The first footprint's first texel: the centre's coordinate minus (kTexels - 1) / 2, a whole number.
    ivec2 first = ivec2(vec2(p) * uSourceScale + uSourceOrigin - 0.5 * float(kTexels - 1));
    vec3 rows0[kSpan], rows1[kSpan]; // row j weighed for the first and the second column
    for (int j = 0; j < kSpan; ++j) {
        vec3 v[kSpan];
        for (int i = 0; i < kSpan; ++i) {
            v[i] = prefiltered(first + ivec2(i, j), uFrameSize);
        }
        rows0[j] = vec3(0.0);
        rows1[j] = vec3(0.0);
        for (int k = 0; k < kTexels; ++k) {
            rows0[j] += v[k] * kTexelWeight[k];
            rows1[j] += v[k + kStep] * kTexelWeight[k];
        }
    }
    vec3 t00 = vec3(0.0), t10 = vec3(0.0), t01 = vec3(0.0), t11 = vec3(0.0);
    for (int k = 0; k < kTexels; ++k) {
        t00 += rows0[k] * kTexelWeight[k];
        t10 += rows1[k] * kTexelWeight[k];
        t01 += rows0[k + kStep] * kTexelWeight[k];
        t11 += rows1[k + kStep] * kTexelWeight[k];
    }
    float insideX0 = insideShare(first.x, uFrameSize.x), insideX1 = insideShare(first.x + kStep, uFrameSize.x);
    float insideY0 = insideShare(first.y, uFrameSize.y), insideY1 = insideShare(first.y + kStep, uFrameSize.y);
    imageStore(uTarget, p, vec4(t00, insideX0 * insideY0));
    imageStore(uTarget, p + ivec2(1, 0), vec4(t10, insideX1 * insideY0));
    imageStore(uTarget, p + ivec2(0, 1), vec4(t01, insideX0 * insideY1));
    imageStore(uTarget, p + ivec2(1, 1), vec4(t11, insideX1 * insideY1));
}
#else
// Per axis two bilinear taps 0.75 texels either side of the centre, each half the weight: [1 3 3 1] / 8.
void main() {
    ivec2 p = clampedInvocationPixel(imageSize(uTarget));
    vec2 c = vec2(p) * uSourceScale + uSourceOrigin;
    vec4 sum = vec4(0.0);
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            sum += readAt(uSource, c + vec2(i == 0 ? -0.75 : 0.75, j == 0 ? -0.75 : 0.75)) * 0.25;
        }
    }
    imageStore(uTarget, p, sum);
}
#endif
