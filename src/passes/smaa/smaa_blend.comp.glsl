// SMAA 1x, step 3: neighbourhood blending (Jimenez et al. 2012, section 3). Each pixel mixes with the
// neighbours across its edges by the weights step 2 left on both sides of every edge: across -y (its own
// r), +y (the +y neighbour's g), -x (its own b) and +x (the +x neighbour's a). Like the reference, only the
// axis with the larger weight is used, so a pixel at a corner is not blended twice. The mix is done on
// linear values (the reference reads its input as sRGB for the same reason) and encoded again; in the HDR
// placement (SMAA_HDR) the input is linear scene light already and the output stays RGBA16F.
#include "passes/common/color.h.glsl"
#include "passes/common/display_format.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uColor;
layout(binding = 1) uniform sampler2D uWeights;
#ifdef SMAA_HDR
layout(binding = 0, rgba16f) uniform writeonly image2D uOutput;
vec3 toLinear(vec3 c) { return c; }
vec3 fromLinear(vec3 c) { return c; }
#else
layout(binding = 0, DISPLAY_FORMAT) uniform writeonly image2D uOutput;
vec3 toLinear(vec3 c) { return srgbDecode(c); }
vec3 fromLinear(vec3 c) { return srgbEncode(c); }
#endif

vec4 weightsAt(ivec2 p, ivec2 size) {
    return any(greaterThanEqual(p, size)) ? vec4(0.0) : texelFetch(uWeights, p, 0);
}

vec3 linearAt(ivec2 p, ivec2 size) {
    return toLinear(texelFetch(uColor, clamp(p, ivec2(0), size - 1), 0).rgb);
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uOutput);
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    vec4 centre = texelFetch(uColor, p, 0);
    vec4 own = texelFetch(uWeights, p, 0);
    vec4 w = vec4(own.r, weightsAt(p + ivec2(0, 1), size).g, own.b, weightsAt(p + ivec2(1, 0), size).a);
    if (max(max(w.x, w.y), max(w.z, w.w)) == 0.0) {
        imageStore(uOutput, p, centre);
        return;
    }
    bool acrossY = max(w.x, w.y) > max(w.z, w.w);
    vec2 pair = acrossY ? w.xy : w.zw;
    ivec2 step1 = acrossY ? ivec2(0, 1) : ivec2(1, 0);
    vec3 c = toLinear(centre.rgb);
    vec3 minusSide = mix(c, linearAt(p - step1, size), pair.x);
    vec3 plusSide = mix(c, linearAt(p + step1, size), pair.y);
    vec3 blended = (pair.x * minusSide + pair.y * plusSide) / (pair.x + pair.y);
    imageStore(uOutput, p, vec4(onDisplayCode(fromLinear(blended)), centre.a));
}
