// Final reduction of the weighted geometric mean (core/Metering.h: exp2(sum(w log2 L) / sum(w)), 0 when no weight):
// one workgroup folds every block's partial of metering.comp.glsl (or the block's rows of metering_rows.comp.glsl,
// added top to bottom first, the order that shader's block totals use), or, for spot metering, the 1/5/9/13 taps
// of the disc.
#include "passes/common/sanitize.h.glsl"
#include "passes/metering/metering.h.glsl"
#include "passes/metering/metering_buffers.h.glsl"

layout(local_size_x = 256) in;
layout(binding = 0) uniform sampler2D uScene;

// Mirrors photopic::MeteringReduceParameters (passes/metering/MeteringPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform MeteringReduceParameters {
    int uSpot;    // 1: meter the spot taps instead of the partials
    int uGroups;  // partials written by the metering dispatch
    vec2 uSpotUv; // image UV, v down
    float uSpotRadius;
    int uSpotTaps;
    int uRowsPerGroup; // 1: one partial per block (metering.comp.glsl); 16: one per block row (metering_rows)
};

shared float sSum[256];
shared float sWeight[256];

void main() {
    uint li = gl_LocalInvocationIndex;
    float sum = 0.0;
    float weight = 0.0;
    if (uSpot != 0) {
        if (int(li) < clamp(uSpotTaps, 1, 13)) {
            ivec2 size = textureSize(uScene, 0);
            ivec2 pixel = spotTapPixel(uSpotUv, uSpotRadius, int(li), size);
            float lum = luma709(sanitize(texelFetch(uScene, texelOfImagePixel(pixel, size), 0).rgb));
            if (isMeterable(lum)) {
                sum = log2(lum);
                weight = 1.0;
            }
        }
    } else {
        for (int i = int(li); i < uGroups; i += 256) {
            vec2 partial = vec2(0.0);
            for (int r = 0; r < uRowsPerGroup; ++r) {
                partial += gPartials[i * uRowsPerGroup + r];
            }
            sum += partial.x;
            weight += partial.y;
        }
    }
    sSum[li] = sum;
    sWeight[li] = weight;
    barrier();
    for (uint stride = 128u; stride > 0u; stride >>= 1) {
        if (li < stride) {
            sSum[li] += sSum[li + stride];
            sWeight[li] += sWeight[li + stride];
        }
        barrier();
    }
    if (li == 0u) {
        float w = sWeight[0];
        gReading = w > 0.0 ? exp2(sSum[0] / w) : 0.0;
        gWeightSum = w;
        gGroups = uint(uGroups);
    }
}
