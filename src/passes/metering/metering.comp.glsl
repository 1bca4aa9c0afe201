// Metering of the sanitised HDR image before exposure (no feedback loop; docs/architecture.md), one read of
// the image in one dispatch: the 256-bin log2 histogram (Tardif 2019: shared-memory atomics per workgroup,
// then one global atomic per non-empty bin), the frame's min/max meterable luminance, and per-workgroup
// partial sums of w log2 L and w for the weighted geometric means (average, centre, mask), reduced by
// metering_reduce.comp.glsl. Formulas: core/Metering.h.
#include "passes/common/sanitize.h.glsl"
#include "passes/metering/metering.h.glsl"
#include "passes/metering/metering_buffers.h.glsl"
#include "passes/metering/metering_group.h.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 0) uniform sampler2D uScene;
layout(binding = 1) uniform sampler2D uMask;

// Mirrors photopic::MeteringParameters (passes/metering/MeteringPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform MeteringParameters {
    int uBuildHistogram; // 1: bin every pixel
    int uWeights;        // -1: no weighted mean; else kMeterAverage, kMeterCenter or kMeterMask
    float uLog2Min;
    float uLog2Max;
};

shared float sSum[256];
shared float sWeight[256];
shared float sRowSum[16];
shared float sRowWeight[16];

void main() {
    uint li = gl_LocalInvocationIndex;
    clearGroupTallies(li, uBuildHistogram != 0);
    barrier();

    ivec2 size = textureSize(uScene, 0);
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    bool inside = all(lessThan(p, size));
    // sanitize() is the identity on the HDR path's already sanitised image; on the LDR path it is the first read.
    float lum = inside ? luma709(sanitize(texelFetch(uScene, p, 0).rgb)) : 0.0;
    bool meterable = inside && isMeterable(lum);
    if (meterable) {
        atomicMin(sMinBits, floatBitsToUint(lum));
        atomicMax(sMaxBits, floatBitsToUint(lum));
    }
    if (uBuildHistogram != 0 && inside) {
        int bin = histogramBin(lum, uLog2Min, uLog2Max);
        if (bin >= 0) {
            atomicAdd(sBins[bin], 1u);
        }
    }
    float w = uWeights >= 0 && meterable ? pixelWeight(uWeights, p, size, uMask) : 0.0;
    sSum[li] = w > 0.0 ? w * log2(lum) : 0.0;
    sWeight[li] = w > 0.0 ? w : 0.0;
    barrier();

    if (uBuildHistogram != 0) {
        mergeGroupBin(li);
    }
    // Two-level sum (16 rows of 16, then the 16 row sums): two barriers instead of a tree's eight. Barriers are
    // what costs on CPU rasterisers (llvmpipe), and 16-term serial float sums keep
    // the precision of a tree.
    if (uWeights >= 0 && li < 16u) {
        float rowSum = 0.0;
        float rowWeight = 0.0;
        for (uint i = 0u; i < 16u; ++i) {
            rowSum += sSum[li * 16u + i];
            rowWeight += sWeight[li * 16u + i];
        }
        sRowSum[li] = rowSum;
        sRowWeight[li] = rowWeight;
    }
    barrier();
    if (li == 0u) {
        mergeGroupExtremes();
        if (uWeights >= 0) {
            uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
            vec2 total = vec2(0.0);
            for (uint i = 0u; i < 16u; ++i) {
                total += vec2(sRowSum[i], sRowWeight[i]);
            }
            gPartials[group] = total;
        }
    }
}
