// The composite's tile list (the header mirrors photopic::GpuDofTileList): the 8x8 tiles of the image that
// the composite changes, appended by dof_changed_tiles.comp.glsl; the composite runs over them as an indirect
// dispatch of one work group a tile, over an image copy of the sharp colour. Where most tiles change, the
// list's last writer hands the frame to the composite over every pixel instead (fullArgs). Include after
// dof_common.h.glsl.
#ifndef PHOTOPIC_DOF_CHANGED_TILES_H_GLSL
#define PHOTOPIC_DOF_CHANGED_TILES_H_GLSL

#ifdef DOF_TILES_WRITE
#define DOF_TILES_ACCESS
#else
#define DOF_TILES_ACCESS readonly
#endif
layout(std430, binding = BINDING_TILE_LIST) DOF_TILES_ACCESS buffer DofChangedTiles {
    uint changedArgs[3]; // glDispatchComputeIndirect: 1, 1, the tiles listed (0 where fullArgs runs)
    uint tilesDone;      // tiles classified so far
    uint fullArgs[3];    // the composite over every pixel: its work groups, z 1 where it runs, else 0
    uint listPad;
    uint changedTiles[]; // y * tiles a row + x
};

// Full-resolution pixels per side of a composite tile: one work group of the composite.
const int kCompositeTile = 8;

// Composite tiles per row and column.
ivec2 compositeTileCount() { return (ivec2(uFullSize) + kCompositeTile - 1) / kCompositeTile; }

#endif
