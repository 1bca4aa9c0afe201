// Debug views of the 3D inputs, shown as they are (never tone mapped): linear depth, view-space normals and
// motion vectors, as the pipeline sees them after decoding, and the data views of the effects (contact
// shadows, ambient occlusion, CoC, reflections, velocity tiles, volumetric light).
// A compute pass (8x8 groups, one pixel each, image store); with RAW the same values also go, unclamped, to an
// RGBA32F image (what an EXR of a data view holds).
#include "passes/common/display_format.h.glsl"
#include "passes/common/inputs.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uInput;
layout(binding = 0, DISPLAY_FORMAT) uniform writeonly image2D uOutput;
#ifdef RAW
layout(binding = 1, rgba32f) uniform writeonly image2D uRaw;
#endif

// Mirrors photopic::DebugInputViewParameters (passes/debug/DebugViewPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform DebugInputViewParameters {
    int uView; // DebugView: 7 depth, 8 normals, 9 motion, 10 TAA history weight, 11 disocclusion,
               // 12 contact shadows, 13 contact-shadow steps, 14 depth of field's CoC, 15 ssr,
               // 16 velocity tiles, 17 volumetric light, 18 ambient occlusion
    int uOctahedral;
    float uNear;
    float uFar;
    float uMaxCoc; // pixels
};

float segmentDistance(vec2 q, vec2 a, vec2 b) {
    vec2 ab = b - a;
    float t = clamp(dot(q - a, ab) / max(dot(ab, ab), 1e-6), 0.0, 1.0);
    return length(q - (a + t * ab));
}

vec3 hsvToRgb(float h, float s, float v) {
    vec3 k = clamp(abs(mod(h * 6.0 + vec3(0.0, 4.0, 2.0), 6.0) - 3.0) - 1.0, 0.0, 1.0);
    return v * mix(vec3(1.0), k, s);
}

const int kArrowCell = 16;

// 1 on the arrow of the motion of `p`'s cell (shaft and a two-stroke head), 0 elsewhere.
float arrowCoverage(ivec2 p, ivec2 size) {
    ivec2 cell = p / kArrowCell;
    vec2 centre = vec2(cell * kArrowCell) + 0.5 * float(kArrowCell);
    ivec2 at = clamp(ivec2(centre), ivec2(0), size - 1);
    vec2 motion = motionUvToPixels(texelFetch(uInput, at, 0).rg, size);
    float len = length(motion);
    if (!(len > 0.05)) {
        return 0.0;
    }
    vec2 arrow = motion * min(0.8 * float(kArrowCell) / max(len, 8.0), 4.0);
    vec2 tip = centre + arrow;
    vec2 q = vec2(p) + 0.5;
    // Distance to the shaft and to the head's two strokes (30 degrees back from the tip).
    vec2 back = -normalize(arrow) * min(4.0, 0.4 * length(arrow) + 1.5);
    float c30 = 0.8660254, s30 = 0.5;
    vec2 h1 = vec2(c30 * back.x - s30 * back.y, s30 * back.x + c30 * back.y);
    vec2 h2 = vec2(c30 * back.x + s30 * back.y, -s30 * back.x + c30 * back.y);
    float d = segmentDistance(q, centre, tip);
    d = min(d, segmentDistance(q, tip, tip + h1));
    d = min(d, segmentDistance(q, tip, tip + h2));
    return d < 0.6 ? 1.0 : 0.0;
}

void store(ivec2 p, vec4 value) {
    imageStore(uOutput, p, value);
#ifdef RAW
    imageStore(uRaw, p, value);
#endif
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(uOutput)))) {
        return;
    }
    ivec2 size = textureSize(uInput, 0);
    vec4 t = texelFetch(uInput, p, 0);
    vec3 c = vec3(0.0);
    if (uView == 7) {
        // log(z / near) / log(far / near): even steps per doubling of distance; the sky stays black.
        float z = t.r;
        if (z > 0.0 && z < uFar) {
            c = vec3(1.0 - clamp(log(z / uNear) / log(uFar / uNear), 0.0, 1.0));
        }
    } else if (uView == 8) {
        vec3 n = uOctahedral != 0 ? octahedralDecode(t.rg) : t.xyz;
        c = dot(n, n) > 0.0 ? 0.5 + 0.5 * normalize(n) : vec3(0.0);
    } else if (uView == 9) {
        vec2 pixels = motionUvToPixels(t.rg, size);
        float len = length(pixels);
        float hue = len > 0.0 ? fract(atan(pixels.y, pixels.x) / 6.28318531 + 1.0) : 0.0;
        c = hsvToRgb(hue, 1.0, clamp(len / 8.0, 0.0, 1.0));
        // An arrow per 16 x 16 cell from the cell's centre along its motion (scaled so that 8 px of motion
        // spans most of the cell; an arrow shows where the point goes, so it points to current - previous).
        if (arrowCoverage(p, size) > 0.0) {
            c = mix(c, vec3(1.0), 0.85);
        }
    } else if (uView == 10) {
        c = vec3(t.r);
    } else if (uView == 11) {
        c = vec3(t.g);
    } else if (uView == 12 || uView == 13) {
        c = vec3(t.r); // contact shadows' visibility, or the steps its march took (normalised)
    } else if (uView == 14) {
        // Signed CoC over the largest radius: near field red, far field blue, in focus black.
        float r = clamp(t.r / uMaxCoc, -1.0, 1.0);
        c = vec3(max(-r, 0.0), 0.0, max(r, 0.0));
    } else if (uView == 15) {
        // Screen-space reflections: the reflected radiance as it is (scene-referred) and the confidence in
        // alpha, so that an EXR of the view holds both.
        store(p, t);
        return;
    } else if (uView == 16) {
        c = t.rgb; // motion blur's neighbourhood maximum radius: x, y (pixels, y up), length
    } else if (uView == 17) {
        c = t.rgb; // the light volumetric light added (scene-referred)
    } else if (uView == 18) {
        c = vec3(t.r); // ambient occlusion's visibility, 1: unoccluded
    }
    store(p, vec4(c, 1.0));
}
