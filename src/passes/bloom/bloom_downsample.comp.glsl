// Bloom downsample: one level of the chain from the level above (or, with PREFILTER, from the scene).
// Reference: J. Jimenez, "Next Generation Post Processing in Call of Duty: Advanced Warfare", SIGGRAPH 2014,
// slides 150-163: 13 bilinear taps form five overlapping 2x2 boxes; the centre box weighs 0.5 and the four
// corner boxes 0.125 each, which removes the pulsing of a plain 2x2 box under motion. With KARIS each box is
// weighted by 1 / (1 + luma) and the result renormalised ("Karis average"), so a single firefly cannot
// dominate a whole region; only the first level needs it, the later ones already see averaged colour.
// With PREFILTER the taps are scene colour multiplied by the frame's exposure (bloom works on exposed colour,
// so what blooms does not depend on the scene's absolute level) and, in threshold mode, the soft knee
// (constants from core/Bloom.cpp) keeps only what lies above the threshold. The prefilter may read the host's
// raw colour (the frame skips the sanitize pass when every reader sanitises), so each of the five boxes is
// sanitised: over finite texels in [0, kSanitizeMax] that is the box of the sanitised texels (up to rounding;
// a 32-bit colour is no longer rounded to half first), and a box holding a NaN or an infinity counts as 0, a
// negative texel is clamped with its box instead of alone. Sanitising each tap, or re-reading a non-finite
// tap texel by texel, cost about 4 and 29 ms more at 1920x1080 on llvmpipe (which runs both sides of a
// branch).
// A compute pass (8x8 groups, rows of 64 on a software renderer; image stores): on GPUs whose raster units
// are a small part of the chip a full-screen triangle runs far below the memory's pace. With BLOCKS each
// invocation filters a 2x2 block of target texels whose taps it shares (BLOCKS_4X4: a 4x4 block): texture
// reads are what a CPU rasteriser pays for, and a GPU issues half the texture instructions. With TILES (the
// prefilter only, 16x16 groups) the boxes come from scene texels fetched once into shared memory; with
// SHARED_TAPS (16x16 groups) from filtered taps fetched once into shared memory.
#include "passes/common/color.h.glsl"
#include "passes/common/invocation.h.glsl"
#ifdef PREFILTER
#include "passes/common/exposure.h.glsl"
#include "passes/common/sanitize.h.glsl"
#endif

#if defined(TILES)
// One target texel per invocation, a TILES x TILES tile per group (the host's tile side).
layout(local_size_x = TILES, local_size_y = TILES) in;
#elif defined(SHARED_TAPS)
layout(local_size_x = SHARED_TAPS, local_size_y = SHARED_TAPS) in;
#else
#include "passes/common/pixel_group.h.glsl"
#endif

layout(binding = 0) uniform sampler2D uSource;
layout(binding = 0, rgba16f) uniform writeonly image2D uTarget;
// Mirrors photopic::BloomDownsampleParameters (passes/bloom/BloomPass.h), std140. The prefilter and the plain
// downsample share the layout; only the prefilter reads uThreshold and uKnee.
layout(std140, binding = BINDING_PARAMETERS) uniform BloomDownsampleParameters {
    vec2 uTargetTexel; // 1 / target size
    vec2 uSourceStep;  // one source texel in UV (two when level 0 is a quarter of the scene)
    int uThreshold;    // 1: threshold mode
    vec4 uKnee;        // T, T - knee, 2 knee, 1 / (4 knee)
};

vec3 tap(vec2 uv) {
    return textureLod(uSource, uv, 0.0).rgb;
}

// One of the five boxes: the mean of its four taps, sanitised and exposed with PREFILTER (exposed before
// the Karis weights, which must see the luma the viewer will see). Each tap is quartered before the sum, the
// same value to the bit (a power of two), so finite raw values near the float maximum cannot overflow to an
// infinity that sanitize would make 0.
#ifdef PREFILTER
// A box's mean of its 16 scene texels, sanitised and exposed.
vec3 exposedBox(vec3 mean) {
    return sanitize(mean) * gExposure.exposure;
}
#endif

