// Shared by the GTAO passes: the parameter block and view-space reconstruction from linear depth.
#ifndef PHOTOPIC_GTAO_COMMON_H_GLSL
#define PHOTOPIC_GTAO_COMMON_H_GLSL

#include "passes/common/inputs.h.glsl"

// Mirrors photopic::GtaoParameters (passes/gtao/GtaoPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform GtaoParameters {
    mat4 uProjection;
    vec2 uFullSize; // full-resolution extent, pixels
    float uRadius;  // world units
    float uBias;    // world units along the normal
    int uSlices; // the preset's, as the search was built for them (GTAO_SLICES, GTAO_STEPS, GTAO_SCALE)
    int uSteps;  // per side
    int uScale;  // full-resolution pixels per AO texel
    uint uFrame;
    int uOctahedral;
    vec2 uTexelScale; // viewPositionAtTexel's constants, from the projection and the extent
    vec2 uTexelBias;
    vec2 uDepthScale;
    vec2 uViewOffset;
};

// View-space point at the centre of a full-resolution texel at linear view depth z (view z = -z), solved
// from the projection's rows in closed form: clip w = P[2][3] vz + P[3][3] and ndc.x = (P[0][0] vx + P[2][0] vz
// + P[3][0]) / w (y alike), for the perspective and orthographic projections the frame takes (off-centre
// included; no shear between x and y). With ndc = (texel + 0.5) 2 / size - 1 the divisions fold into four
// constants the pass computes once (GtaoPass::texelToView): xy = (texel uTexelScale + uTexelBias) w + z
// uDepthScale + uViewOffset, w = P[3][3] - P[2][3] z. A few multiply-adds a sample.
vec3 viewPositionAtTexel(ivec2 texel, float z) {
    float w = uProjection[3][3] - uProjection[2][3] * z;
    return vec3((vec2(texel) * uTexelScale + uTexelBias) * w + z * uDepthScale + uViewOffset, -z);
}

// The full-resolution pixel an AO texel is computed at. At half resolution the pixel within the 2 x 2 block
// alternates between neighbouring texels (x with the texel's row, y with its column), so every
// full-resolution row and column is sampled by every second texel: a one-pixel contact strip (the ground
// at the foot of a wall seen at a grazing angle) is not skipped whole when it falls on odd rows.
ivec2 aoSourcePixelAt(ivec2 q, ivec2 full, int scale) {
    ivec2 offset = scale == 2 ? ivec2(q.y & 1, q.x & 1) : ivec2(0);
    return min(q * scale + offset, full - 1);
}

#endif
