// Shared by the volumetric light dispatches: the parameter block and a few guards.
#ifndef PHOTOPIC_VOLUMETRIC_LIGHT_COMMON_H_GLSL
#define PHOTOPIC_VOLUMETRIC_LIGHT_COMMON_H_GLSL

// Mirrors photopic::VolumetricLightParameters (passes/volumetriclight/VolumetricLightPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform VolumetricLightParameters {
    vec2 uSunUv;    // the sun's projected position, UV, (0, 0) bottom-left; may be off screen
    vec2 uHalfSize; // texels of the half-resolution march
    vec2 uFullSize; // pixels
    float uDensity; // fraction of the way to the sun the samples reach
    float uLogDecay; // 64 log2(decay): a sample at fraction t of the way weighs exp2(t uLogDecay)
    float uScale;    // intensity x weight x exposure x the sun's fade
    float uHistoryWeight;
    int uSamples;
    uint uFrame;
    int uHasHistory;
    int uHasMotion;
    int uWriteView;
    int uActive; // 0: the sun is behind the camera or beyond the fade margin; every dispatch writes 0
    float uSkyDepth; // linear depths at or beyond this are the sky (+inf always is)
    vec3 uPadding;
};

const float kHalfMax = 65504.0;

// Finite, non-negative and below the half-float maximum; anything else is 0.
vec3 sanitizeLight(vec3 c) {
    bvec3 bad = bvec3(isnan(c.x) || isinf(c.x), isnan(c.y) || isinf(c.y), isnan(c.z) || isinf(c.z));
    return any(bad) ? vec3(0.0) : clamp(c, vec3(0.0), vec3(kHalfMax));
}

#endif
