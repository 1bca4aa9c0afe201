// Scene-value debug views (frame order: docs/architecture.md): they replace the image before tone mapping and
// are shown as they are, never tone mapped. Values are exposed scene values (colour x gExposure.exposure).
// Conventions (false-colour bands: blue ramp below 1, yellow >= 1, orange >= 2, magenta >= 4, white >= 8;
// stops log2(Y exposure / 0.18), one colour per stop -6..+6, as in the EL Zone System); core/Metering.h for
// the metering weights.
// A compute pass (8x8 groups, one pixel each, image store), like every full-screen pass.
#include "passes/common/color.h.glsl"
#include "passes/common/display_format.h.glsl"
#include "passes/common/exposure.h.glsl"
#include "passes/common/sanitize.h.glsl"
#include "passes/metering/metering.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uScene;
layout(binding = 0, DISPLAY_FORMAT) uniform writeonly image2D uOutput;
layout(binding = 1) uniform sampler2D uMask;
layout(binding = 2) uniform sampler2D uBloom;

// Mirrors photopic::DebugSceneViewParameters (passes/debug/DebugViewPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform DebugSceneViewParameters {
    int uView; // DebugView: 1 exposure, 2 luma, 3 ev, 4 metering, 6 bloom
    int uHasBloom;
    int uHasMask;
    int uMeteringMode;
    float uLog2Min;
    float uLog2Max;
    vec2 uSpotUv;
    float uSpotRadius;
};

// Display colours (sRGB-encoded, written as they are).
vec3 falseColor(float y) {
    if (y >= 8.0) {
        return vec3(1.0);
    }
    if (y >= 4.0) {
        return vec3(1.0, 0.0, 1.0);
    }
    if (y >= 2.0) {
        return vec3(1.0, 0.5, 0.0);
    }
    if (y >= 1.0) {
        return vec3(1.0, 1.0, 0.0);
    }
    return mix(vec3(0.0, 0.0, 0.15), vec3(0.35, 0.65, 1.0), clamp(y, 0.0, 1.0));
}

// One colour per stop from -6 to +6 around middle grey: cold to hot, middle grey itself grey.
const vec3 kStopColors[13] = vec3[](vec3(0.10, 0.00, 0.25), vec3(0.25, 0.00, 0.55), vec3(0.20, 0.15, 0.85),
                                     vec3(0.00, 0.40, 1.00), vec3(0.00, 0.70, 0.90), vec3(0.00, 0.75, 0.45),
                                     vec3(0.50, 0.50, 0.50), vec3(0.55, 0.85, 0.10), vec3(0.95, 0.90, 0.00),
                                     vec3(1.00, 0.65, 0.00), vec3(1.00, 0.35, 0.00), vec3(0.90, 0.00, 0.10),
                                     vec3(1.00, 1.00, 1.00));

vec3 stopColor(float y) {
    if (!(y > 0.0)) {
        return kStopColors[0];
    }
    float stops = log2(y / 0.18);
    return kStopColors[clamp(int(floor(stops + 0.5)), -6, 6) + 6];
}

// The weight this pixel gets in the current metering mode (core/Metering.h); 0 for luminance no mean takes.
float meteringWeight(ivec2 texel, ivec2 size, float lum) {
    if (!isMeterable(lum) && uMeteringMode != kMeterHistogram) {
        return 0.0;
    }
    vec2 uv = imageUv(imagePixel(texel, size), size);
    float aspect = float(size.x) / float(size.y);
    if (uMeteringMode == kMeterHistogram) {
        // Inside the percentile window: the bin's centre lies between the window's edge bins.
        int bin = histogramBin(lum, uLog2Min, uLog2Max);
        if (bin < 0 || gExposure.histogramCount == 0u) {
            return 0.0;
        }
        float centre = histogramBinCentreLog2(bin, uLog2Min, uLog2Max);
        return centre >= gExposure.histogramLowLog2 && centre <= gExposure.histogramHighLog2 ? 1.0 : 0.0;
    }
    if (uMeteringMode == kMeterSpot) {
        return spotWeight(uv, uSpotUv, uSpotRadius, aspect);
    }
    if (uMeteringMode == kMeterCenter) {
        return centerWeight(uv, aspect);
    }
    if (uMeteringMode == kMeterMask && uHasMask != 0) {
        return maskWeight(uMask, uv);
    }
    return 1.0;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(uOutput)))) {
        return;
    }
    ivec2 size = textureSize(uScene, 0);
    vec3 scene = sanitize(texelFetch(uScene, p, 0).rgb);
    float lum = luma709(scene);
    float exposed = lum * gExposure.exposure;
    vec3 c = vec3(0.0);
    if (uView == 1) {
        c = falseColor(exposed);
    } else if (uView == 2) {
        c = vec3(srgbEncode(exposed));
    } else if (uView == 3) {
        c = stopColor(exposed);
    } else if (uView == 4) {
        float w = clamp(meteringWeight(p, size, lum), 0.0, 1.0);
        // The weight over a dim grey copy of the image, so the metered region reads against the scene.
        c = mix(vec3(0.3 * srgbEncode(exposed)), vec3(1.0, 0.6, 0.1), w);
    } else if (uView == 6 && uHasBloom != 0) {
        // The bloom chain's result is half or a quarter of the frame: brought up with one bilinear tap, as the
        // composite adds it (a texel fetch at the frame's pixel would read past its edge).
        c = srgbEncode(sanitize(textureLod(uBloom, (vec2(p) + 0.5) / vec2(size), 0.0).rgb));
    }
    imageStore(uOutput, p, vec4(onDisplayCode(c), 1.0));
}
