// The exposure state every pass after metering reads (DESIGN.md: GPU-resident, written by the adaptation pass or,
// with auto exposure off, by the CPU). Mirrors photopic::GpuExposureState (passes/Bindings.h), std430.
layout(std430, binding = BINDING_EXPOSURE_STATE) readonly buffer ExposureStateBuffer {
    float appliedLog2;      // auto exposure's own log2 multiplier (0 when off)
    float targetLog2;       // auto exposure's target log2 multiplier
    float meteredLuminance; // metered scene luminance of the frame
    float exposure;         // total multiplier applied to the frame: 2^(manualEV + appliedLog2)
    int adapting;
    int initialized;
    float manualEV;
    float pad0;
}
gExposure;
