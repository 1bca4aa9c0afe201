// GTAO's surface texture (gtao_surface.h.glsl) from the linear depth and the host's normals: read once per
// pixel here, then by every sample of the horizon search and every tap of the denoiser as one texel.
#include "passes/gtao/gtao_common.h.glsl"
#include "passes/gtao/gtao_normal.h.glsl"
#include "passes/gtao/gtao_pyramid.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1, r32f) uniform readonly image2D uLinearDepth; // +inf: sky
layout(binding = 1) uniform sampler2D uNormals;     // view space (or octahedral)
layout(binding = 0, rg32ui) uniform writeonly uimage2D uSurfaceOut;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(uFullSize)))) {
        return;
    }
    float z = imageLoad(uLinearDepth, p).r;
    vec4 t = texelFetch(uNormals, p, 0);
    vec3 n = uOctahedral != 0 ? octahedralDecode(t.rg) : t.xyz;
    float len2 = dot(n, n);
    // A missing or broken normal: the surface faces the camera (the search then finds the horizons the
    // depths give, clamped to the hemisphere around the view vector).
    n = len2 > 1e-12 && !isinf(len2) ? n : vec3(0.0, 0.0, 1.0);
    uvec4 texel = uvec4(floatBitsToUint(z), packNormal10(n), 0u, 0u);
    imageStore(uSurfaceOut, p, texel);
#if GTAO_SAMPLE_MIPS
    // The coarse levels: this pixel's texel where it is the one its cell keeps.
    ivec2 full = ivec2(uFullSize);
    for (int level = 1; level <= kSurfaceLevels; ++level) {
        ivec2 cell = p >> level;
        ivec2 pick = surfacePick(cell, level, full);
        if (all(equal(pick, p))) {
            imageStore(uSurfaceOut, surfaceLevelOrigin(level, full) + cell,
                       uvec4(coarseSurfaceTexel(texel.xy, pick - (cell << level)), 0u, 0u));
        }
    }
#endif
}
