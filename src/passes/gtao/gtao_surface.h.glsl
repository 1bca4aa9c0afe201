// GTAO's surface texture: one RG32UI texel per full-resolution pixel holding the linear view depth (x, its
// float bits; +inf for the sky) and the view-space normal (y, packNormal10), so a sample of the horizon
// search or the denoiser is one fetch, not a depth and a normal fetch.
#ifndef PHOTOPIC_GTAO_SURFACE_H_GLSL
#define PHOTOPIC_GTAO_SURFACE_H_GLSL

#include "passes/gtao/gtao_normal.h.glsl"

layout(binding = 0) uniform usampler2D uSurface;

struct GtaoSurface {
    float z;   // linear view depth; +inf: sky
    vec3 n;    // view-space normal, NOT normalized (its largest component +-511): callers that need a unit
               // normal normalize it; plane equations do not need to
};

// Octahedral decode without the normalization (the branchless form of octahedralDecode's fold), of a pair
// scaled so that `one` stands for 1: the direction comes out `one` times longer.
vec3 octahedralDirection(vec2 e, float one) {
    vec3 n = vec3(e, one - abs(e.x) - abs(e.y));
    float t = max(-n.z, 0.0);
    n.xy += vec2(n.x >= 0.0 ? -t : t, n.y >= 0.0 ? -t : t);
    return n;
}

GtaoSurface unpackSurface(uvec2 t) { return GtaoSurface(uintBitsToFloat(t.x), unpackNormal10(t.y)); }

GtaoSurface surfaceAt(ivec2 p) { return unpackSurface(texelFetch(uSurface, p, 0).xy); }

// The horizon search's output texel (RG32UI): the surface it was computed at (the depth's bits, the normal's
// octahedral pair as two snorm8, enough for the denoiser's weights) and the raw visibility as unorm16, so a
// tap of the denoiser is one fetch. `normal` as the surface texture holds it (packNormal10).
uvec2 packAoTexel(uint depthBits, uint normalBits, float visibility) {
    vec2 e = octahedralEncode(unpackNormal10(normalBits));
    uint normal = packSnorm4x8(vec4(e, 0.0, 0.0)) & 0xFFFFu;
    return uvec2(depthBits, normal | (packUnorm2x16(vec2(0.0, visibility)) & 0xFFFF0000u));
}

struct AoTexel {
    float z;          // +inf: sky
    vec3 n;           // not normalized (127 times the octahedral direction)
    float visibility; // raw, [0, 1]
};

AoTexel unpackAoTexel(uvec2 t) {
    // The snorm8 pair as integers: the direction comes out 127 times longer, which the denoiser's weights
    // (a cosine from a ratio of dot products) do not see.
    vec2 e = vec2(ivec2(uvec2(t.y << 24, t.y << 16)) >> 24);
    return AoTexel(uintBitsToFloat(t.x), octahedralDirection(e, 127.0), unpackUnorm2x16(t.y).y);
}

bool isSurface(float z) { return !isinf(z) && z > 0.0; }

#endif
