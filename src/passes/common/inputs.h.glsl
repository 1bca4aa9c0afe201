// Decoding the host's 3D inputs (docs/architecture.md, "Inputs"): depth kinds, normal encodings, motion units.
#ifndef PHOTOPIC_INPUTS_H_GLSL
#define PHOTOPIC_INPUTS_H_GLSL

const int kDepthStandard = 0;
const int kDepthReversed = 1;
const int kDepthLinearView = 2;

float infinity() { return uintBitsToFloat(0x7F800000u); }

// Positive view depth in scene units from a depth texel; the sky (far plane or beyond) is +inf.
float linearViewDepth(float d, int kind, float near, float far) {
    if (kind == kDepthLinearView) {
        return d >= far ? infinity() : d;
    }
    if (kind == kDepthReversed) {
        // d = n (f - z) / (z (f - n)), or n / z for an infinite far plane.
        if (d <= 0.0) {
            return infinity();
        }
        return isinf(far) ? near / d : near * far / (d * (far - near) + near);
    }
    // Standard GL window depth: ndc = 2d - 1.
    if (d >= 1.0) {
        return infinity();
    }
    float ndc = 2.0 * d - 1.0;
    return isinf(far) ? 2.0 * near / (1.0 - ndc) : 2.0 * near * far / (far + near - ndc * (far - near));
}

// Octahedral normal encoding (Cigolle et al. 2014, "A Survey of Efficient Representations for Independent
// Unit Vectors"): [-1, 1]^2 -> unit vector.
vec3 octahedralDecode(vec2 e) {
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    if (n.z < 0.0) {
        n.xy = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
    }
    return normalize(n);
}

// Motion is UV displacement (current - previous, y up); in pixels of a `size` target.
vec2 motionUvToPixels(vec2 motion, ivec2 size) { return motion * vec2(size); }

#endif