vec3 box(vec3 a, vec3 b, vec3 c, vec3 d) {
#ifdef PREFILTER
    // precise: a compiler may not factor the quarters out of the sum (that sum could overflow).
    precise vec3 mean = a * 0.25 + b * 0.25 + c * 0.25 + d * 0.25;
    return exposedBox(mean);
#else
    return (a + b + c + d) * 0.25;
#endif
}

#ifdef KARIS
float karisWeight(vec3 box) {
    return 1.0 / (1.0 + luma709(box));
}
#endif

// The filter of one target texel from its five boxes (each already sanitised and exposed with PREFILTER).
vec3 combine(vec3 centre, vec3 topLeft, vec3 topRight, vec3 bottomLeft, vec3 bottomRight) {
#ifdef KARIS
    float wc = 0.5 * karisWeight(centre);
    float w0 = 0.125 * karisWeight(topLeft);
    float w1 = 0.125 * karisWeight(topRight);
    float w2 = 0.125 * karisWeight(bottomLeft);
    float w3 = 0.125 * karisWeight(bottomRight);
    vec3 color = (centre * wc + topLeft * w0 + topRight * w1 + bottomLeft * w2 + bottomRight * w3) /
                 (wc + w0 + w1 + w2 + w3);
#else
    vec3 color = centre * 0.5 + (topLeft + topRight + bottomLeft + bottomRight) * 0.125;
#endif

#ifdef PREFILTER
    if (uThreshold != 0) {
        float br = max(color.r, max(color.g, color.b));
        float rq = clamp(br - uKnee.y, 0.0, uKnee.z);
        rq = rq * rq * uKnee.w;
        color *= max(rq, br - uKnee.x) / max(br, 1e-4);
    }
#endif
    return color;
}

// The filter of one target texel from its 13 taps: a, b, c on the row two steps up, d, e one up, f, g, h on
// its own row, i, j one down, k, l, m two down (g at its centre).
vec3 downsample(vec3 a, vec3 b, vec3 c, vec3 d, vec3 e, vec3 f, vec3 g, vec3 h, vec3 i, vec3 j, vec3 k,
                vec3 l, vec3 m) {
    return combine(box(d, e, i, j), box(a, b, f, g), box(b, c, g, h), box(f, g, k, l), box(g, h, l, m));
}

