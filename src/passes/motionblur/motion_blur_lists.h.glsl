// Motion blur's two tile lists (the header mirrors photopic::GpuMotionTileLists). The neighbour-max step
// appends each tile to the moving list, where its neighbourhood's longest velocity may reach half a pixel,
// or to the still one; the gather runs over the moving tiles and a copy over the still ones, each an
// indirect dispatch of (work groups a tile side)^2 x the tiles listed. Include after
// motion_blur_common.h.glsl.
#ifndef PHOTOPIC_MOTION_BLUR_LISTS_H_GLSL
#define PHOTOPIC_MOTION_BLUR_LISTS_H_GLSL

#ifdef MOTION_BLUR_LISTS_WRITE
#define MOTION_BLUR_LISTS_ACCESS
#else
#define MOTION_BLUR_LISTS_ACCESS readonly
#endif
layout(std430, binding = BINDING_TILE_LIST) MOTION_BLUR_LISTS_ACCESS buffer MotionTileLists {
    uint movingArgs[3]; // glDispatchComputeIndirect
    uint stillArgs[3];
    uint listPad0;
    uint listPad1;
    uint listTiles[]; // [0, tiles): the moving tiles (y * tiles a row + x); [tiles, 2 tiles): the still ones
};

// A still tile's neighbourhood velocity is under this many pixels. Below the gather's half pixel by more
// than the RG16F neighbour-max texture's rounding, so a tile listed still is one whose pixels the gather
// would copy; the moving list's pixels still test the rounded value themselves.
const float kStillBelow = 0.49;

#endif
