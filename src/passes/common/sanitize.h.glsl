// Sanitising scene input (where the pipeline first reads it): NaN, +-Inf and negative values become 0, and
// values are clamped below the half-float maximum (65504) so RGBA16F targets never hold Inf. Finite-ness is
// tested on the bit pattern, which no compiler may optimise away (isnan/isinf can be folded under relaxed
// float rules).
const float kSanitizeMax = 65000.0;

float sanitizeValue(float x) {
    bool finite = (floatBitsToUint(x) & 0x7f800000u) != 0x7f800000u;
    return finite ? clamp(x, 0.0, kSanitizeMax) : 0.0;
}

vec3 sanitize(vec3 c) { return vec3(sanitizeValue(c.r), sanitizeValue(c.g), sanitizeValue(c.b)); }
