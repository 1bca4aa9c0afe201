// Metering without the histogram (average, centre and mask weights; the min/max for spot metering): the
// same readings as metering.comp.glsl, bit for bit, without its workgroup barriers and shared memory. Each
// invocation meters one 16-pixel row of one of metering.comp.glsl's 16x16 blocks, summing w log2 L and w
// from left to right exactly as that shader's row sums do, and writes the row's pair; metering_reduce
// adds a block's 16 rows top to bottom, as that shader's block total does, before the blocks. On a CPU
// rasteriser (llvmpipe) a barrier suspends and resumes every SIMD batch of the group, and the 16x16
// shader's three of them cost most of a frame's metering there (docs/bench/LOG.md); this shader has none. The weighting is the compile-time WEIGHTS (-1: no weighted
// mean; else kMeterAverage, kMeterCenter or kMeterMask), not uWeights: llvmpipe computes every weight a
// uniform branch could pick, the mask's texel fetch and the centre's exp included. Formulas: core/Metering.h.
#include "passes/common/sanitize.h.glsl"
#include "passes/metering/metering.h.glsl"
#include "passes/metering/metering_buffers.h.glsl"

// One workgroup per block, dispatched like metering.comp.glsl's (so within the same dispatch limits), one
// invocation per row of the block.
layout(local_size_x = 16) in;
layout(binding = 0) uniform sampler2D uScene;
layout(binding = 1) uniform sampler2D uMask;

// Mirrors photopic::MeteringParameters (passes/metering/MeteringPass.h), std140; uBuildHistogram is 0 here,
// uWeights equals WEIGHTS.
layout(std140, binding = BINDING_PARAMETERS) uniform MeteringParameters {
    int uBuildHistogram;
    int uWeights; // -1: no weighted mean; else kMeterAverage, kMeterCenter or kMeterMask
    float uLog2Min;
    float uLog2Max;
};

const uint kBlock = 16u; // metering.comp.glsl's workgroup side

void main() {
    ivec2 size = textureSize(uScene, 0);
    uint block = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    uint row = block * kBlock + gl_LocalInvocationID.x;
    ivec2 origin = ivec2(gl_WorkGroupID.xy * kBlock) + ivec2(0, int(gl_LocalInvocationID.x));
    float rowSum = 0.0;
    float rowWeight = 0.0;
    uint minBits = 0xffffffffu;
    uint maxBits = 0u;
    for (uint x = 0u; x < kBlock; ++x) {
        ivec2 p = origin + ivec2(int(x), 0);
        bool inside = all(lessThan(p, size));
        float lum = inside ? luma709(sanitize(texelFetch(uScene, p, 0).rgb)) : 0.0;
        bool meterable = inside && isMeterable(lum);
        if (meterable) {
            minBits = min(minBits, floatBitsToUint(lum));
            maxBits = max(maxBits, floatBitsToUint(lum));
        }
        float w = WEIGHTS >= 0 && meterable ? pixelWeight(WEIGHTS, p, size, uMask) : 0.0;
        rowSum += w > 0.0 ? w * log2(lum) : 0.0;
        rowWeight += w > 0.0 ? w : 0.0;
    }
    if (maxBits != 0u) {
        atomicMin(gMinBits, minBits);
        atomicMax(gMaxBits, maxBits);
    }
    if (WEIGHTS >= 0) {
        gPartials[row] = vec2(rowSum, rowWeight);
    }
}
