// Subject probes (multi-tap, steadier than one texel): one invocation per subject
// averages the Rec.709 luma at the first `taps` kProbeTaps around its screen UV. A line-for-line mirror of core's
// probeImage and probeTapTexel (core/Subjects.cpp); the texture's rows run bottom-up (gl/TextureIo.h), so the
// image pixel is flipped to its texel. For `subject` metering the invocation of the subject of the view also keeps
// its luma behind the probe deadband (core: applyLumaDeadband) in a buffer that persists across frames, and the
// reading the adaptation pass reads is that kept luma every frame: exposure keeps adapting between probes.
#include "passes/common/color.h.glsl"
#include "passes/common/sanitize.h.glsl"
#include "passes/metering/metering.h.glsl"
#include "passes/metering/metering_buffers.h.glsl"

layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D uScene;

// Mirrors photopic::ProbeParameters (passes/probe/ProbePass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform ProbeParameters {
    int uWriteReading; // 1: subject metering, write gReading
};

struct ProbeEntry {
    vec2 uv; // image UV, v down
    uint id;
    float luma;
};

// Mirrors photopic::GpuProbeHeader + GpuProbeEntry[] (passes/Bindings.h).
layout(std430, binding = BINDING_PROBE) buffer ProbeBuffer {
    uint gCount;
    int gTaps;
    float gRadius;
    int gSelected; // entry of the subject of the view, -1 when it is not probed this frame
    int gActive;   // 1: there is a subject of the view
    uint gSelectedId;
    float gDeadbandEV;
    float gTimeS;
    ProbeEntry gEntries[];
};

// Mirrors photopic::GpuSubjectState.
layout(std430, binding = BINDING_SUBJECT_STATE) buffer SubjectStateBuffer {
    float gKeptLuma;
    uint gKeptId;
    int gHasKept;
    uint gStatePad;
};

// core: probeTapTexel = spotTapTexel over the first nine spot taps (kProbeTapCount), so a probe and a spot
// meter read the same disc.
const int kProbeTapCount = 9;

// core: probeImage (arithmetic mean; sanitised luma is finite and non-negative).
float probe(vec2 uv) {
    if (isnan(uv.x) || isnan(uv.y)) {
        return 0.0;
    }
    ivec2 size = textureSize(uScene, 0);
    int n = clamp(gTaps, 1, kProbeTapCount);
    float sum = 0.0;
    for (int t = 0; t < n; ++t) {
        ivec2 pixel = spotTapPixel(uv, gRadius, t, size);
        sum += luma709(sanitize(texelFetch(uScene, texelOfImagePixel(pixel, size), 0).rgb));
    }
    return sum / float(n);
}

// core: applyLumaDeadband, with the kept value reset when the subject of the view changes.
void keep(float measured) {
    if (!isMeterable(measured)) {
        return;
    }
    if (gHasKept == 0 || gKeptId != gSelectedId || !isMeterable(gKeptLuma) ||
        abs(log2(measured) - log2(gKeptLuma)) > gDeadbandEV) {
        gKeptLuma = measured;
    }
    gKeptId = gSelectedId;
    gHasKept = 1;
}

float keptReading() {
    return gActive != 0 && gHasKept != 0 && gKeptId == gSelectedId ? gKeptLuma : 0.0;
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < gCount) {
        float luma = probe(gEntries[i].uv);
        gEntries[i].luma = luma;
        if (int(i) == gSelected) {
            keep(luma);
            if (uWriteReading != 0) {
                gReading = keptReading();
            }
        }
    }
    // No probe of the subject this frame: its last kept luma (0 without a subject: exposure holds).
    if (i == 0u && gSelected < 0 && uWriteReading != 0) {
        gReading = keptReading();
    }
}
