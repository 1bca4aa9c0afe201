// Colour helpers shared by the shaders; mirror of src/core/Color.h/.cpp (no #version: included after it).
// References: IEC 61966-2-1:1999 (sRGB transfer function), ITU-R BT.709-6 (luma weights).
#ifndef PHOTOPIC_COLOR_H_GLSL
#define PHOTOPIC_COLOR_H_GLSL

// Rec.709 relative luminance of linear Rec.709 RGB.
float luma709(vec3 linearRgb) {
    return 0.2126 * linearRgb.r + 0.7152 * linearRgb.g + 0.0722 * linearRgb.b;
}

// The power segment of the sRGB OETF, 1.055 x^(1/2.4) - 0.055, for x in [0.0031308, 1]: a polynomial of
// degree 8 in u = x^(1/4) (two square roots), fitted at the Chebyshev nodes of u's range [0.23654, 1] and
// evaluated on t, that range mapped onto [-1, 1]. Largest error 1.7e-7 in float (the 16-bit display's step
// is 1.5e-5). A software renderer pays far less for it than for pow(), which llvmpipe builds from a log2
// with a division and an exp2: the encode of three channels took 58 instructions a pixel that way, 23 this
// way. Below the break point the value is unused.
vec3 srgbEncodePower(vec3 x) {
    vec3 t = sqrt(sqrt(x)) * 2.61966991 - 1.61966991;
    return (((((((3.64824555e-05 * t - 8.46880503e-05) * t + 0.000127711988) * t - 0.000381717575) * t +
              0.00141894119) * t - 0.00688499445) * t + 0.100251831) * t + 0.487126529) * t + 0.418389946;
}

// sRGB OETF (linear -> encoded), input clamped to [0, 1] first.
vec3 srgbEncode(vec3 linear) {
    vec3 x = clamp(linear, 0.0, 1.0);
    return mix(srgbEncodePower(x), 12.92 * x, lessThanEqual(x, vec3(0.0031308)));
}

float srgbEncode(float linear) {
    return srgbEncode(vec3(linear)).x;
}

// sRGB EOTF (encoded -> linear); no clamp, values below the break point follow the linear segment.
float srgbDecode(float encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : pow((encoded + 0.055) / 1.055, 2.4);
}

vec3 srgbDecode(vec3 encoded) {
    // max() keeps the unused branch's pow() base non-negative (pow of a negative base is undefined in GLSL).
    vec3 power = pow(max((encoded + 0.055) / 1.055, vec3(0.0)), vec3(2.4));
    return mix(power, encoded / 12.92, lessThanEqual(encoded, vec3(0.04045)));
}

#endif // PHOTOPIC_COLOR_H_GLSL
