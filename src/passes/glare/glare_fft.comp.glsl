// One radix-2 FFT line (a row or a column of the padded spectrum) per workgroup, in shared memory: the
// lines are loaded into registers, each complex signal of a texel is transformed in turn (bit-reversed
// load, LOG2_SIZE Cooley-Tukey stages, one barrier each), and the texel is stored whole.
//
// The spectrum texel holds two complex numbers: (R + iG, B + i0). Packing two real channels into one complex
// signal is the real-to-complex saving: the kernel is real, so the real and imaginary parts of the product's
// inverse are the two channels' convolutions apart. Defines pick the line's source and target:
//   ROWS / (default) columns; INVERSE: the inverse transform (unscaled but for STORE_GLARE);
//   LOAD_SCENE: the exposed, sanitised scene (each pixel the mean of DIVISOR x DIVISOR scene texels), the
//     padding columns repeating the nearer edge; LOAD_KERNEL: the R32F kernel image (one signal);
//   MULTIPLY: multiply by the kernel's spectrum before the transform;
//   STORE_GLARE: the first uColumns texels of the row, scaled by uScale, to the glare image (rgba16f);
//   STORE_SPECTRUM: the first signal to the kernel spectrum (rg32f); else back to the spectrum (rgba32f).
// The forward column pass loads only the first uLoadRows texels (the rows the row pass wrote; the padding
// rows repeat the nearer edge row's transform) and the inverse stores only the first uStoreRows (the rows
// the image needs).
#include "passes/common/color.h.glsl"
#ifdef LOAD_SCENE
#include "passes/common/exposure.h.glsl"
#include "passes/common/sanitize.h.glsl"
#endif

layout(local_size_x = THREADS) in;

#define PER_THREAD (FFT_SIZE / THREADS)
#define BUTTERFLIES (FFT_SIZE / 2 / THREADS)

#if defined(LOAD_SCENE) || defined(LOAD_KERNEL)
layout(binding = UNIT_SOURCE) uniform sampler2D uSource;
#else
layout(binding = IMAGE_SPECTRUM, rgba32f) uniform readonly image2D uSpectrumIn;
#endif
#ifdef MULTIPLY
layout(binding = UNIT_KERNEL_SPECTRUM) uniform sampler2D uKernelSpectrum;
#endif
#if defined(STORE_GLARE)
layout(binding = IMAGE_TARGET, rgba16f) uniform writeonly image2D uGlare;
#elif defined(STORE_SPECTRUM)
layout(binding = IMAGE_TARGET, rg32f) uniform writeonly image2D uKernelOut;
#else
layout(binding = IMAGE_TARGET, rgba32f) uniform writeonly image2D uSpectrumOut;
#endif

// Mirrors photopic::GlareFftParameters (passes/glare/GlarePass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform GlareFftParameters {
    int uColumns;   // texels of a row that hold the image (the rest is the padding)
    int uLoadRows;  // rows a column pass loads (past them: the zero padding)
    int uStoreRows; // rows a column pass stores (the inverse stores only the image's)
    int uDivisor;   // scene texels per glare pixel side (LOAD_SCENE)
    float uScale;     // 1 / (width * height) of the padded spectrum (STORE_GLARE)
    float uHaloShare; // the halo's share s of the kernel: the glare image is s times the halo's convolution, alpha s
};

shared vec2 sLine[FFT_SIZE];

vec2 complexMultiply(vec2 a, vec2 b) {
    return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x);
}

ivec2 texelOf(int line, int i) {
#ifdef ROWS
    return ivec2(i, line);
#else
    return ivec2(line, i);
#endif
}

// The padding past the image's last column or row (`extent`) repeats the nearer edge of the image, the last
// one or, across the wrap-around, the first: what lies beyond the frame is taken to continue it.
int edgeExtended(int i, int extent) {
    return i < extent ? i : (i - extent < FFT_SIZE - i ? extent - 1 : 0);
}

