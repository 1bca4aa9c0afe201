// The group shape of a pixel pass that lets the host choose it (gl/ShaderLibrary.h pixelGroup): 8x8
// invocations, or with PIXEL_GROUP_ROW one row of 64, which a software renderer (eight lanes along x) runs
// faster. The pass must not depend on the shape: one pixel (or block) per invocation by its global id.
#ifdef PIXEL_GROUP_ROW
layout(local_size_x = 64, local_size_y = 1) in;
#else
layout(local_size_x = 8, local_size_y = 8) in;
#endif
