// Outlines from depth and normal discontinuities, in the HDR image before TAA.
// Depth: 1/z is affine in screen space on any plane, so its second difference across the pixel,
// (2 w0 - wl - wr) / w0 with w = 1/z at +-width pixels, is zero on every plane whatever its tilt, and a jump
// from z0 to a farther z1 on one side gives (z1 - z0) / z1 on the near side (negative on the far side, which
// is not drawn). The sky (w = 0) is the farthest surface; sky pixels are never outlined.
// Normals: 1 - cos of the angle between the normals at -width and +width, on each axis (sky excluded, and
// not on the far side of a depth jump).
// An edge replaces the colour by the outline colour times intensity.
#include "passes/common/inputs.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1, rgba16f) uniform readonly image2D uScene;
layout(binding = 2, r32f) uniform readonly image2D uDepth;
layout(binding = 2) uniform sampler2D uNormals;
layout(binding = 0, rgba16f) uniform writeonly image2D uOut;

// Mirrors photopic::OutlineParameters (passes/outline/OutlinePass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform OutlineParameters {
    vec4 uColor; // rgb: colour, a: intensity
    float uDepthThreshold;
    float uNormalThreshold;
    int uWidth;
    int uNormalsKind; // 0 none, 1 view xyz, 2 octahedral
};

// 1/z: 0 for the sky, +inf, zero, negative and NaN depths.
float inverseDepth(ivec2 q, ivec2 size) {
    float z = imageLoad(uDepth, clamp(q, ivec2(0), size - 1)).r;
    return (z > 0.0 && !isinf(z)) ? 1.0 / z : 0.0;
}

// Unit normal, or 0 for the sky and broken values.
vec3 normalAt(ivec2 q, ivec2 size) {
    q = clamp(q, ivec2(0), size - 1);
    vec4 t = texelFetch(uNormals, q, 0);
    vec3 n = uNormalsKind == 2 ? octahedralDecode(t.rg) : t.xyz;
    float len2 = dot(n, n);
    return (len2 > 0.25 && !isinf(len2) && !isnan(len2) && inverseDepth(q, size) > 0.0) ? n * inversesqrt(len2)
                                                                                         : vec3(0.0);
}

float normalEdge(ivec2 a, ivec2 b, ivec2 size) {
    vec3 na = normalAt(a, size);
    vec3 nb = normalAt(b, size);
    return (dot(na, na) > 0.0 && dot(nb, nb) > 0.0) ? 1.0 - dot(na, nb) : 0.0;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uOut);
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    vec4 c = imageLoad(uScene, p);
    float w0 = inverseDepth(p, size);
    bool edge = false;
    if (w0 > 0.0) {
        ivec2 dx = ivec2(uWidth, 0), dy = ivec2(0, uWidth);
        float jumpX = (2.0 * w0 - inverseDepth(p - dx, size) - inverseDepth(p + dx, size)) / w0;
        float jumpY = (2.0 * w0 - inverseDepth(p - dy, size) - inverseDepth(p + dy, size)) / w0;
        edge = max(jumpX, jumpY) > uDepthThreshold;
        if (!edge && uNormalsKind != 0) {
            // Not across a jump whose far side this pixel is: the near side draws that one.
            float turnX = jumpX > -uDepthThreshold ? normalEdge(p - dx, p + dx, size) : 0.0;
            float turnY = jumpY > -uDepthThreshold ? normalEdge(p - dy, p + dy, size) : 0.0;
            edge = max(turnX, turnY) > uNormalThreshold;
        }
    }
    if (edge) {
        c.rgb = mix(c.rgb, uColor.rgb, uColor.a);
    }
    imageStore(uOut, p, c);
}
