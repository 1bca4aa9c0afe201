// Colour helpers shared by the shaders; mirror of src/core/Color.h/.cpp (no #version: included after it).
// References: IEC 61966-2-1:1999 (sRGB transfer function), ITU-R BT.709-6 (luma weights).
#ifndef PHOTOPIC_COLOR_H_GLSL
#define PHOTOPIC_COLOR_H_GLSL

// Rec.709 relative luminance of linear Rec.709 RGB.
float luma709(vec3 linearRgb) {
    return 0.2126 * linearRgb.r + 0.7152 * linearRgb.g + 0.0722 * linearRgb.b;
}

// sRGB OETF (linear -> encoded), input clamped to [0, 1] first.
float srgbEncode(float linear) {
    float x = clamp(linear, 0.0, 1.0);
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

vec3 srgbEncode(vec3 linear) {
    vec3 x = clamp(linear, 0.0, 1.0);
    // pow(0, y) with y > 0 is defined (0), so the unused branch is safe to evaluate.
    return mix(1.055 * pow(x, vec3(1.0 / 2.4)) - 0.055, 12.92 * x, lessThanEqual(x, vec3(0.0031308)));
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
