// Tile-based lighting (specular and sparkle only where there is material, which saves most of the work on
// a mostly matte canvas): builds the occupancy map and the two tile lists on the GPU. One
// workgroup per tile: any pixel with material (shininess > 0 or glitter) flags the tile; thread 0 appends the
// tile to the occupied or the empty list with an atomic add on the list's indirect-dispatch z count, so the
// shading dispatches need no CPU round trip.
layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 1) uniform usampler2D uMaterial;
layout(std430, binding = TILE_LIST_BINDING) buffer TileLists {
    uint occupiedArgs[3]; // glDispatchComputeIndirect: (groups per tile side)^2 x occupied tiles
    uint emptyArgs[3];
    uint pad0;
    uint pad1;
    uint tiles[]; // [0, N): occupied tile indices; [N, 2N): empty ones
};
uniform int uTileSize;
uniform int uTilesX;
uniform int uTileCount;

shared uint sHasMaterial;

void main() {
    if (gl_LocalInvocationIndex == 0u) {
        sHasMaterial = 0u;
    }
    barrier();
    ivec2 size = textureSize(uMaterial, 0);
    ivec2 origin = ivec2(gl_WorkGroupID.xy) * uTileSize;
    uint found = 0u;
    for (int y = int(gl_LocalInvocationID.y); y < uTileSize; y += 16) {
        for (int x = int(gl_LocalInvocationID.x); x < uTileSize; x += 16) {
            ivec2 p = origin + ivec2(x, y);
            if (all(lessThan(p, size))) {
                uvec4 m = texelFetch(uMaterial, p, 0);
                found |= (m.b > 0u || m.a >= 128u) ? 1u : 0u;
            }
        }
    }
    if (found != 0u) {
        atomicOr(sHasMaterial, 1u);
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u) {
        uint tile = gl_WorkGroupID.y * uint(uTilesX) + gl_WorkGroupID.x;
        if (sHasMaterial != 0u) {
            tiles[atomicAdd(occupiedArgs[2], 1u)] = tile;
        } else {
            tiles[uint(uTileCount) + atomicAdd(emptyArgs[2], 1u)] = tile;
        }
    }
}
