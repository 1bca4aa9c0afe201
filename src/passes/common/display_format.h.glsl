// The display image's storage format for image stores: RGBA8, or RGBA16 (unorm) when the pipeline renders the
// display domain at 16 bits (output.bitDepth; passes/DisplayProgram.h builds the DISPLAY_16 variant).
#ifdef DISPLAY_16
#define DISPLAY_FORMAT rgba16
#else
#define DISPLAY_FORMAT rgba8
#endif

// The display image's largest code value.
#ifdef DISPLAY_16
const float kDisplayCodes = 65535.0;
#else
const float kDisplayCodes = 255.0;
#endif

// A display value in [0, 1] (clamped here) put on its nearest code, ties to even, before the image store
// (DISPLAY_ROUNDING, on GPUs: passes/DisplayProgram.h displayStoresRound). The store's own conversion to
// unorm may round a value within a tenth of a code of the midpoint either way (GL lets it take either
// neighbour; D3D's rules allow 0.6 of a code step), and GPUs were seen to send a dithered grey to the code
// below more often than to the code above, where round to nearest sends it to each equally. On its code already, the value
// converts to that code on any device. A software renderer's store rounds to nearest even itself: the same
// bits without it.
#ifdef DISPLAY_ROUNDING
vec3 onDisplayCode(vec3 v) {
    return roundEven(clamp(v, 0.0, 1.0) * kDisplayCodes) * (1.0 / kDisplayCodes);
}
#else
vec3 onDisplayCode(vec3 v) {
    return clamp(v, 0.0, 1.0);
}
#endif
