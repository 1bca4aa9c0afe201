// SMAA's tile list (SmaaPass::Tiles; the header mirrors photopic::GpuSmaaTilesHeader). Include after
// smaa_parameters.h.glsl.
// The 8 x 8 tiles the edge step found an edge in: the weights step runs on those only (the reference runs
// it under a stencil test that the edge step set). The edge step flags a tile and appends it the first time
// one of its pixels has an edge; the list's length is the weights step's indirect dispatch.
#ifdef SMAA_TILES_WRITE
#define SMAA_TILES_ACCESS coherent
#else
#define SMAA_TILES_ACCESS readonly
#endif
layout(std430, binding = BINDING_TILE_LIST) SMAA_TILES_ACCESS buffer SmaaTiles {
    uint tileGroups[3]; // glDispatchComputeIndirect: (tiles listed, 1, 1)
    uint tilePad;
    uint tileData[]; // [0, uTileCount): the listed tiles' indices (y * uTilesX + x); then one flag a tile
};
