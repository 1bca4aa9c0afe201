// Motion blur's parameter block and helpers, shared by its four dispatches.
#ifndef PHOTOPIC_MOTION_BLUR_COMMON_H_GLSL
#define PHOTOPIC_MOTION_BLUR_COMMON_H_GLSL

// Mirrors photopic::MotionBlurParameters (passes/motionblur/MotionBlurPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform MotionBlurParameters {
    vec2 uFullSize;     // pixels
    float uRadiusScale; // UV motion x uFullSize x this = blur radius in pixels
    float uMaxBlur;     // pixels
    int uTileSize;
    int uSampleCount;
    uint uFrame;
    int uWriteTiles;
    ivec2 uTileCount;
};

// The larger of two velocities by length (the first on a tie).
vec2 longer(vec2 a, vec2 b) { return dot(b, b) > dot(a, a) ? b : a; }

#endif
