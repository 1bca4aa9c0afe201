// The display image's storage format for image stores: RGBA8, or RGBA16 (unorm) when the pipeline renders the
// display domain at 16 bits (output.bitDepth; passes/DisplayProgram.h builds the DISPLAY_16 variant).
#ifdef DISPLAY_16
#define DISPLAY_FORMAT rgba16
#else
#define DISPLAY_FORMAT rgba8
#endif
