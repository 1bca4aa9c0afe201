// Shared by the contact-shadow passes: the parameter block and view-space reconstruction from linear depth.
#ifndef PHOTOPIC_CONTACT_SHADOWS_COMMON_H_GLSL
#define PHOTOPIC_CONTACT_SHADOWS_COMMON_H_GLSL

#include "passes/common/inputs.h.glsl"

// Mirrors photopic::ContactShadowParameters (passes/contactshadows/ContactShadowsPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform ContactShadowParameters {
    mat4 uProjection;
    mat4 uReprojection; // this frame's view space -> last frame's clip space
    vec4 uRayNear[3];   // view-space point at NDC z = -1: [0] + x [1] + y [2]
    vec4 uRayFar[3];    // the same at NDC z = 0
    vec4 uSunView;      // xyz: unit, towards the sun, view space
    vec2 uFullSize;     // pixels
    float uDistance;    // world units
    float uThickness;   // world units
    float uStrength;
    int uSteps;
    uint uFrame;
    int uMaskCount;
    int uWriteSteps;
    int uHasHistory;
    int uHasMotion;
    float uEdgeFade; // pixels
    float uHistoryWeight;
    float uPadding0, uPadding1, uPadding2;
    uvec4 uMask[4];
};

bool validDepth(float z) { return z > 0.0 && !isinf(z); } // NaN fails the first test

// The view ray through a window position (pixels, GL origin): its points at NDC z = -1 and z = 0.
void viewRay(vec2 window, out vec3 a, out vec3 b) {
    vec2 ndc = window / uFullSize * 2.0 - 1.0;
    a = uRayNear[0].xyz + ndc.x * uRayNear[1].xyz + ndc.y * uRayNear[2].xyz;
    b = uRayFar[0].xyz + ndc.x * uRayFar[1].xyz + ndc.y * uRayFar[2].xyz;
}

// View-space point through a window position at linear view depth z (perspective and orthographic alike).
vec3 viewPositionAt(vec2 window, float z) {
    vec3 a, b;
    viewRay(window, a, b);
    float t = (-z - a.z) / (b.z - a.z);
    return mix(a, b, t);
}

#endif
