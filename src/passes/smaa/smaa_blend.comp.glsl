// SMAA 1x, step 3: neighbourhood blending (Jimenez et al. 2012, section 3). Each pixel mixes with the
// neighbours across its edges by the weights step 2 left on both sides of every edge: across -y (its own
// r), +y (the +y neighbour's g), -x (its own b) and +x (the +x neighbour's a). Like the reference, only the
// axis with the larger weight is used, so a pixel at a corner is not blended twice. The mix is done on
// linear values (the reference reads its input as sRGB for the same reason) and encoded again; in the HDR
// placement (SMAA_HDR) the input is linear scene light already and the output stays RGBA16F. It runs where a
// weight or an edge can be (smaa_tiles.h.glsl).
//
// Sub-pixel ridges. A line thinner than a pixel (a wire, a far pole, a distant texture's stripe) shows in a
// one-sample image as pixels of full contrast wherever a pixel centre fell on it, and the patterns leave
// most of them alone: a ridge one pixel wide is two parallel edges, not a step. Such a pixel, with an edge
// on both sides along an axis and darker or brighter than both neighbours there, moves `uSubpixel` of the
// way towards their mean in linear light. A feature of width or area w (uniform in 0..1) is hit by a pixel
// centre with probability w, so given that it was hit, its expected coverage is 2/3: a third of the
// contrast is the expected excess. A pixel that is a ridge along both axes (a dot) takes the mean of both.
#include "passes/common/color.h.glsl"
#include "passes/common/display_format.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uColor;
layout(binding = 1, rgba8) uniform readonly image2D uWeights;
layout(binding = 2, rg8) uniform readonly image2D uEdges; // r, an edge with the -x neighbour; g, with the -y one
#ifdef SMAA_HDR
layout(binding = 0, rgba16f) uniform writeonly image2D uOutput;
vec3 toLinear(vec3 c) { return c; }
vec3 fromLinear(vec3 c) { return c; }
#else
layout(binding = 0, DISPLAY_FORMAT) uniform writeonly image2D uOutput;
vec3 toLinear(vec3 c) { return srgbDecode(c); }
vec3 fromLinear(vec3 c) { return srgbEncode(c); }
#endif

#include "passes/smaa/smaa_parameters.h.glsl"
#include "passes/smaa/smaa_tiles.h.glsl"

vec4 weightsAt(ivec2 p, ivec2 size) {
    return any(greaterThanEqual(p, size)) ? vec4(0.0) : imageLoad(uWeights, p);
}

vec3 linearAt(ivec2 p, ivec2 size) {
    return toLinear(texelFetch(uColor, clamp(p, ivec2(0), size - 1), 0).rgb);
}

vec2 edgesAt(ivec2 p, ivec2 size) {
    return any(greaterThanEqual(p, size)) ? vec2(0.0) : imageLoad(uEdges, p).rg;
}

// The ridge filter above for the unblended pixel p of colour `centre` (as stored); false where p is no ridge.
// Most pixels have no edge on either side and stop after one fetch.
bool subpixelRidge(ivec2 p, ivec2 size, vec3 centre, out vec3 filtered) {
    vec2 own = edgesAt(p, size);
    bvec2 edged = bvec2(own.r > 0.5 && edgesAt(p + ivec2(1, 0), size).r > 0.5,
                        own.g > 0.5 && edgesAt(p + ivec2(0, 1), size).g > 0.5);
    filtered = centre;
    if (!any(edged)) {
        return false;
    }
    vec3 c = toLinear(centre);
    float l = luma709(c);
    vec3 sum = vec3(0.0);
    float axes = 0.0;
    for (int axis = 0; axis < 2; ++axis) {
        if (!edged[axis]) {
            continue;
        }
        ivec2 step1 = axis == 0 ? ivec2(1, 0) : ivec2(0, 1);
        vec3 minusSide = linearAt(p - step1, size);
        vec3 plusSide = linearAt(p + step1, size);
        if ((l - luma709(minusSide)) * (l - luma709(plusSide)) > 0.0) {
            sum += mix(c, 0.5 * (minusSide + plusSide), uSubpixel);
            axes += 1.0;
        }
    }
    filtered = sum / max(axes, 1.0);
    return axes > 0.0;
}

// One work group per tile the weights step listed for blending (an indirect dispatch; every other pixel
// keeps the input's colour, copied before), or with uBlendAll one per 8 x 8 block of the image.
void main() {
    ivec2 p = uBlendAll != 0 ? ivec2(gl_GlobalInvocationID.xy) : listedPixel(1, gl_WorkGroupID.x);
    ivec2 size = imageSize(uOutput);
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    vec4 centre = texelFetch(uColor, p, 0);
    vec4 own = imageLoad(uWeights, p);
    vec4 w = vec4(own.r, weightsAt(p + ivec2(0, 1), size).g, own.b, weightsAt(p + ivec2(1, 0), size).a);
    if (max(max(w.x, w.y), max(w.z, w.w)) == 0.0) {
        vec3 filtered;
        if (uSubpixel > 0.0 && subpixelRidge(p, size, centre.rgb, filtered)) {
            imageStore(uOutput, p, vec4(onDisplayCode(fromLinear(filtered)), centre.a));
        } else {
            imageStore(uOutput, p, centre);
        }
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
