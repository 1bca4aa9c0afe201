// Shadow-map volumetric light, step 2: temporal accumulation at the march's resolution. This frame's value
// is a 3x3 tent over the march taken over the texels of the same surface (depth within 5%), so it removes
// part of the dither without smearing light across a depth edge. Last frame's accumulated light is fetched
// where this texel's point was: the point at its depth (the sky's at maxDistance) seen through last frame's
// view-projection, the camera's motion from depth. Each of the four bilinear history taps counts only where
// last frame's depth there is the depth this point had then (the sky matches the sky), so history from
// another surface (a disocclusion) is rejected; with no tap left the texel starts over. The history is
// clamped to this frame's 3x3 range (Karis 2014) so a shadow that moved leaves no trail. A cut, a resize or
// a reset starts every texel over.
#include "passes/volumetriclight/volumetric_shadow_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1, rgba16f) uniform readonly image2D uRaw;          // this frame's march
layout(binding = 2, rgba16f) uniform readonly image2D uHistory;      // last frame's accumulated light
layout(binding = 3, r32f) uniform readonly image2D uLowDepth;     // this frame's march depths
layout(binding = 4, r32f) uniform readonly image2D uPrevLowDepth; // last frame's march depths
layout(binding = 0, rgba16f) uniform writeonly image2D uOut;

shared vec3 sRaw[10][10];
shared float sDepth[10][10];

void loadTile(ivec2 size) {
    ivec2 origin = ivec2(gl_WorkGroupID.xy) * 8 - 1;
    for (uint i = gl_LocalInvocationIndex; i < 100u; i += 64u) {
        ivec2 q = clamp(origin + ivec2(int(i % 10u), int(i / 10u)), ivec2(0), size - 1);
        sRaw[i / 10u][i % 10u] = imageLoad(uRaw, q).rgb;
        sDepth[i / 10u][i % 10u] = imageLoad(uLowDepth, q).r;
    }
    barrier();
}

bool finite4(vec4 v) { return !any(isnan(v)) && !any(isinf(v)); }

// Last frame's accumulated light at this texel's point, from the taps whose depth matches; false if none.
bool reprojectedHistory(ivec2 q, float z, out vec3 history) {
    history = vec3(0.0);
    if (!(z > 0.0)) {
        return false;
    }
    vec2 uv = (vec2(q) + 0.5) / uLowSize;
    vec3 ray = viewRay(uv);
    float perDepth = length(ray);
    if (!(perDepth > 0.0)) {
        return false;
    }
    bool sky = isSky(z);
    float depth = sky ? uMaxDistance / perDepth : min(z, uMaxDistance / perDepth);
    vec4 prev = uPrevViewProjection * vec4(cameraPosition() + ray * depth, 1.0);
    if (!finite4(prev) || !(prev.w > 0.0)) {
        return false;
    }
    vec2 prevUv = prev.xy / prev.w * 0.5 + 0.5;
    if (any(lessThan(prevUv, vec2(0.0))) || any(greaterThan(prevUv, vec2(1.0)))) {
        return false;
    }
    // Last frame's linear depth of this point: its clip w (GL perspective), the sky's +inf.
    float expected = sky ? uintBitsToFloat(0x7f800000u) : prev.w;
    vec2 f = prevUv * uLowSize - 0.5;
    ivec2 base = ivec2(floor(f));
    vec2 t = f - vec2(base);
    ivec2 size = ivec2(uLowSize);
    float total = 0.0;
    for (int i = 0; i < 4; ++i) {
        ivec2 o = ivec2(i & 1, i >> 1);
        ivec2 tap = clamp(base + o, ivec2(0), size - 1);
        float w = (o.x == 1 ? t.x : 1.0 - t.x) * (o.y == 1 ? t.y : 1.0 - t.y);
        float d = imageLoad(uPrevLowDepth, tap).r;
        if (w > 0.0 && validDepth(d) && sameSurface(d, expected)) {
            history += w * imageLoad(uHistory, tap).rgb;
            total += w;
        }
    }
    if (!(total > 0.05)) {
        return false;
    }
    history /= total;
    return all(greaterThanEqual(history, vec3(0.0))) && all(lessThanEqual(history, vec3(kHalfMax)));
}

void main() {
    ivec2 size = ivec2(uLowSize);
    loadTile(size);
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(q, size))) {
        return;
    }
    ivec2 l = ivec2(gl_LocalInvocationID.xy) + 1;
    float z = sDepth[l.y][l.x];
    vec3 current = vec3(0.0);
    float weights = 0.0;
    vec3 lo = sRaw[l.y][l.x];
    vec3 hi = lo;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            float d = sDepth[l.y + dy][l.x + dx];
            if (!sameSurface(d, z)) {
                continue;
            }
            vec3 v = sRaw[l.y + dy][l.x + dx];
            float w = float((2 - abs(dx)) * (2 - abs(dy)));
            current += w * v;
            weights += w;
            lo = min(lo, v);
            hi = max(hi, v);
        }
    }
    current = weights > 0.0 ? current / weights : sRaw[l.y][l.x];
    vec3 result = current;
    vec3 history;
    if (uHasHistory != 0 && reprojectedHistory(q, z, history)) {
        result = mix(current, clamp(history, lo, hi), uHistoryWeight);
    }
    imageStore(uOut, q, vec4(sanitizeLight(result), 1.0));
}
