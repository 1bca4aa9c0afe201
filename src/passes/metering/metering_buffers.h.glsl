// The metering storage buffers. Mirrors GpuMeteringHeader (passes/Bindings.h), std430.
#ifndef PHOTOPIC_METERING_BUFFERS_H_GLSL
#define PHOTOPIC_METERING_BUFFERS_H_GLSL

layout(std430, binding = BINDING_HISTOGRAM) buffer HistogramBuffer {
    uint gBins[256]; // bin 0 underflow, 255 overflow (core/Metering.h)
};

layout(std430, binding = BINDING_METERING) buffer MeteringBuffer {
    uint gMinBits;   // bits of the smallest meterable L; positive floats order as their bit patterns
    uint gMaxBits;   // bits of the largest meterable L; 0: none this frame
    uint gGroups;
    uint gMeterPad0;
    float gReading;  // weighted geometric mean (reduce dispatch), 0: no reading
    float gWeightSum;
    float gMeterPad1;
    float gMeterPad2;
    vec2 gPartials[]; // per workgroup: (sum of w log2 L, sum of w)
};

#endif // PHOTOPIC_METERING_BUFFERS_H_GLSL