#ifdef BLOCKS_4X4
// Each invocation filters a 4x4 block of target texels from 61 taps (a 6x6 grid on the even offsets, a 5x5
// on the odd ones) instead of 208: 3.8 filtered taps per target texel where 2x2 blocks take 6.25. The host
// picks it on a software renderer, where it takes the prefilter at 1920x1080 from 10.4 to 8 ms; a GPU keeps
// the 2x2 blocks, whose 25 taps held at once cost less occupancy. Target texel (q, r) of the block reads
// e<q..q+2><r..r+2> and o<q..q+1><r..r+1> (x first, y growing with the texture's y).
vec3 gridTap(vec2 origin, int i, int j) {
    return tap(origin + uSourceStep * vec2(2 * i, 2 * j));
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy) * 4;
    vec2 uv0 = (vec2(p) + 0.5) * uTargetTexel;
    // Even offsets -2, 0, ..., +8 source steps from the first texel's centre; odd offsets -1, +1, ..., +7.
    vec2 e = uv0 - 2.0 * uSourceStep, o = uv0 - uSourceStep;
    vec3 e00 = gridTap(e, 0, 0), e10 = gridTap(e, 1, 0), e20 = gridTap(e, 2, 0);
    vec3 e30 = gridTap(e, 3, 0), e40 = gridTap(e, 4, 0), e50 = gridTap(e, 5, 0);
    vec3 e01 = gridTap(e, 0, 1), e11 = gridTap(e, 1, 1), e21 = gridTap(e, 2, 1);
    vec3 e31 = gridTap(e, 3, 1), e41 = gridTap(e, 4, 1), e51 = gridTap(e, 5, 1);
    vec3 e02 = gridTap(e, 0, 2), e12 = gridTap(e, 1, 2), e22 = gridTap(e, 2, 2);
    vec3 e32 = gridTap(e, 3, 2), e42 = gridTap(e, 4, 2), e52 = gridTap(e, 5, 2);
    vec3 e03 = gridTap(e, 0, 3), e13 = gridTap(e, 1, 3), e23 = gridTap(e, 2, 3);
    vec3 e33 = gridTap(e, 3, 3), e43 = gridTap(e, 4, 3), e53 = gridTap(e, 5, 3);
    vec3 e04 = gridTap(e, 0, 4), e14 = gridTap(e, 1, 4), e24 = gridTap(e, 2, 4);
    vec3 e34 = gridTap(e, 3, 4), e44 = gridTap(e, 4, 4), e54 = gridTap(e, 5, 4);
    vec3 e05 = gridTap(e, 0, 5), e15 = gridTap(e, 1, 5), e25 = gridTap(e, 2, 5);
    vec3 e35 = gridTap(e, 3, 5), e45 = gridTap(e, 4, 5), e55 = gridTap(e, 5, 5);
    vec3 o00 = gridTap(o, 0, 0), o10 = gridTap(o, 1, 0), o20 = gridTap(o, 2, 0);
    vec3 o30 = gridTap(o, 3, 0), o40 = gridTap(o, 4, 0);
    vec3 o01 = gridTap(o, 0, 1), o11 = gridTap(o, 1, 1), o21 = gridTap(o, 2, 1);
    vec3 o31 = gridTap(o, 3, 1), o41 = gridTap(o, 4, 1);
    vec3 o02 = gridTap(o, 0, 2), o12 = gridTap(o, 1, 2), o22 = gridTap(o, 2, 2);
    vec3 o32 = gridTap(o, 3, 2), o42 = gridTap(o, 4, 2);
    vec3 o03 = gridTap(o, 0, 3), o13 = gridTap(o, 1, 3), o23 = gridTap(o, 2, 3);
    vec3 o33 = gridTap(o, 3, 3), o43 = gridTap(o, 4, 3);
    vec3 o04 = gridTap(o, 0, 4), o14 = gridTap(o, 1, 4), o24 = gridTap(o, 2, 4);
    vec3 o34 = gridTap(o, 3, 4), o44 = gridTap(o, 4, 4);
    // downsample()'s a, b, c are on the row two steps up (+y), k, l, m two steps down.
    imageStore(uTarget, p + ivec2(0, 0),
               vec4(downsample(e02, e12, e22, o01, o11, e01, e11, e21, o00, o10, e00, e10, e20), 1.0));
    imageStore(uTarget, p + ivec2(1, 0),
               vec4(downsample(e12, e22, e32, o11, o21, e11, e21, e31, o10, o20, e10, e20, e30), 1.0));
    imageStore(uTarget, p + ivec2(2, 0),
               vec4(downsample(e22, e32, e42, o21, o31, e21, e31, e41, o20, o30, e20, e30, e40), 1.0));
    imageStore(uTarget, p + ivec2(3, 0),
               vec4(downsample(e32, e42, e52, o31, o41, e31, e41, e51, o30, o40, e30, e40, e50), 1.0));
    imageStore(uTarget, p + ivec2(0, 1),
               vec4(downsample(e03, e13, e23, o02, o12, e02, e12, e22, o01, o11, e01, e11, e21), 1.0));
    imageStore(uTarget, p + ivec2(1, 1),
               vec4(downsample(e13, e23, e33, o12, o22, e12, e22, e32, o11, o21, e11, e21, e31), 1.0));
    imageStore(uTarget, p + ivec2(2, 1),
               vec4(downsample(e23, e33, e43, o22, o32, e22, e32, e42, o21, o31, e21, e31, e41), 1.0));
    imageStore(uTarget, p + ivec2(3, 1),
               vec4(downsample(e33, e43, e53, o32, o42, e32, e42, e52, o31, o41, e31, e41, e51), 1.0));
    imageStore(uTarget, p + ivec2(0, 2),
               vec4(downsample(e04, e14, e24, o03, o13, e03, e13, e23, o02, o12, e02, e12, e22), 1.0));
    imageStore(uTarget, p + ivec2(1, 2),
               vec4(downsample(e14, e24, e34, o13, o23, e13, e23, e33, o12, o22, e12, e22, e32), 1.0));
    imageStore(uTarget, p + ivec2(2, 2),
               vec4(downsample(e24, e34, e44, o23, o33, e23, e33, e43, o22, o32, e22, e32, e42), 1.0));
    imageStore(uTarget, p + ivec2(3, 2),
               vec4(downsample(e34, e44, e54, o33, o43, e33, e43, e53, o32, o42, e32, e42, e52), 1.0));
    imageStore(uTarget, p + ivec2(0, 3),
               vec4(downsample(e05, e15, e25, o04, o14, e04, e14, e24, o03, o13, e03, e13, e23), 1.0));
    imageStore(uTarget, p + ivec2(1, 3),
               vec4(downsample(e15, e25, e35, o14, o24, e14, e24, e34, o13, o23, e13, e23, e33), 1.0));
    imageStore(uTarget, p + ivec2(2, 3),
               vec4(downsample(e25, e35, e45, o24, o34, e24, e34, e44, o23, o33, e23, e33, e43), 1.0));
    imageStore(uTarget, p + ivec2(3, 3),
               vec4(downsample(e35, e45, e55, o34, o44, e34, e44, e54, o33, o43, e33, e43, e53), 1.0));
}
#elif defined(TILES)
// The prefilter from a tile of scene texels in shared memory (with PREFILTER, where level 0 is exactly half
// the scene): each group fetches the 36x36 texels under its 16x16 targets unfiltered and builds the boxes in
// arithmetic, so no filtered fetch of the scene's (often 128-bit) texels is made. The 13 taps fall on texel
// corners, so each box of four taps is the mean of a 4x4 block of texels: the corner boxes of target x start
// at source texels 2x - 2 and 2x, which the next target shares, and the centre box at 2x - 1. Means are built
// from halves and eighths (precise, as in box()) so that finite texels up to the float maximum cannot
// overflow, and a NaN or an infinity still removes its box. Clamping the texel coordinates is the taps' clamp
// to edge.
const int kTile = TILES;         // target texels per side of a group's tile
const int kSpan = 2 * kTile + 4; // scene texels per side under it: two past each edge
const int kPairsPerRow = kSpan - 1;
// [row][column]: the mean of tile texels (column, row) and (column + 1, row); vec4 rows for 16-byte shared
// loads and stores.
shared vec4 sPairs[kSpan][kPairsPerRow];
// Boxes of 4x4 texels, sanitised and exposed: [j][i] starts at tile texel (2i, 2j), or (2i + 1, 2j + 1).
shared vec4 sCorner[kTile + 1][kTile + 1];
shared vec4 sCentre[kTile][kTile];

