// Shared by the depth-of-field passes: the parameter block, the CoC model and the gather's sample pattern.
#ifndef PHOTOPIC_DOF_COMMON_H_GLSL
#define PHOTOPIC_DOF_COMMON_H_GLSL

// Mirrors photopic::DofParameters (passes/dof/DofPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform DofParameters {
    vec2 uFullSize;      // pixels
    vec2 uHalfSize;      // pixels of the half-resolution fields
    float uCocScale;     // physical: r(z) = scale / z + bias, full-resolution pixels
    float uCocBias;
    float uFocalDistance; // artistic
    float uFocalRange;
    float uBokehRadius;
    float uMaxCoc;      // full-resolution pixels
    int uArtistic;      // 1: artistic model
    int uKernel;        // 0: disc, 1: hexagon
    int uRings;         // rings of the gather pattern
    int uTileSize;      // half-resolution pixels per tile side
    ivec2 uTileCount;
    int uDilation;      // tiles: the near field's reach around a tile
};

bool finite4(vec4 v) { return !any(isnan(v)) && !any(isinf(v)); }

// Signed CoC radius in full-resolution pixels at linear view depth z: < 0 in front of the focus, > 0 behind.
// A depth that is not a distance (NaN, <= 0) is taken as in focus.
float cocRadius(float z) {
    if (!(z > 0.0)) {
        return 0.0;
    }
    float r;
    if (uArtistic != 0) {
        r = isinf(z) ? uBokehRadius : uBokehRadius * clamp((z - uFocalDistance) / uFocalRange, -1.0, 1.0);
    } else {
        r = isinf(z) ? uCocBias : uCocScale / z + uCocBias;
    }
    return isnan(r) ? 0.0 : clamp(r, -uMaxCoc, uMaxCoc);
}

const float kPi = 3.14159265358979;

// Sample j of ring i (1..rings; ring i holds 8 i samples, so every sample stands for the same area) on the
// unit aperture: its offset and the ring's radius fraction i / rings. The hexagon squeezes each ring onto a
// regular hexagon with its corners on the ring (the aperture of six straight blades).
vec2 apertureSample(int ring, int j, out float fraction) {
    fraction = float(ring) / float(uRings);
    float angle = 2.0 * kPi * (float(j) + 0.5 * float(ring & 1)) / float(8 * ring);
    float radius = fraction;
    if (uKernel == 1) {
        float sector = mod(angle, kPi / 3.0) - kPi / 6.0;
        radius *= cos(kPi / 6.0) / cos(sector);
    }
    return radius * vec2(cos(angle), sin(angle));
}

#endif
