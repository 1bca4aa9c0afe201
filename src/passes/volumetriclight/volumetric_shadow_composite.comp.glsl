// Shadow-map volumetric light, step 3: the accumulated light upsampled to full resolution with depth in mind
// and added to the scene colour, times intensity. Of the four march texels around a pixel, bilinear weights
// when all four lie on the pixel's surface (depth within 5%); else the texel whose depth is nearest the
// pixel's, so the light in front of a near edge does not bleed onto the far side or the reverse. The light
// in the air lies in front of every surface, so it is added everywhere. The debug view gets the light added.
#include "passes/volumetriclight/volumetric_shadow_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 2, rgba16f) uniform readonly image2D uScene;
layout(binding = 3, r32f) uniform readonly image2D uDepth;    // full resolution linear depth
layout(binding = 4, r32f) uniform readonly image2D uLowDepth; // the march's depths
layout(binding = 5, rgba16f) uniform readonly image2D uAccumulated; // the accumulated light
layout(binding = 0, rgba16f) uniform writeonly image2D uOut;
layout(binding = 1, rgba16f) uniform writeonly image2D uView;

// How far apart two depths are, relative (the sky to the sky: 0; the sky to a surface: large).
float depthGap(float a, float b) {
    if (isSky(a) || isSky(b)) {
        return isSky(a) && isSky(b) ? 0.0 : 1e9;
    }
    float d = abs(a - b) / max(max(a, b), 1e-20);
    return isnan(d) ? 1e9 : d;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uOut);
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    vec4 c = imageLoad(uScene, p);
    float z = imageLoad(uDepth, p).r;
    ivec2 lowSize = ivec2(uLowSize);
    vec2 f = (vec2(p) + 0.5) / float(uFactor) - 0.5;
    ivec2 base = ivec2(floor(f));
    vec2 t = f - vec2(base);
    vec3 blended = vec3(0.0);
    vec3 nearest = vec3(0.0);
    float nearestGap = 1e30;
    bool all4 = true;
    for (int i = 0; i < 4; ++i) {
        ivec2 o = ivec2(i & 1, i >> 1);
        ivec2 tap = clamp(base + o, ivec2(0), lowSize - 1);
        float w = (o.x == 1 ? t.x : 1.0 - t.x) * (o.y == 1 ? t.y : 1.0 - t.y);
        vec3 light = imageLoad(uAccumulated, tap).rgb;
        float gap = depthGap(imageLoad(uLowDepth, tap).r, z);
        blended += w * light;
        all4 = all4 && gap <= 0.05;
        if (gap < nearestGap) {
            nearestGap = gap;
            nearest = light;
        }
    }
    vec3 added = sanitizeLight(uIntensity * (all4 ? blended : nearest));
    imageStore(uOut, p, vec4(min(sanitizeLight(c.rgb) + added, vec3(kHalfMax)), c.a));
    if (uWriteView != 0) {
        imageStore(uView, p, vec4(added, 1.0));
    }
}