// Each invocation takes a run of kRun pairs along a row: its kRun + 1 texels are fetched together (the
// loops have constant bounds, so all the fetches are in flight at once) and each is fetched by one run
// only but the run's last, which the next run fetches again (36 rows of 7 runs fetch 1512 texels for the
// 1296 under a 16x16 tile, where fetching both texels of every pair took 2520).
const int kRun = 5;
const int kRunsPerRow = (kPairsPerRow + kRun - 1) / kRun;

void main() {
    ivec2 tile = ivec2(gl_WorkGroupID.xy) * kTile;
    ivec2 origin = 2 * tile - 2;
    ivec2 last = textureSize(uSource, 0) - 1;
    int invocation = int(gl_LocalInvocationIndex);
    const int kInvocations = kTile * kTile;
    for (int k = invocation; k < kSpan * kRunsPerRow; k += kInvocations) {
        int row = k / kRunsPerRow, first = (k % kRunsPerRow) * kRun;
        int y = clamp(origin.y + row, 0, last.y);
        vec3 texel[kRun + 1];
        for (int n = 0; n <= kRun; ++n) {
            texel[n] = texelFetch(uSource, ivec2(clamp(origin.x + first + n, 0, last.x), y), 0).rgb;
        }
        for (int n = 0; n < kRun; ++n) {
            precise vec3 pair = texel[n] * 0.5 + texel[n + 1] * 0.5; // precise: no factoring the halves out
            if (first + n < kPairsPerRow) {
                sPairs[row][first + n] = vec4(pair, 0.0);
            }
        }
    }
    barrier();
    const int kCorners = (kTile + 1) * (kTile + 1);
    for (int k = invocation; k < kCorners + kTile * kTile; k += kInvocations) {
        bool corner = k < kCorners;
        int n = corner ? kTile + 1 : kTile, q = corner ? k : k - kCorners;
        ivec2 ij = ivec2(q % n, q / n);
        ivec2 first = 2 * ij + (corner ? 0 : 1);
        precise vec3 sum = vec3(0.0);
        for (int r = 0; r < 4; ++r) {
            sum += sPairs[first.y + r][first.x].rgb * 0.125 + sPairs[first.y + r][first.x + 2].rgb * 0.125;
        }
        if (corner) {
            sCorner[ij.y][ij.x] = vec4(exposedBox(sum), 0.0);
        } else {
            sCentre[ij.y][ij.x] = vec4(exposedBox(sum), 0.0);
        }
    }
    barrier();
    // The top boxes (+y) cover source rows 2y..2y+3, the bottom ones 2y-2..2y+1.
    ivec2 l = ivec2(gl_LocalInvocationID.xy);
    vec3 color = combine(sCentre[l.y][l.x].rgb, sCorner[l.y + 1][l.x].rgb, sCorner[l.y + 1][l.x + 1].rgb,
                         sCorner[l.y][l.x].rgb, sCorner[l.y][l.x + 1].rgb);
    imageStore(uTarget, tile + l, vec4(color, 1.0)); // past the target's edge: no effect
}
#elif defined(SHARED_TAPS)
// The prefilter from filtered taps shared through group memory, where level 0 is exactly half the scene in
// tap steps: a group's SHARED_TAPS x SHARED_TAPS targets take their 13 taps from two grids that neighbouring
// targets share. The even grid holds a tap at every target's centre (target x's taps two steps left and
// right are its neighbours' centres), the odd grid a tap one step up and right of every centre (target x's
// four one-step taps are the odd taps of x - 1 and x, on rows y - 1 and y). Each tap of the (S + 2)^2 even
// and (S + 1)^2 odd taps under a group's S x S targets is fetched once: 2.4 filtered fetches a target texel
// for S = 16, where blocks of 2x2 targets take 6.25 and of 4x4 take 3.8. The boxes and their weights are
// the taps' (box() and combine()), so the result is the blocks' to the rounding of the tap coordinates.
// With SHARED_TEXELS no tap is filtered: each is the mean of the 2x2 texels around its texel corner, from
// four unfiltered fetches (9.4 a target texel), for telling the filtering of wide texels from their reading.
const int kTile = SHARED_TAPS;
const int kEven = kTile + 2; // even taps per side: the tile's centres and one past each edge
const int kOdd = kTile + 1;  // odd taps per side: one before the tile's first centre, then one per centre
shared vec4 sEven[kEven][kEven];
shared vec4 sOdd[kOdd][kOdd];
const int kEvenTaps = kEven * kEven;
const int kTaps = kEvenTaps + kOdd * kOdd;
const int kInvocations = kTile * kTile;
const int kRounds = (kTaps + kInvocations - 1) / kInvocations;

