// The exposure state every pass after metering reads (GPU-resident, so nothing waits on the CPU; written once
// per frame by the adaptation pass, passes/exposure/). Mirrors photopic::GpuExposureState
// (passes/Bindings.h), std430. The adaptation pass defines EXPOSURE_STATE_WRITABLE before including this and
// writes it as a storage buffer; every other reader gets it as a uniform block.
#ifndef PHOTOPIC_EXPOSURE_H_GLSL
#define PHOTOPIC_EXPOSURE_H_GLSL

// The members, in one list for the two declarations below:
// appliedLog2: auto exposure's own log2 multiplier; targetLog2: its target (last valid reading);
// meteredLuminance: last valid metered scene luminance; exposure: total multiplier applied to the frame,
// 2^(manualEV + appliedLog2); frameLuminance: this frame's own reading, 0 when none.
#define PHOTOPIC_EXPOSURE_MEMBERS \
    float appliedLog2; \
    float targetLog2; \
    float meteredLuminance; \
    float exposure; \
    int adapting; \
    int initialized; \
    float manualEV; \
    int autoEnabled; \
    float frameLuminance; \
    float minLuminance; \
    float maxLuminance; \
    uint histogramCount; \
    float histogramLowLog2; \
    float histogramHighLog2; \
    float histogramAverageLog2; \
    uint histogramPeak;

#ifdef EXPOSURE_STATE_WRITABLE
layout(std430, binding = BINDING_EXPOSURE_STATE) buffer ExposureStateBuffer {
    PHOTOPIC_EXPOSURE_MEMBERS
}
gExposure;
#else
// Readers see the same buffer as a uniform block (passes/Bindings.h kBindingExposureUniform): every member is a
// 4-byte scalar, so std140 gives the same offsets as std430.
layout(std140, binding = BINDING_EXPOSURE_UNIFORM) uniform ExposureStateBlock {
    PHOTOPIC_EXPOSURE_MEMBERS
}
gExposure;
#endif

#endif // PHOTOPIC_EXPOSURE_H_GLSL
