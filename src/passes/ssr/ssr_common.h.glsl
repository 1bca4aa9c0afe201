// Shared by the screen-space reflection passes: the parameter block and view-space reconstruction from
// linear depth.
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

#endif
