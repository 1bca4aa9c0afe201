// GTAO's surface texture: one RG32UI texel per full-resolution pixel holding the linear view depth (x, its
// float bits; +inf for the sky) and the view-space normal (y, packNormal10), so a sample of the horizon
// search or the denoiser is one load, not a depth and a normal fetch. Read as an image: a load skips the
// sampler's level and filtering logic (on a SIMD CPU implementation about a fifth of the search's time).
#ifndef PHOTOPIC_GTAO_SURFACE_H_GLSL
#define PHOTOPIC_GTAO_SURFACE_H_GLSL

#include "passes/gtao/gtao_normal.h.glsl"
#include "passes/gtao/gtao_pyramid.h.glsl"

layout(binding = 1, rg32ui) uniform readonly uimage2D uSurface;

struct GtaoSurface {
    float z;   // linear view depth; +inf: sky
    vec3 n;    // view-space normal, NOT normalized (its largest component +-511): callers that need a unit
               // normal normalize it; plane equations do not need to
};

GtaoSurface unpackSurface(uvec2 t) { return GtaoSurface(uintBitsToFloat(t.x), unpackNormal10(t.y)); }

GtaoSurface surfaceAt(ivec2 p) { return unpackSurface(imageLoad(uSurface, p).xy); }

// The horizon search's output texel (RG32UI): the surface it was computed at and the raw visibility, so a
// tap of the denoiser is one fetch. x: the depth's float bits with the low 8 mantissa bits replaced by the
// unit normal's z as snorm8 (the depth keeps 15 bits of mantissa, a relative error under 3e-5, far below the
// denoiser's plane tolerance; +inf, the sky, stays +inf); y: the normal's x and y as snorm8, the visibility
// as unorm16. The normal is unit length times 127, so the denoiser's cosine is a dot product and a constant
// scale, with no decode beyond three shifts. `normal` as the surface texture holds it (packNormal10).
uvec2 packAoTexel(uint depthBits, uint normalBits, float visibility) {
    ivec3 n = ivec3(round(normalize(unpackNormal10(normalBits)) * 127.0)) & 0xFF;
    return uvec2((depthBits & 0xFFFFFF00u) | uint(n.z),
                 uint(n.x) | (uint(n.y) << 8) | (uint(round(clamp(visibility, 0.0, 1.0) * 65535.0)) << 16));
}

struct AoTexel {
    float z;          // +inf: sky
    vec3 n;           // 127 times the unit normal (to within rounding)
    float visibility; // raw, [0, 1]
};

AoTexel unpackAoTexel(uvec2 t) {
    vec3 n = vec3(ivec3(uvec3(t.y << 24, t.y << 16, t.x << 24)) >> 24);
    return AoTexel(uintBitsToFloat(t.x & 0xFFFFFF00u), n, float(t.y >> 16) * (1.0 / 65535.0));
}

bool isSurface(float z) { return !isinf(z) && z > 0.0; }

#endif
