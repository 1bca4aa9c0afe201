// Histogram overlay (an overlay, last in the display domain; docs/architecture.md), drawn straight from the
// GPU histogram buffer over the tone-mapped image: 256 bars (bin 0 underflow at the left, 255 overflow at the
// right; height ~ sqrt of the count so thin tails stay visible), the percentile window shaded blue, and
// vertical markers in log2 scene luminance: the window's average (cyan), the luminance the target exposure
// maps to the key value (green) and the one the current exposure maps to it (red). Binning as in
// core/Metering.h.
// A compute pass (8x8 groups, one pixel each, image store), like every full-screen pass.
#include "passes/common/display_format.h.glsl"
#include "passes/common/exposure.h.glsl"
#include "passes/metering/metering.h.glsl"
#include "passes/metering/metering_buffers.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uDisplay;
layout(binding = 0, DISPLAY_FORMAT) uniform writeonly image2D uOutput;

// Mirrors photopic::HistogramOverlayParameters (passes/debug/DebugViewPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform HistogramOverlayParameters {
    vec4 uPanel; // x0, y0, width, height in pixels (GL window coordinates, origin bottom-left)
    float uLog2Min;
    float uLog2Max;
    float uKeyValue;
};

// Panel x (0..1) of a log2 luminance: bin b spans [b, b + 1) / 256 and its centre is at (b + 0.5) / 256.
float panelX(float log2L) {
    float binWidth = (uLog2Max - uLog2Min) / kHistogramRangeBins;
    float bin = (log2L - uLog2Min) / binWidth + 0.5;
    return (bin + 0.5) / float(kHistogramBins);
}

bool nearMarker(float x, float markerX, float pixel) {
    return abs(x - markerX) <= pixel;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(uOutput)))) {
        return;
    }
    vec3 c = texelFetch(uDisplay, p, 0).rgb;
    vec2 local = (vec2(p) + 0.5 - uPanel.xy) / uPanel.zw;
    if (all(greaterThanEqual(local, vec2(0.0))) && all(lessThan(local, vec2(1.0)))) {
        int bin = clamp(int(local.x * float(kHistogramBins)), 0, kHistogramBins - 1);
        float centre = histogramBinCentreLog2(bin, uLog2Min, uLog2Max);
        bool inWindow = gExposure.histogramCount > 0u && centre >= gExposure.histogramLowLog2 &&
                        centre <= gExposure.histogramHighLog2;
        c = mix(c, inWindow ? vec3(0.05, 0.12, 0.3) : vec3(0.0), 0.7);
        float peak = float(max(gExposure.histogramPeak, 1u));
        float height = sqrt(float(gBins[bin]) / peak);
        if (local.y < height) {
            c = inWindow ? vec3(0.85, 0.9, 1.0) : vec3(0.55);
        }
        float pixel = 1.0 / uPanel.z;
        if (gExposure.histogramCount > 0u && nearMarker(local.x, panelX(gExposure.histogramAverageLog2), pixel)) {
            c = vec3(0.0, 1.0, 1.0);
        }
        float keyLog2 = log2(uKeyValue);
        if (gExposure.initialized != 0 || gExposure.meteredLuminance > 0.0) {
            if (nearMarker(local.x, panelX(keyLog2 - gExposure.targetLog2), pixel)) {
                c = vec3(0.1, 1.0, 0.2);
            }
        }
        if (gExposure.initialized != 0 && gExposure.autoEnabled != 0 &&
            nearMarker(local.x, panelX(keyLog2 - gExposure.appliedLog2), pixel)) {
            c = vec3(1.0, 0.15, 0.1);
        }
    }
    imageStore(uOutput, p, vec4(onDisplayCode(c), 1.0));
}
