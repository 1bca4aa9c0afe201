// Shared by the screen-space reflection passes: the parameter block, view-space reconstruction from linear
// depth, the surface normal (the host's, or from the depths around the pixel).
#ifndef PHOTOPIC_SSR_COMMON_H_GLSL
#define PHOTOPIC_SSR_COMMON_H_GLSL

#include "passes/common/inputs.h.glsl"

// Mirrors photopic::SsrParameters (passes/ssr/SsrPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform SsrParameters {
    mat4 uProjection;
    mat4 uReprojection; // this frame's view space -> last frame's clip space
    vec4 uRayNear[3];   // view-space point at NDC z = -1: [0] + x [1] + y [2]
    vec4 uRayFar[3];    // the same at NDC z = 0
    vec2 uFullSize;     // pixels
    vec2 uTraceSize;    // pixels of the trace target (half the image at half resolution)
    float uThickness;   // world units
    float uMaxDistance; // world units
    float uRoughnessCutoff;
    float uEdgeFade; // pixels
    float uIntensity;
    int uMaxSteps;
    int uLevels;      // levels of the depth pyramid
    int uNormals;     // 0: reconstruct from depth, 1: view xyz, 2: octahedral
    int uHasMaterial; // the host gave F0 and roughness
    int uHasHistory;  // last frame's image is valid
    int uHasMotion;   // the frame has motion vectors
    int uHalf;        // the trace runs at half resolution
    ivec2 uPyramidSize; // level 0 of the depth pyramid (ssr_pyramid.h.glsl)
};

// Positive and finite: tested on the bit pattern (a positive float's bits are below +inf's, 0x7f800000; NaN,
// +-inf, zero and negative values are not), which no compiler may fold away as it may isinf or isnan, or a
// comparison with a NaN, under relaxed float rules.
bool finitePositive(float x) {
    uint bits = floatBitsToUint(x);
    return bits != 0u && bits < 0x7f800000u;
}

// A depth a surface can be at.
bool validDepth(float z) { return finitePositive(z); }

// The view-space point through a window position (pixels, GL origin) at linear view depth z: the view ray's
// points at NDC z = -1 and 0 are affine in NDC x and y for perspective and orthographic projections alike.
vec3 viewPositionAt(vec2 window, float z) {
    vec2 ndc = window / uFullSize * 2.0 - 1.0;
    vec3 a = uRayNear[0].xyz + ndc.x * uRayNear[1].xyz + ndc.y * uRayNear[2].xyz;
    vec3 b = uRayFar[0].xyz + ndc.x * uRayFar[1].xyz + ndc.y * uRayFar[2].xyz;
    return mix(a, b, (-z - a.z) / (b.z - a.z));
}

// The unit view direction from the eye through a window position.
vec3 viewDirectionAt(vec2 window) {
    vec2 ndc = window / uFullSize * 2.0 - 1.0;
    vec3 a = uRayNear[0].xyz + ndc.x * uRayNear[1].xyz + ndc.y * uRayNear[2].xyz;
    vec3 b = uRayFar[0].xyz + ndc.x * uRayFar[1].xyz + ndc.y * uRayFar[2].xyz;
    return normalize(b - a);
}

// The view-space step from p's point to its neighbour along +o or -o, whichever depth is closer (most likely
// the same surface); zero when neither is valid.
vec3 neighbourStep(sampler2D depth, ivec2 p, ivec2 o, vec3 centre, float z) {
    ivec2 size = ivec2(uFullSize);
    ivec2 a = clamp(p + o, ivec2(0), size - 1);
    ivec2 b = clamp(p - o, ivec2(0), size - 1);
    float za = texelFetch(depth, a, 0).r;
    float zb = texelFetch(depth, b, 0).r;
    bool useA = validDepth(za) && a != p && (!validDepth(zb) || b == p || abs(za - z) <= abs(zb - z));
    if (useA) {
        return viewPositionAt(vec2(a) + 0.5, za) - centre;
    }
    if (validDepth(zb) && b != p) {
        return centre - viewPositionAt(vec2(b) + 0.5, zb);
    }
    return vec3(0.0);
}

// The unit view-space normal at pixel p (facing the camera), or zero when there is none to trust. Where
// the normals come from is the define SSR_NORMALS (uNormals' values), not the uniform: the program is
// built once per source, so a SIMD implementation that runs every side of a branch under a mask does not
// pay for the depth reconstruction when the host gives normals.
vec3 surfaceNormal(sampler2D depth, sampler2D normals, ivec2 p, vec3 centre, float z) {
#if SSR_NORMALS == 1
    vec3 n = texelFetch(normals, p, 0).xyz;
#elif SSR_NORMALS == 2
    vec3 n = octahedralDecode(texelFetch(normals, p, 0).rg);
#else
    vec3 dx = neighbourStep(depth, p, ivec2(1, 0), centre, z);
    vec3 dy = neighbourStep(depth, p, ivec2(0, 1), centre, z);
    vec3 n = cross(dx, dy);
#endif
    float len2 = dot(n, n);
    if (!finitePositive(len2) || len2 <= 1e-12) { // NaN, zero, tiny or infinite
        return vec3(0.0);
    }
    n *= inversesqrt(len2);
    // Facing the camera: a reconstructed normal's sign is arbitrary; a host's may be flipped.
    return dot(n, centre) > 0.0 ? -n : n;
}

#endif
