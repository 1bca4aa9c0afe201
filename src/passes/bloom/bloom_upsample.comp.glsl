// Bloom upsample: level i of the result = mix(downsampled level i, tent(result of level i + 1), radius).
// Reference: J. Jimenez, "Next Generation Post Processing in Call of Duty: Advanced Warfare", SIGGRAPH 2014:
// a 3x3 tent [1 2 1; 2 4 2; 1 2 1] / 16 on the coarser level, accumulated level by level, so each level is
// blurred once more per step up and the sum approximates a wide, smooth kernel. Mixing (instead of adding)
// keeps the weights of all levels summing to 1 (core/Bloom.h bloomLevelWeight), so bloom moves energy
// around without adding any: what `energy-conserving` needs and what keeps `threshold` mode predictable.
// A compute pass (8x8 groups, rows of 64 on a software renderer; image store), as the downsample.
#include "passes/common/invocation.h.glsl"

#include "passes/common/pixel_group.h.glsl"

layout(binding = 0) uniform sampler2D uCoarse; // result of level i + 1 (or the smallest downsampled level)
layout(binding = 1) uniform sampler2D uFine;   // downsampled level i
layout(binding = 0, rgba16f) uniform writeonly image2D uTarget; // result of level i
// Mirrors photopic::BloomUpsampleParameters (passes/bloom/BloomPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform BloomUpsampleParameters {
    vec2 uTargetTexel; // 1 / size of level i
    vec2 uCoarseTexel; // 1 / size of level i + 1
    float uRadius;
};

// The tent's three bilinear taps per axis (at -1, 0 and +1 coarse texel, all with the same fraction f) read four
// coarse texels with the weights (1 - f) / 4, 1/2 - f/4, 1/4 + f/4 and f/4. Each pair of neighbours is one
// bilinear tap at the position its two weights say: four taps instead of nine, the same filter (to rounding;
// clamp-to-edge replicates the same border texels). Texture reads are what a CPU rasteriser pays for.
vec2 pairOffset(vec2 w0, vec2 w1) {
    return w1 / (w0 + w1);
}

#ifdef BLOCKS_4X4
// Each invocation upsamples a 4x4 block of target texels where the target is exactly twice the coarser level
// (the host checks): the block's texels sit at coarse positions 2m - 0.25, 2m + 0.25, 2m + 0.75 and 2m + 1.25
// along each axis (m: the block's index), so their fractions alternate 3/4, 1/4 and the tent's four weights
// per axis are constants, and the 16 texels read a 6x6 square of coarse texels between them: 36 fetches and
// separable sums instead of 64 filtered taps. The same filter; its float sums round in another order. The
// host picks it on a software renderer, where texture reads are what a pass pays for (bloom up 0 at 1920x1080
// on llvmpipe: 6.2 -> 3.3 ms); a GPU's filtered taps cost it little. Stores past an odd target's edge have no
// effect.
const vec4 kTentThreeQuarters = vec4(0.0625, 0.3125, 0.4375, 0.1875); // f = 3/4, texels i - 1 .. i + 2
const vec4 kTentOneQuarter = vec4(0.1875, 0.4375, 0.3125, 0.0625);    // f = 1/4

vec3 coarseAt(ivec2 texel, ivec2 size) {
    return texelFetch(uCoarse, clamp(texel, ivec2(0), size - 1), 0).rgb; // clamp to edge, as the sampler
}

// The tent along x for the block's four columns from one row of six coarse texels c0..c5 (c0 at 2m - 2).
void tentRow(vec3 c0, vec3 c1, vec3 c2, vec3 c3, vec3 c4, vec3 c5, out vec3 h0, out vec3 h1, out vec3 h2,
             out vec3 h3) {
    vec4 a = kTentThreeQuarters, b = kTentOneQuarter;
    h0 = c0 * a.x + c1 * a.y + c2 * a.z + c3 * a.w;
    h1 = c1 * b.x + c2 * b.y + c3 * b.z + c4 * b.w;
    h2 = c1 * a.x + c2 * a.y + c3 * a.z + c4 * a.w;
    h3 = c2 * b.x + c3 * b.y + c4 * b.z + c5 * b.w;
}

void store(ivec2 p, vec3 tent) {
    imageStore(uTarget, p, vec4(mix(texelFetch(uFine, p, 0).rgb, tent, uRadius), 1.0));
}

void main() {
    ivec2 block = ivec2(gl_GlobalInvocationID.xy);
    ivec2 p = block * 4;
    ivec2 size = textureSize(uCoarse, 0);
    ivec2 c = block * 2 - 2; // the 6x6 square's first coarse texel
    vec3 h[24];             // h[4 * row + column]: the x tent of coarse row `row` for block column `column`
    for (int row = 0; row < 6; ++row) {
        int y = c.y + row;
        tentRow(coarseAt(ivec2(c.x, y), size), coarseAt(ivec2(c.x + 1, y), size),
                coarseAt(ivec2(c.x + 2, y), size), coarseAt(ivec2(c.x + 3, y), size),
                coarseAt(ivec2(c.x + 4, y), size), coarseAt(ivec2(c.x + 5, y), size), h[4 * row],
                h[4 * row + 1], h[4 * row + 2], h[4 * row + 3]);
    }
    vec4 a = kTentThreeQuarters, b = kTentOneQuarter;
    for (int column = 0; column < 4; ++column) {
        store(p + ivec2(column, 0),
              h[column] * a.x + h[4 + column] * a.y + h[8 + column] * a.z + h[12 + column] * a.w);
        store(p + ivec2(column, 1),
              h[4 + column] * b.x + h[8 + column] * b.y + h[12 + column] * b.z + h[16 + column] * b.w);
        store(p + ivec2(column, 2),
              h[4 + column] * a.x + h[8 + column] * a.y + h[12 + column] * a.z + h[16 + column] * a.w);
        store(p + ivec2(column, 3),
              h[8 + column] * b.x + h[12 + column] * b.y + h[16 + column] * b.z + h[20 + column] * b.w);
    }
}
#else
void main() {
    ivec2 p = clampedInvocationPixel(imageSize(uTarget));
    vec2 uv = (vec2(p) + 0.5) * uTargetTexel;
    vec2 x = uv / uCoarseTexel - 0.5; // in coarse texels, texel centres at integers
    vec2 i = floor(x);
    vec2 f = x - i;
    vec2 wA = 0.75 - 0.5 * f; // texels i - 1 and i
    vec2 wB = 0.25 + 0.5 * f; // texels i + 1 and i + 2
    vec2 a = (i - 0.5 + pairOffset(0.25 - 0.25 * f, 0.5 - 0.25 * f)) * uCoarseTexel;
    vec2 b = (i + 1.5 + pairOffset(0.25 + 0.25 * f, 0.25 * f)) * uCoarseTexel;
    vec3 s = (textureLod(uCoarse, a, 0.0).rgb * wA.x + textureLod(uCoarse, vec2(b.x, a.y), 0.0).rgb * wB.x) * wA.y +
             (textureLod(uCoarse, vec2(a.x, b.y), 0.0).rgb * wA.x + textureLod(uCoarse, b, 0.0).rgb * wB.x) * wB.y;
    vec3 fine = texelFetch(uFine, p, 0).rgb; // the target's own texel: a fetch, not a filtered tap
    imageStore(uTarget, p, vec4(mix(fine, s, uRadius), 1.0));
}
#endif
