// SMAA's tile lists (the header mirrors photopic::GpuSmaaTiles). Include after smaa_parameters.h.glsl.
// The weights step runs only on the 8 x 8 tiles the edge step found an edge in (the reference runs it under
// a stencil test the edge step set): the edge step flags a tile and appends it the first time one of its
// pixels has an edge. The blend step runs only where a weight can reach: on those tiles and the tiles left
// of and below them (whose pixels read their +x and +y neighbours' weights), which the weights step lists;
// every other pixel keeps its colour (the output starts as a copy of the input).
#ifndef PHOTOPIC_SMAA_TILES_H_GLSL
#define PHOTOPIC_SMAA_TILES_H_GLSL

#ifdef SMAA_TILES_WRITE
#define SMAA_TILES_ACCESS coherent
#else
#define SMAA_TILES_ACCESS readonly
#endif
layout(std430, binding = BINDING_TILE_LIST) SMAA_TILES_ACCESS buffer SmaaTiles {
    uint weightGroups[3]; // glDispatchComputeIndirect: (tiles with an edge, 1, 1)
    uint tilePad0;
    uint blendGroups[3]; // (tiles to blend, 1, 1)
    uint tilePad1;
    // Tile indices (y * uTilesX + x), uTileCount each: [0, n) the tiles with an edge, [n, 2n) the tiles to
    // blend, [2n, 3n) and [3n, 4n) their flags.
    uint tileData[];
};

// Lists `tile` (its index) in list `list` (0: edges, 1: blend) the first time it is asked for.
#ifdef SMAA_TILES_WRITE
void listTile(uint tile, int list) {
    uint n = uint(uTileCount);
    if (atomicOr(tileData[(2u + uint(list)) * n + tile], 1u) == 0u) {
        uint slot = list == 0 ? atomicAdd(weightGroups[0], 1u) : atomicAdd(blendGroups[0], 1u);
        tileData[uint(list) * n + slot] = tile;
    }
}
#endif

// The pixel of this invocation in the tile entry `entry` of list `list`.
ivec2 listedPixel(int list, uint entry) {
    uint tile = tileData[uint(list) * uint(uTileCount) + entry];
    return ivec2(int(tile % uint(uTilesX)), int(tile / uint(uTilesX))) * 8 + ivec2(gl_LocalInvocationID.xy);
}

#endif
