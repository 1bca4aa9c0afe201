// Shared by the GTAO passes: the parameter block and view-space reconstruction from linear depth.
#ifndef PHOTOPIC_GTAO_COMMON_H_GLSL
#define PHOTOPIC_GTAO_COMMON_H_GLSL

#include "passes/common/inputs.h.glsl"

// Mirrors photopic::GtaoParameters (passes/gtao/GtaoPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform GtaoParameters {
    mat4 uInvProjection;
    mat4 uProjection;
    vec2 uFullSize; // full-resolution extent, pixels
    float uRadius;  // world units
    float uBias;    // world units along the normal
    int uSlices;
    int uSteps; // per side
    int uScale; // full-resolution pixels per AO texel
    uint uFrame;
    int uOctahedral;
};

// View-space point on the ray through a full-resolution window position (pixels, GL origin) at linear view
// depth z. The ray is the line through two unprojected points, so orthographic projections work as well.
vec3 viewPositionAt(vec2 window, float z) {
    vec2 ndc = window / uFullSize * 2.0 - 1.0;
    vec4 a = uInvProjection * vec4(ndc, -1.0, 1.0);
    vec4 b = uInvProjection * vec4(ndc, 0.0, 1.0);
    a.xyz /= a.w;
    b.xyz /= b.w;
    float t = (-z - a.z) / (b.z - a.z);
    return mix(a.xyz, b.xyz, t);
}

// The full-resolution pixel an AO texel is computed at. At half resolution the pixel within the 2 x 2 block
// alternates between neighbouring texels (x with the texel's row, y with its column), so every
// full-resolution row and column is sampled by every second texel: a one-pixel contact strip (the ground
// at the foot of a wall seen at a grazing angle) is not skipped whole when it falls on odd rows.
ivec2 aoSourcePixel(ivec2 q, ivec2 full) {
    ivec2 offset = uScale == 2 ? ivec2(q.y & 1, q.x & 1) : ivec2(0);
    return min(q * uScale + offset, full - 1);
}

#endif
