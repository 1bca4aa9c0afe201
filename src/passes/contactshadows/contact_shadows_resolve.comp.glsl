// Temporal accumulation of the contact-shadow march: this frame's visibility blended with last frame's
// accumulated value at the same surface point (motion vectors, or the camera's reprojection), the history
// clamped to the 3x3 neighbourhood of this frame's values first (Karis 2014, "High Quality Temporal
// Supersampling"), so a moving shadow or a disocclusion does not leave a trail. The march's start offset
// moves every frame, so the accumulation averages over offsets and the dithering does not show.
#include "passes/contactshadows/contact_shadows_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1, r32f) uniform readonly image2D uLinearDepth; // +inf: sky
layout(binding = 2, r16f) uniform readonly image2D uRaw;         // this frame's visibility
layout(binding = 4) uniform sampler2D uHistory;     // last frame's accumulated visibility (bilinear)
layout(binding = 5) uniform sampler2D uMotion;      // UV, current - previous (CONTACT_SHADOWS_MOTION)
layout(binding = 0, r16f) uniform writeonly image2D uOut;

bool finite2(vec2 v) { return !any(isnan(v)) && !any(isinf(v)); }

// Where this pixel's surface was in last frame's image (UV); false when that is unknown or off screen.
bool previousUv(ivec2 p, out vec2 prevUv) {
    vec2 uv = (vec2(p) + 0.5) / uFullSize;
    if (CONTACT_SHADOWS_MOTION != 0) { // a define: a program with motion vectors and one without
        vec2 motion = texelFetch(uMotion, p, 0).rg;
        if (!finite2(motion)) {
            return false;
        }
        prevUv = uv - motion;
    } else {
        float z = imageLoad(uLinearDepth, p).r;
        if (!validDepth(z)) {
            prevUv = uv; // the sky: visibility 1 wherever it was
        } else {
            vec4 clip = uReprojection * vec4(viewPositionAt(vec2(p) + 0.5, z), 1.0);
            if (!(clip.w > 0.0)) {
                return false;
            }
            prevUv = clip.xy / clip.w * 0.5 + 0.5;
        }
    }
    return finite2(prevUv) && all(greaterThanEqual(prevUv, vec2(0.0))) && all(lessThanEqual(prevUv, vec2(1.0)));
}

// This frame's values over the work group and a one-texel border, for the 3x3 neighbourhood boxes.
shared float sRaw[10][10];

void loadTile(ivec2 size) {
    ivec2 origin = ivec2(gl_WorkGroupID.xy) * 8 - 1;
    for (uint i = gl_LocalInvocationIndex; i < 100u; i += 64u) {
        ivec2 q = clamp(origin + ivec2(int(i % 10u), int(i / 10u)), ivec2(0), size - 1);
        sRaw[i / 10u][i % 10u] = imageLoad(uRaw, q).r;
    }
    barrier();
}

void main() {
    ivec2 size = ivec2(uFullSize);
    loadTile(size);
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    ivec2 l = ivec2(gl_LocalInvocationID.xy) + 1;
    float current = sRaw[l.y][l.x];
    float result = current;
    vec2 prevUv;
    if (uHasHistory != 0 && previousUv(p, prevUv)) {
        float lo = current;
        float hi = current;
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                float v = sRaw[l.y + dy][l.x + dx];
                lo = min(lo, v);
                hi = max(hi, v);
            }
        }
        float history = texture(uHistory, prevUv).r;
        if (history >= 0.0 && history <= 1.0) { // NaN fails: a broken history is not reused
            result = mix(current, clamp(history, lo, hi), uHistoryWeight);
        }
    }
    imageStore(uOut, p, vec4(clamp(result, 0.0, 1.0)));
}
