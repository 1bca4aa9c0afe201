// Volumetric light, step 2: the radial march (Mitchell, "Volumetric Light Scattering as a Post-Process",
// GPU Gems 3 ch. 13). From each half-resolution texel, `samples` points on the segment towards the sun's
// projected position (density of the way there), each weighing decay^(64 t) at fraction t of the way; their
// mean of the occlusion source is the light scattered towards this pixel. Where an occluder lies between the
// pixel and the sun, its samples read 0 there, which cuts the ray. The start is dithered per texel
// (interleaved gradient noise, Jimenez 2014) and moved every frame along the golden-ratio sequence: the
// samples' steps would otherwise show as bands at the sun's distance, and the accumulation (step 3) averages
// the dither away.
#include "passes/volumetriclight/volumetric_light_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 2) uniform sampler2D uSource; // full resolution, bilinear, clamped to the edge
layout(binding = 0, rgba16f) uniform writeonly image2D uOut;

float interleavedGradientNoise(vec2 p) {
    return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715))));
}

void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uOut);
    if (any(greaterThanEqual(q, size))) {
        return;
    }
    vec3 sum = vec3(0.0);
    if (uActive != 0) {
        vec2 uv = (vec2(q) + 0.5) / uHalfSize;
        vec2 toSun = (uSunUv - uv) * uDensity;
        float offset = fract(interleavedGradientNoise(vec2(q)) + 0.61803399 * float(uFrame));
        float n = float(uSamples);
        for (int i = 0; i < uSamples; ++i) {
            float t = (float(i) + offset) / n;
            vec2 s = uv + t * toSun;
            // The segment starts on screen, so once it leaves the image it stays off it: nothing more to add.
            if (any(lessThan(s, vec2(0.0))) || any(greaterThan(s, vec2(1.0)))) {
                break;
            }
            sum += exp2(t * uLogDecay) * textureLod(uSource, s, 0.0).rgb;
        }
        sum = sanitizeLight(sum / n);
    }
    imageStore(uOut, q, vec4(sum, 1.0));
}
