// Debug views of the 3D inputs, shown as they are (never tone mapped): linear depth, view-space normals and
// motion vectors, as the pipeline sees them after decoding.
#include "passes/common/inputs.h.glsl"

layout(binding = 0) uniform sampler2D uInput;

// Mirrors photopic::DebugInputViewParameters (passes/debug/DebugViewPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform DebugInputViewParameters {
    int uView; // DebugView: 7 depth, 8 normals, 9 motion, 10 TAA history weight, 11 disocclusion
    int uOctahedral;
    float uNear;
    float uFar;
};

layout(location = 0) out vec4 oColor;

vec3 hsvToRgb(float h, float s, float v) {
    vec3 k = clamp(abs(mod(h * 6.0 + vec3(0.0, 4.0, 2.0), 6.0) - 3.0) - 1.0, 0.0, 1.0);
    return v * mix(vec3(1.0), k, s);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
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
    } else if (uView == 10) {
        c = vec3(t.r);
    } else if (uView == 11) {
        c = vec3(t.g);
    }
    oColor = vec4(c, 1.0);
}
