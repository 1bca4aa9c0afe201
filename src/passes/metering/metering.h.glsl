// Metering conventions shared by the metering, adaptation and debug shaders; a line-for-line mirror of
// core/Metering.{h,cpp} (the CPU source of truth, which states each formula).
// References: A. Tardif, "Automatic Exposure Using a Luminance Histogram" (2019) for the binning;
// ITU-R BT.709-6 for the luma weights (passes/common/color.h.glsl).
#ifndef PHOTOPIC_METERING_H_GLSL
#define PHOTOPIC_METERING_H_GLSL

#include "passes/common/color.h.glsl"

const int kHistogramBins = 256;
const float kHistogramRangeBins = 254.0;
const float kCenterFalloff = 8.0;

// Metering modes, in core's MeteringMode order.
const int kMeterAverage = 0;
const int kMeterHistogram = 1;
const int kMeterSpot = 2;
const int kMeterCenter = 3;
const int kMeterMask = 4;
const int kMeterSubject = 5; // the probe pass (passes/probe/) writes gReading

// core: kSpotTaps (x right, y down, in spot radii).
const vec2 kSpotTaps[13] = vec2[](vec2(0.0, 0.0), vec2(0.5, 0.0), vec2(-0.5, 0.0), vec2(0.0, 0.5), vec2(0.0, -0.5),
                                  vec2(0.5, 0.5), vec2(-0.5, 0.5), vec2(0.5, -0.5), vec2(-0.5, -0.5), vec2(1.0, 0.0),
                                  vec2(-1.0, 0.0), vec2(0.0, 1.0), vec2(0.0, -1.0));

// core: isMeterableLuminance, L in [FLT_MIN, FLT_MAX]. On the bit pattern: a clear sign bit and a biased exponent
// in 1..254 is exactly a positive, normal, finite float (NaN, inf, zero, denormals and negatives fail), and no
// compiler may fold it away as it may isnan() under relaxed float rules.
bool isMeterable(float luminance) {
    uint e = floatBitsToUint(luminance) >> 23;
    return e >= 1u && e <= 254u;
}

// Finite (any sign): the exponent is not all ones.
bool isFiniteBits(float x) {
    return (floatBitsToUint(x) & 0x7f800000u) != 0x7f800000u;
}

// core: histogramBin. -1 for non-finite, 0 for underflow (L < 2^log2Min, L <= 0, denormal).
int histogramBin(float luminance, float log2Min, float log2Max) {
    if (!isFiniteBits(luminance)) {
        return -1;
    }
    if (!isMeterable(luminance)) {
        return 0;
    }
    float lg = log2(luminance);
    if (lg < log2Min) {
        return 0;
    }
    float t = min((lg - log2Min) / (log2Max - log2Min), 1.0);
    return int(1.0 + kHistogramRangeBins * t);
}

// x * y exactly, as the float nearest to it (hi) and the rest (lo): Dekker's product, each factor split into
// halves of 12 significant bits (Veltkamp's split) whose partial products floats hold exactly. `precise`
// keeps a compiler from fusing or reordering the steps, which would undo them. For |x|, |y| < 2^100.
void exactProduct(float x, float y, out float hi, out float lo) {
    precise float cx = 4097.0 * x;
    precise float xh = cx - (cx - x);
    precise float xl = x - xh;
    precise float cy = 4097.0 * y;
    precise float yh = cy - (cy - y);
    precise float yl = y - yh;
    precise float p = x * y;
    precise float rest = ((xh * yh - p) + xh * yl + xl * yh) + xl * yl;
    hi = p;
    lo = rest;
}

// a / b rounded to the nearest float, as the CPU divides. GLSL lets a division be 2.5 ulp off (GPUs multiply
// by a reciprocal, and a compiler may do so for a constant divisor). The remainder a - q b, exact from
// Dekker's product (no fma, which a software renderer may run as a multiply and an add), moves the quotient
// to the rounded one; a quotient that already is stays (its remainder is under half an ulp of it).
float divideRounded(float a, float b) {
    precise float q = a / b;
    float p;
    float e;
    exactProduct(q, b, p, e);
    precise float r = (a - p) - e;
    precise float rounded = q + r / b;
    return rounded;
}