#ifdef SHARED_TEXELS
// The bilinear tap at the texel corner `corner` (the corner below and left of texel `corner`), clamped to the
// edge as the sampler clamps: the mean of the 2x2 texels around it, quartered before the sum as box() does.
vec3 cornerTap(ivec2 corner, ivec2 last) {
    ivec2 lo = clamp(corner - 1, ivec2(0), last), hi = clamp(corner, ivec2(0), last);
    vec3 a = texelFetch(uSource, lo, 0).rgb, b = texelFetch(uSource, ivec2(hi.x, lo.y), 0).rgb;
    vec3 c = texelFetch(uSource, ivec2(lo.x, hi.y), 0).rgb, d = texelFetch(uSource, hi, 0).rgb;
    precise vec3 mean = a * 0.25 + b * 0.25 + c * 0.25 + d * 0.25;
    return mean;
}
#endif

void main() {
    ivec2 tile = ivec2(gl_WorkGroupID.xy) * kTile;
    int invocation = int(gl_LocalInvocationIndex);
#ifdef SHARED_TEXELS
    ivec2 last = textureSize(uSource, 0) - 1;
    // Source texels per tap step (1, or 2 where level 0 is a quarter of the scene): the target is half the
    // source in tap steps.
    ivec2 step = textureSize(uSource, 0) / (2 * imageSize(uTarget));
#endif
    // Constant bounds: the compiler may issue an invocation's fetches together. Taps past the texture's edge
    // clamp to it as the blocks' taps do.
    vec3 fetched[kRounds];
    for (int n = 0; n < kRounds; ++n) {
        int k = invocation + n * kInvocations;
        bool even = k < kEvenTaps;
        int side = even ? kEven : kOdd, q = even ? k : k - kEvenTaps;
        // Tap (i, j) of either grid belongs to target tile + (i, j) - 1.
        ivec2 target = tile + ivec2(q % side, q / side) - 1;
#ifdef SHARED_TEXELS
        // A target's centre is the texel corner (2 target + 1) steps from the source's origin.
        ivec2 corner = (2 * target + (even ? 1 : 2)) * step;
        fetched[n] = k < kTaps ? cornerTap(corner, last) : vec3(0.0);
#else
        vec2 centre = (vec2(target) + 0.5) * uTargetTexel;
        fetched[n] = k < kTaps ? tap(even ? centre : centre + uSourceStep) : vec3(0.0);
#endif
    }
    for (int n = 0; n < kRounds; ++n) {
        int k = invocation + n * kInvocations;
        if (k < kEvenTaps) {
            sEven[k / kEven][k % kEven] = vec4(fetched[n], 0.0);
        } else if (k < kTaps) {
            sOdd[(k - kEvenTaps) / kOdd][(k - kEvenTaps) % kOdd] = vec4(fetched[n], 0.0);
        }
    }
    barrier();
    // Target l's even taps are sEven[l.y .. l.y + 2][l.x .. l.x + 2], its odd taps sOdd[l.y .. l.y + 1]
    // [l.x .. l.x + 1]; downsample()'s a, b, c are on the row two steps up (+y), k, l, m two steps down.
    ivec2 l = ivec2(gl_LocalInvocationID.xy);
    vec3 color = downsample(
        sEven[l.y + 2][l.x].rgb, sEven[l.y + 2][l.x + 1].rgb, sEven[l.y + 2][l.x + 2].rgb,
        sOdd[l.y + 1][l.x].rgb, sOdd[l.y + 1][l.x + 1].rgb, sEven[l.y + 1][l.x].rgb,
        sEven[l.y + 1][l.x + 1].rgb, sEven[l.y + 1][l.x + 2].rgb, sOdd[l.y][l.x].rgb, sOdd[l.y][l.x + 1].rgb,
        sEven[l.y][l.x].rgb, sEven[l.y][l.x + 1].rgb, sEven[l.y][l.x + 2].rgb);
    imageStore(uTarget, tile + l, vec4(color, 1.0)); // past the target's edge: no effect
}
#elif defined(BLOCKS)
// Each invocation filters a 2x2 block of target texels. Neighbouring target texels share taps (the corner
// boxes of one are those of the next), so the block needs 25 taps instead of 52: a 4x4 grid on the even
// offsets and a 3x3 grid on the odd ones. The host picks this variant only where the target is exactly half
// the source in both directions (in units of the tap step), where the second texel's taps are the first's
// moved by two steps. A block's second column and row lie past the edge of an odd-sized target; image stores
// there have no effect (no early return: see passes/common/invocation.h.glsl).
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy) * 2;
    vec2 t = uSourceStep;
    vec2 uv0 = (vec2(p) + 0.5) * uTargetTexel;
    vec2 uv1 = uv0 + 2.0 * t;
    // Even offsets: -2, 0, +2 of the first texel and +2 of the second; odd: -1, +1 of the first, +1 of the
    // second.
    vec4 ex = vec4(uv0.x - 2.0 * t.x, uv0.x, uv1.x, uv1.x + 2.0 * t.x);
    vec4 ey = vec4(uv0.y - 2.0 * t.y, uv0.y, uv1.y, uv1.y + 2.0 * t.y);
    vec3 ox = vec3(uv0.x - t.x, uv0.x + t.x, uv1.x + t.x);
    vec3 oy = vec3(uv0.y - t.y, uv0.y + t.y, uv1.y + t.y);
    vec3 e00 = tap(vec2(ex.x, ey.x)), e10 = tap(vec2(ex.y, ey.x)), e20 = tap(vec2(ex.z, ey.x));
    vec3 e30 = tap(vec2(ex.w, ey.x)), e01 = tap(vec2(ex.x, ey.y)), e11 = tap(vec2(ex.y, ey.y));
    vec3 e21 = tap(vec2(ex.z, ey.y)), e31 = tap(vec2(ex.w, ey.y)), e02 = tap(vec2(ex.x, ey.z));
    vec3 e12 = tap(vec2(ex.y, ey.z)), e22 = tap(vec2(ex.z, ey.z)), e32 = tap(vec2(ex.w, ey.z));
    vec3 e03 = tap(vec2(ex.x, ey.w)), e13 = tap(vec2(ex.y, ey.w)), e23 = tap(vec2(ex.z, ey.w));
    vec3 e33 = tap(vec2(ex.w, ey.w));
    vec3 o00 = tap(vec2(ox.x, oy.x)), o10 = tap(vec2(ox.y, oy.x)), o20 = tap(vec2(ox.z, oy.x));
    vec3 o01 = tap(vec2(ox.x, oy.y)), o11 = tap(vec2(ox.y, oy.y)), o21 = tap(vec2(ox.z, oy.y));
    vec3 o02 = tap(vec2(ox.x, oy.z)), o12 = tap(vec2(ox.y, oy.z)), o22 = tap(vec2(ox.z, oy.z));
    // downsample()'s a, b, c are on the row two steps up (+y), k, l, m two steps down; the grids' second
    // index grows with y.
    imageStore(uTarget, p,
               vec4(downsample(e02, e12, e22, o01, o11, e01, e11, e21, o00, o10, e00, e10, e20), 1.0));
    imageStore(uTarget, p + ivec2(1, 0),
               vec4(downsample(e12, e22, e32, o11, o21, e11, e21, e31, o10, o20, e10, e20, e30), 1.0));
    imageStore(uTarget, p + ivec2(0, 1),
               vec4(downsample(e03, e13, e23, o02, o12, e02, e12, e22, o01, o11, e01, e11, e21), 1.0));
    imageStore(uTarget, p + ivec2(1, 1),
               vec4(downsample(e13, e23, e33, o12, o22, e12, e22, e32, o11, o21, e11, e21, e31), 1.0));
}
#else
// One target texel per invocation: for levels that are not half the one above (odd sizes), where each texel's
// taps are placed from its own centre.
void main() {
    ivec2 p = clampedInvocationPixel(imageSize(uTarget));
    vec2 uv = (vec2(p) + 0.5) * uTargetTexel;
    vec2 t = uSourceStep;
    vec3 color = downsample(tap(uv + t * vec2(-2.0, 2.0)), tap(uv + t * vec2(0.0, 2.0)),
                            tap(uv + t * vec2(2.0, 2.0)), tap(uv + t * vec2(-1.0, 1.0)),
                            tap(uv + t * vec2(1.0, 1.0)), tap(uv + t * vec2(-2.0, 0.0)), tap(uv),
                            tap(uv + t * vec2(2.0, 0.0)), tap(uv + t * vec2(-1.0, -1.0)),
                            tap(uv + t * vec2(1.0, -1.0)), tap(uv + t * vec2(-2.0, -2.0)),
                            tap(uv + t * vec2(0.0, -2.0)), tap(uv + t * vec2(2.0, -2.0)));
    imageStore(uTarget, p, vec4(color, 1.0));
}
#endif
