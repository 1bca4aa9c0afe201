// Shared by the shadow-map volumetric light dispatches: the parameter block, the view rays and the guards.
#ifndef PHOTOPIC_VOLUMETRIC_SHADOW_COMMON_H_GLSL
#define PHOTOPIC_VOLUMETRIC_SHADOW_COMMON_H_GLSL

// Mirrors photopic::VolumetricShadowParameters (passes/volumetriclight/VolumetricLightPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform VolumetricShadowParameters {
    mat4 uWorldToShadowClip;  // world -> the sun view's clip space
    mat4 uInverseView;        // view -> world: the camera's axes and position
    mat4 uPrevViewProjection; // world -> last frame's clip space
    vec4 uProjection;         // x: 1 / P00, y: 1 / P11, z: P20, w: P21 (the projection's terms)
    vec4 uLight;              // rgb: illuminance x single-scattering albedo; w: anisotropy g
    vec4 uToSun;              // xyz: towards the sun, unit; w: unused
    vec2 uLowSize;            // texels of the march
    vec2 uFullSize;           // pixels
    float uExtinction;        // per scene unit
    float uMaxDistance;       // scene units along the ray
    float uHistoryWeight;
    float uSkyDepth;          // linear depths at or beyond this are the sky (+inf always is)
    int uSamples;
    uint uFrame;
    int uHasHistory;
    int uWriteView;
    int uFactor;              // full-resolution pixels per march texel on each axis
    float uIntensity;
    vec2 uPadding;
};

const float kHalfMax = 65504.0;

// Finite, non-negative and below the half-float maximum; anything else is 0.
vec3 sanitizeLight(vec3 c) {
    bvec3 bad = bvec3(isnan(c.x) || isinf(c.x), isnan(c.y) || isinf(c.y), isnan(c.z) || isinf(c.z));
    return any(bad) ? vec3(0.0) : clamp(c, vec3(0.0), vec3(kHalfMax));
}

bool isSky(float z) { return z >= uSkyDepth; } // +inf passes, NaN fails

// A usable depth: positive and finite, or the sky.
bool validDepth(float z) { return z > 0.0 && !isnan(z); }

// The world-space ray through `uv` per unit of linear (view-axis) depth: point = origin + ray * depth.
vec3 viewRay(vec2 uv) {
    vec2 ndc = uv * 2.0 - 1.0;
    vec3 v = vec3((ndc.x + uProjection.z) * uProjection.x, (ndc.y + uProjection.w) * uProjection.y, -1.0);
    return mat3(uInverseView) * v;
}

vec3 cameraPosition() { return uInverseView[3].xyz; }

// Two linear depths belong to the same surface: both the sky, or within 5% of each other.
bool sameSurface(float a, float b) {
    if (isSky(a) || isSky(b)) {
        return isSky(a) && isSky(b);
    }
    return abs(a - b) <= 0.05 * max(a, b);
}

#endif
