// Shadow-map volumetric light, step 1: single scattering ray-marched along each view ray at half or quarter
// resolution. From the camera to the surface (the sky's rays to maxDistance), `samples` steps of equal length;
// each step's point is looked up in the sun's shadow map (a hardware depth comparison: visible or not), and
// the step adds albedo x illuminance x phase x visibility x the light the medium removes over the step,
// T(start) (1 - exp(-extinction x step)), so the sum over the steps integrates the transmittance exactly
// (Hillaire 2015, "Physically Based and Unified Volumetric Rendering in Frostbite") and only the visibility
// is sampled. The phase is Henyey-Greenstein's for the angle between the sun's light and the view ray, the
// same along a ray for a directional sun. The steps start at an interleaved-gradient-noise offset (Jimenez
// 2014) moved every frame along the golden-ratio sequence: the accumulation (step 2) averages the visibility
// of a shaft's edge over the whole step. Writes this texel's linear depth too, for the reprojection and the
// upsample.
#include "passes/volumetriclight/volumetric_shadow_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 2, r32f) uniform readonly image2D uDepth; // linear depth, full resolution, +inf: sky
layout(binding = 7) uniform sampler2DShadow uShadowMap;   // the host's depth, compared LEQUAL
layout(binding = 0, rgba16f) uniform writeonly image2D uOut;
layout(binding = 1, r32f) uniform writeonly image2D uLowDepth;

float interleavedGradientNoise(vec2 p) {
    return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715))));
}

// The shadow map's clip coordinates are affine along a view ray, c(t) = c0 + t cd, and the ray lies in the
// map where -w <= c.xyz <= w and w > 0: linear constraints on t, so the interval of t inside the map is found
// once per ray, and each step costs one multiply-add, a division and the lookup. Outside the interval the sun
// reaches the point (1).
struct ShadowRay {
    vec4 c0;
    vec4 cd;
    float lo; // t within [lo, hi] lies in the map
    float hi;
};

// Narrows [lo, hi] to the t where a + b t >= 0.
void keepNonNegative(float a, float b, inout float lo, inout float hi) {
    if (b > 0.0) {
        lo = max(lo, -a / b);
    } else if (b < 0.0) {
        hi = min(hi, -a / b);
    } else if (a < 0.0) {
        hi = -1.0;
        lo = 1.0;
    }
}

ShadowRay shadowRay(vec3 origin, vec3 dir, float rayLength) {
    ShadowRay r;
    r.c0 = uWorldToShadowClip * vec4(origin, 1.0);
    r.cd = uWorldToShadowClip * vec4(dir, 0.0);
    r.lo = 0.0;
    r.hi = rayLength;
    // w > 0 (within rounding: the points with w = 0 exactly are the limit, not lit by the map)
    keepNonNegative(r.c0.w, r.cd.w, r.lo, r.hi);
    for (int k = 0; k < 3; ++k) {
        keepNonNegative(r.c0.w + r.c0[k], r.cd.w + r.cd[k], r.lo, r.hi);
        keepNonNegative(r.c0.w - r.c0[k], r.cd.w - r.cd[k], r.lo, r.hi);
    }
    return r;
}

// 1 where the sun's light reaches the ray's point at t (or the point lies outside the map), 0 in a caster's
// shadow.
float sunVisibility(ShadowRay r, float t) {
    vec4 clip = r.c0 + t * r.cd;
    vec3 s = clip.xyz / clip.w * 0.5 + 0.5;
    // Outside the map's interval, or behind its eye: lit, and the lookup (made anyway: selects, not branches,
    // so a SIMD implementation pays no masks in the loop) reads a safe coordinate.
    bool inMap = t >= r.lo && t <= r.hi && clip.w > 0.0;
    // No depth bias: the points are in the air, not on a surface that could shadow itself. A bias would light
    // the air just under every occluder (measured: 13 cm of it under the test's roof doubled the light in
    // its shadow); without it only the last step in front of a lit surface can read its own texel.
    float lit = texture(uShadowMap, inMap ? s : vec3(0.5));
    return inMap ? lit : 1.0;
}

float henyeyGreenstein(float cosTheta, float g) {
    float d = max(1.0 + g * g - 2.0 * g * cosTheta, 1e-6);
    return (1.0 - g * g) / (4.0 * 3.14159265 * d * sqrt(d));
}

void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uOut);
    if (any(greaterThanEqual(q, size))) {
        return;
    }
    vec2 uv = (vec2(q) + 0.5) / uLowSize;
    ivec2 p = clamp(ivec2(uv * uFullSize), ivec2(0), ivec2(uFullSize) - 1);
    float z = imageLoad(uDepth, p).r;
    if (!validDepth(z)) {
        z = 0.0; // a broken depth: no march, and no surface the reprojection could match
    }
    imageStore(uLowDepth, q, vec4(z, 0.0, 0.0, 0.0));

    vec3 ray = viewRay(uv);
    float perDepth = length(ray); // scene units along the ray per unit of linear depth
    vec3 sum = vec3(0.0);
    if (z > 0.0 && perDepth > 0.0) {
        float rayLength = isSky(z) ? uMaxDistance : min(z * perDepth, uMaxDistance);
        vec3 dir = ray / perDepth;
        float n = float(uSamples);
        float stepLength = rayLength / n;
        float offset = fract(interleavedGradientNoise(vec2(q)) + 0.61803399 * float(uFrame));
        float stepLoss = 1.0 - exp(-uExtinction * stepLength); // the share of the light one step removes
        float stepTransmittance = 1.0 - stepLoss;
        float transmittance = 1.0;
        float visible = 0.0;
        ShadowRay shadow = shadowRay(cameraPosition(), dir, rayLength);
        for (int i = 0; i < uSamples; ++i) {
            visible += transmittance * sunVisibility(shadow, (float(i) + offset) * stepLength);
            transmittance *= stepTransmittance;
        }
        float phase = henyeyGreenstein(dot(dir, uToSun.xyz), uLight.w);
        sum = sanitizeLight(uLight.rgb * (phase * stepLoss * visible));
    }
    imageStore(uOut, q, vec4(sum, 1.0));
}
