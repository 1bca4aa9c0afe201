// Volumetric light, step 3: temporal accumulation of the dithered march at half resolution. This frame's
// value (a 3x3 tent over the march) is blended with last frame's accumulated value where this texel's point
// was (motion vectors: the rays move with the sun, which moves with the camera's rotation like the sky
// does), the history clamped to the 3x3 neighbourhood of this frame's values first (Karis 2014, "High
// Quality Temporal Supersampling"), so a ray that moved or an occluder that passed leaves no trail. Without
// it the dither, and the sun's rasterised disc gaining and losing pixels from frame to frame on a slow pan
// (+-7% of its light at 160x90), would make the rays pump.
#include "passes/volumetriclight/volumetric_light_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 3) uniform sampler2D uRaw;     // this frame's march (nearest)
layout(binding = 4) uniform sampler2D uHistory; // last frame's accumulated light (bilinear)
layout(binding = 5) uniform sampler2D uMotion;  // UV, current - previous, full resolution, when uHasMotion
layout(binding = 0, rgba16f) uniform writeonly image2D uOut;

bool finite2(vec2 v) { return !any(isnan(v)) && !any(isinf(v)); }

// Where this texel's point was in last frame's image (UV); false when unknown or off screen.
bool previousUv(ivec2 q, out vec2 prevUv) {
    vec2 uv = (vec2(q) + 0.5) / uHalfSize;
    prevUv = uv;
    if (uHasMotion != 0) {
        ivec2 p = clamp(ivec2(uv * uFullSize), ivec2(0), ivec2(uFullSize) - 1);
        vec2 motion = texelFetch(uMotion, p, 0).rg;
        if (!finite2(motion)) {
            return false;
        }
        prevUv = uv - motion;
    }
    return finite2(prevUv) && all(greaterThanEqual(prevUv, vec2(0.0))) && all(lessThanEqual(prevUv, vec2(1.0)));
}

// This frame's values over the work group and a one-texel border, for the 3x3 neighbourhood boxes.
shared vec3 sRaw[10][10];

void loadTile(ivec2 size) {
    ivec2 origin = ivec2(gl_WorkGroupID.xy) * 8 - 1;
    for (uint i = gl_LocalInvocationIndex; i < 100u; i += 64u) {
        ivec2 q = clamp(origin + ivec2(int(i % 10u), int(i / 10u)), ivec2(0), size - 1);
        sRaw[i / 10u][i % 10u] = texelFetch(uRaw, q, 0).rgb;
    }
    barrier();
}

void main() {
    ivec2 size = ivec2(uHalfSize);
    loadTile(size);
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(q, size))) {
        return;
    }
    ivec2 l = ivec2(gl_LocalInvocationID.xy) + 1;
    // This frame's value: a 3x3 tent over the march. Neighbouring texels start their samples at offsets
    // spread over [0, 1) (interleaved gradient noise is made to be averaged over 3x3), so the tent removes
    // part of the dither within the frame, leaving the accumulation less to average. It softens a shaft's
    // edge by one half-resolution texel.
    vec3 current = vec3(0.0);
    vec3 lo = sRaw[l.y][l.x];
    vec3 hi = lo;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            vec3 v = sRaw[l.y + dy][l.x + dx];
            current += float((2 - abs(dx)) * (2 - abs(dy))) * v;
            lo = min(lo, v);
            hi = max(hi, v);
        }
    }
    current *= 1.0 / 16.0;
    vec3 result = current;
    vec2 prevUv;
    if (uActive != 0 && uHasHistory != 0 && previousUv(q, prevUv)) {
        vec3 history = textureLod(uHistory, prevUv, 0.0).rgb;
        if (all(greaterThanEqual(history, vec3(0.0))) && all(lessThanEqual(history, vec3(kHalfMax)))) {
            result = mix(current, clamp(history, lo, hi), uHistoryWeight); // NaN fails the test above
        }
    }
    imageStore(uOut, q, vec4(sanitizeLight(result), 1.0));
}