vec4 loadTexel(int line, int i) {
#if defined(LOAD_SCENE)
    i = edgeExtended(i, uColumns);
    vec3 sum = vec3(0.0);
    ivec2 size = textureSize(uSource, 0);
    for (int y = 0; y < uDivisor; ++y)
        for (int x = 0; x < uDivisor; ++x)
            sum += sanitize(texelFetch(uSource, min(ivec2(i, line) * uDivisor + ivec2(x, y), size - 1), 0).rgb);
    vec3 c = sum * (gExposure.exposure / float(uDivisor * uDivisor));
    return vec4(c.r, c.g, c.b, 0.0);
#elif defined(LOAD_KERNEL)
    return vec4(texelFetch(uSource, texelOf(line, i), 0).r, 0.0, 0.0, 0.0);
#else
#ifndef ROWS
    i = edgeExtended(i, uLoadRows); // the row transform of a repeated row is that row's
#endif
    ivec2 t = texelOf(line, i);
    vec4 v = imageLoad(uSpectrumIn, t);
#ifdef MULTIPLY
    vec2 k = texelFetch(uKernelSpectrum, t, 0).rg;
    v = vec4(complexMultiply(v.xy, k), complexMultiply(v.zw, k));
#endif
    return v;
#endif
}

// The transform of what sLine holds (in bit-reversed order) in place.
void transformShared(uint thread) {
#ifdef INVERSE
    const float direction = 1.0;
#else
    const float direction = -1.0;
#endif
    for (int stage = 1; stage <= LOG2_SIZE; ++stage) {
        int span = 1 << (stage - 1);
        for (int b = 0; b < BUTTERFLIES; ++b) {
            int butterfly = int(thread) + b * THREADS;
            int position = butterfly & (span - 1);
            int i0 = ((butterfly >> (stage - 1)) << stage) + position;
            int i1 = i0 + span;
            float angle = direction * 3.14159265358979 * float(position) / float(span);
            vec2 t = complexMultiply(vec2(cos(angle), sin(angle)), sLine[i1]);
            vec2 a = sLine[i0];
            sLine[i0] = a + t;
            sLine[i1] = a - t;
        }
        barrier();
    }
}

void main() {
    int line = int(gl_WorkGroupID.x);
    uint thread = gl_LocalInvocationID.x;
    vec4 v[PER_THREAD];
    for (int k = 0; k < PER_THREAD; ++k)
        v[k] = loadTexel(line, int(thread) + k * THREADS);
#if defined(LOAD_KERNEL) || defined(STORE_SPECTRUM)
    const int signals = 1;
#else
    const int signals = 2;
#endif
    for (int s = 0; s < signals; ++s) {
        for (int k = 0; k < PER_THREAD; ++k) {
            uint i = thread + uint(k * THREADS);
            sLine[bitfieldReverse(i) >> (32 - LOG2_SIZE)] = s == 0 ? v[k].xy : v[k].zw;
        }
        barrier();
        transformShared(thread);
        for (int k = 0; k < PER_THREAD; ++k) {
            vec2 c = sLine[int(thread) + k * THREADS];
            if (s == 0)
                v[k].xy = c;
            else
                v[k].zw = c;
        }
        barrier(); // the next signal overwrites sLine
    }
    for (int k = 0; k < PER_THREAD; ++k) {
        int i = int(thread) + k * THREADS;
#if defined(STORE_GLARE)
        // Each channel's convolution: R and G are the first signal's real and imaginary parts, B the second's
        // real part.
        if (i < uColumns)
            imageStore(uGlare, ivec2(i, line), vec4(v[k].xyz * (uScale * uHaloShare), uHaloShare));
#elif defined(STORE_SPECTRUM)
        imageStore(uKernelOut, texelOf(line, i), vec4(v[k].xy, 0.0, 0.0));
#else
#ifndef ROWS
        if (i >= uStoreRows)
            continue;
#endif
        imageStore(uSpectrumOut, texelOf(line, i), v[k]);
#endif
    }
}
