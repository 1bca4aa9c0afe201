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
    vec2 uTexelScale; // viewPositionAtTexel's constants, from the projection and the extent
    vec2 uTexelBias;
    vec2 uDepthScale;
    vec2 uViewOffset;
};

// View-space point on the ray through a full-resolution window position (pixels, GL origin) at linear view
// depth z (view z = -z), solved from the projection's rows in closed form: clip w = P[2][3] vz + P[3][3] and
// ndc.x = (P[0][0] vx + P[2][0] vz + P[3][0]) / w (y alike), for the perspective and orthographic projections
// the frame takes (off-centre included; no shear between x and y). A few multiply-adds where unprojecting two
// points took two matrix products and two divisions, at every sample.
vec3 viewPositionAt(vec2 window, float z) {
    vec2 ndc = window / uFullSize * 2.0 - 1.0;
    float w = uProjection[3][3] - uProjection[2][3] * z;
    vec2 xy = (ndc * w + vec2(uProjection[2][0], uProjection[2][1]) * z - vec2(uProjection[3][0], uProjection[3][1])) /
              vec2(uProjection[0][0], uProjection[1][1]);
    return vec3(xy, -z);
}

// viewPositionAt at a texel's centre with the divisions folded into constants the pass computes once
// (GtaoPass::texelToView): xy = (texel uTexelScale + uTexelBias) w + z uDepthScale + uViewOffset.
vec3 viewPositionAtTexel(ivec2 texel, float z) {
    float w = uProjection[3][3] - uProjection[2][3] * z;
    return vec3((vec2(texel) * uTexelScale + uTexelBias) * w + z * uDepthScale + uViewOffset, -z);
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
