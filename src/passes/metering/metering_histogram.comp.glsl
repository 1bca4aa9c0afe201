// Metering that needs the histogram and no weighted mean (histogram metering, or the histogram view with
// auto exposure off): the 256-bin log2 histogram and the frame's min/max meterable luminance, one read of the
// image in one dispatch, the same bins and extremes to the bit as metering.comp.glsl. Each invocation bins a
// row of kRun pixels, kGroupWidth apart (so a group's reads of one step are contiguous), counting runs of one
// bin in a register and adding each run to the shared bins with one atomic: neighbouring pixels mostly share
// a bin, so the shared atomics of a smooth region no longer queue on a few bins one pixel at a time. A group
// covers kRun times the pixels of metering.comp.glsl's, so a frame has kRun times fewer groups, each merging
// its non-empty bins into the global ones once. The extremes are kept in registers and merged once per
// invocation.
#include "passes/common/sanitize.h.glsl"
#include "passes/metering/metering.h.glsl"
#include "passes/metering/metering_buffers.h.glsl"
#include "passes/metering/metering_group.h.glsl"

const int kGroupWidth = 16;
const int kRun = RUN; // pixels per invocation (the host's MeteringPass::kHistogramRun): a group covers
                      // kGroupWidth * kRun x 16 pixels
layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 0) uniform sampler2D uScene;

// Mirrors photopic::MeteringParameters (passes/metering/MeteringPass.h), std140; this kernel reads the
// histogram's range only.
layout(std140, binding = BINDING_PARAMETERS) uniform MeteringParameters {
    int uBuildHistogram;
    int uWeights;
    float uLog2Min;
    float uLog2Max;
};

void main() {
    uint li = gl_LocalInvocationIndex;
    clearGroupTallies(li, true);
    barrier();

    ivec2 size = textureSize(uScene, 0);
    int x0 = int(gl_WorkGroupID.x) * kGroupWidth * kRun + int(gl_LocalInvocationID.x);
    int y = int(gl_GlobalInvocationID.y);
    uint minBits = 0xffffffffu, maxBits = 0u;
    int runBin = -1;
    uint runLength = 0u;
    for (int k = 0; k < kRun; ++k) {
        ivec2 p = ivec2(x0 + k * kGroupWidth, y);
        bool inside = all(lessThan(p, size));
        // sanitize() is the identity on the HDR path's already sanitised image; on the LDR path it is the
        // first read.
        float lum = inside ? luma709(sanitize(texelFetch(uScene, p, 0).rgb)) : 0.0;
        if (inside && isMeterable(lum)) {
            minBits = min(minBits, floatBitsToUint(lum));
            maxBits = max(maxBits, floatBitsToUint(lum));
        }
        int bin = inside ? histogramBin(lum, uLog2Min, uLog2Max) : -1;
        if (bin != runBin) {
            if (runLength != 0u) {
                atomicAdd(sBins[runBin], runLength);
            }
            runBin = bin;
            runLength = 0u;
        }
        runLength += bin >= 0 ? 1u : 0u;
    }
    if (runLength != 0u) {
        atomicAdd(sBins[runBin], runLength);
    }
    if (maxBits != 0u) {
        atomicMin(sMinBits, minBits);
        atomicMax(sMaxBits, maxBits);
    }
    barrier();

    mergeGroupBin(li);
    if (li == 0u) {
        mergeGroupExtremes();
    }
}
