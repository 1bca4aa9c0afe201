// Canvas shading into the scene's HDR target (RGBA16F, scene-linear).
// References: Blinn 1977 (half-vector specular).
// Variants (#defines):
//   CANVAS_TILED     1: one workgroup per 16x16 block of a listed tile, the tile from the list at uListOffset +
//                       gl_WorkGroupID.z (glDispatchComputeIndirect); 0: one dispatch over the whole image
//   CANVAS_SPECULAR  1: diffuse + Blinn-Phong + sparkle; 0: diffuse only (empty tiles, which have no material)
layout(local_size_x = 16, local_size_y = 16) in;
#include "canvas_shading.h.glsl"

layout(binding = 0, rgba16f) writeonly uniform image2D uOutput;
#if CANVAS_TILED
layout(std430, binding = TILE_LIST_BINDING) readonly buffer TileLists {
    uint occupiedArgs[3];
    uint emptyArgs[3];
    uint pad0;
    uint pad1;
    uint tiles[];
};
uniform int uTileSize;
uniform int uTilesX;
uniform int uListOffset;
#endif

void main() {
#if CANVAS_TILED
    uint tile = tiles[uint(uListOffset) + gl_WorkGroupID.z];
    ivec2 origin = ivec2(int(tile % uint(uTilesX)), int(tile / uint(uTilesX))) * uTileSize;
    ivec2 p = origin + ivec2(gl_WorkGroupID.xy * 16u + gl_LocalInvocationID.xy);
#else
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
#endif
    ivec2 size = imageSize(uOutput);
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    vec3 base = texelFetch(uColor, p, 0).rgb;
    uvec4 m = texelFetch(uMaterial, p, 0);
    vec3 n = decodeNormal(m);
    vec3 c = shadeDiffuse(base, n);
#if CANVAS_SPECULAR
    c += shadeSpecular(n, m, p, size);
#endif
    imageStore(uOutput, p, vec4(c, 1.0));
}