// core: histogramBinCentreLog2. `precise`: a compiler may otherwise fuse the multiply and add into one fma
// (NVIDIA's does), which rounds once where the CPU rounds twice.
float histogramBinCentreLog2(int bin, float log2Min, float log2Max) {
    precise float binWidth = divideRounded(log2Max - log2Min, kHistogramRangeBins);
    precise float centre = log2Min + (float(bin) - 0.5) * binWidth;
    return centre;
}

// Image coordinates of texel p of a texture uploaded bottom-up (gl/TextureIo.h): image row y = H - 1 - p.y, so
// image v runs down from the top as in core.
ivec2 imagePixel(ivec2 texel, ivec2 size) {
    return ivec2(texel.x, size.y - 1 - texel.y);
}
ivec2 texelOfImagePixel(ivec2 pixel, ivec2 size) {
    return ivec2(pixel.x, size.y - 1 - pixel.y);
}

// core: pixelU, the image UV of a pixel centre.
vec2 imageUv(ivec2 pixel, ivec2 size) {
    return vec2((float(pixel.x) + 0.5) / float(size.x), (float(pixel.y) + 0.5) / float(size.y));
}

// core: centerWeight.
float centerWeight(vec2 uv, float aspect) {
    float dx = (uv.x - 0.5) * aspect;
    float dy = uv.y - 0.5;
    return exp(-kCenterFalloff * (dx * dx + dy * dy));
}

// core: spotWeight (the debug view's disc; the reading uses the taps).
float spotWeight(vec2 uv, vec2 spotUv, float radius, float aspect) {
    float dx = (uv.x - spotUv.x) * aspect;
    float dy = uv.y - spotUv.y;
    return dx * dx + dy * dy <= radius * radius ? 1.0 : 0.0;
}

// core: spotTapTexel, as an image pixel (x right, y down).
ivec2 spotTapPixel(vec2 spotUv, float radius, int tap, ivec2 size) {
    vec2 offset = kSpotTaps[clamp(tap, 0, 12)];
    float radiusPixels = radius * float(size.y);
    float px = spotUv.x * float(size.x) + offset.x * radiusPixels;
    float py = spotUv.y * float(size.y) + offset.y * radiusPixels;
    return ivec2(clamp(int(floor(px)), 0, size.x - 1), clamp(int(floor(py)), 0, size.y - 1));
}

// core: meterMasked's weight, the mask's Rec.709 luma sampled nearest at the image UV; non-finite or negative -> 0.
float maskWeight(sampler2D mask, vec2 uv) {
    ivec2 maskSize = textureSize(mask, 0);
    int mx = clamp(int(floor(uv.x * float(maskSize.x))), 0, maskSize.x - 1);
    int my = clamp(int(floor(uv.y * float(maskSize.y))), 0, maskSize.y - 1);
    float w = luma709(texelFetch(mask, texelOfImagePixel(ivec2(mx, my), maskSize), 0).rgb);
    return isFiniteBits(w) && w > 0.0 ? w : 0.0;
}

// The weight of a meterable pixel `p` of an image of `size` in the weighted mode `weights` (kMeterAverage,
// kMeterCenter or kMeterMask), the mask read from `mask` (core/Metering.h).
float pixelWeight(int weights, ivec2 p, ivec2 size, sampler2D mask) {
    vec2 uv = imageUv(imagePixel(p, size), size);
    if (weights == kMeterCenter) {
        return centerWeight(uv, float(size.x) / float(size.y));
    }
    if (weights == kMeterMask) {
        return maskWeight(mask, uv);
    }
    return 1.0;
}

#endif // PHOTOPIC_METERING_H_GLSL
