// The exposure state every pass after metering reads (GPU-resident, so nothing waits on the CPU; written once
// per frame by the adaptation pass, passes/exposure/). Mirrors photopic::GpuExposureState
// (passes/Bindings.h), std430. The adaptation pass defines EXPOSURE_STATE_WRITABLE before including this;
// every other reader gets it readonly.
#ifndef PHOTOPIC_EXPOSURE_H_GLSL
#define PHOTOPIC_EXPOSURE_H_GLSL

#ifdef EXPOSURE_STATE_WRITABLE
#define PHOTOPIC_EXPOSURE_ACCESS
#else
#define PHOTOPIC_EXPOSURE_ACCESS readonly
#endif

layout(std430, binding = BINDING_EXPOSURE_STATE) PHOTOPIC_EXPOSURE_ACCESS buffer ExposureStateBuffer {
    float appliedLog2;      // auto exposure's own log2 multiplier
    float targetLog2;       // auto exposure's target log2 multiplier (last valid reading)
    float meteredLuminance; // last valid metered scene luminance
    float exposure;         // total multiplier applied to the frame: 2^(manualEV + appliedLog2)
    int adapting;
    int initialized;
    float manualEV;
    int autoEnabled;
    float frameLuminance;   // this frame's own reading, 0 when none
    float minLuminance;
    float maxLuminance;
    uint histogramCount;
    float histogramLowLog2;
    float histogramHighLog2;
    float histogramAverageLog2;
    uint histogramPeak;
}
gExposure;

#endif // PHOTOPIC_EXPOSURE_H_GLSL
