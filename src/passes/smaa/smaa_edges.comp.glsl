// SMAA 1x, step 1: luma edge detection with local contrast adaptation (Jimenez et al. 2012, "SMAA:
// Enhanced Subpixel Morphological Antialiasing", section 3.1). An edge on a pixel's -x or -y side is kept
// when the luma step across it exceeds the threshold and is not dwarfed (by `uContrastFactor`) by a
// neighbouring edge, so the weaker edge beside a strong one does not start a second, wrong pattern. With
// SMAA_DEPTH (a 3D host's frame) an edge across a depth step is a silhouette and is kept whatever its
// neighbours: where a textured surface meets the sky, its light texels' steps against the sky are weaker
// than the texture's own edges beside them, and dropping them cut the silhouette into short runs that blend.
// Luma is Rec.709 weights on the display-encoded values: edges are judged by perceived contrast. In the HDR
// placement (SMAA_HDR) the colour is scene-referred: luma is taken from the exposed value through a
// Reinhard-like curve and a square root, sqrt(l E / (1 + l E)), close enough to a tone-mapped, encoded value
// for the thresholds to keep their meaning.
// Output RG8: r, an edge between this pixel and its -x neighbour; g, with its -y neighbour; and the tile
// list (smaa_tiles.h.glsl) of the tiles with an edge.
#include "passes/common/color.h.glsl"
#ifdef SMAA_HDR
#include "passes/common/exposure.h.glsl"
#endif

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uColor;
layout(binding = 0, rg8) uniform writeonly image2D uEdges;
#ifdef SMAA_DEPTH
layout(binding = 1, r32f) uniform readonly image2D uLinearDepth; // view depth, +inf: sky

float depthAt(ivec2 p) {
    return imageLoad(uLinearDepth, clamp(p, ivec2(0), imageSize(uLinearDepth) - 1)).r;
}

// 1 where the two depths differ by more than a tenth of the nearer (a silhouette), else 0.
float depthStep(float a, float b) {
    float lo = min(a, b), hi = max(a, b);
    return (isinf(hi) && !isinf(lo)) || hi > 1.1 * lo ? 1.0 : 0.0;
}
#endif

#include "passes/smaa/smaa_parameters.h.glsl"
#define SMAA_TILES_WRITE
#include "passes/smaa/smaa_tiles.h.glsl"

float lumaAt(ivec2 p) {
    p = clamp(p, ivec2(0), textureSize(uColor, 0) - 1);
#ifdef SMAA_HDR
    float l = max(luma709(texelFetch(uColor, p, 0).rgb), 0.0) * max(gExposure.exposure, 1e-8);
    return sqrt(l / (1.0 + l));
#else
    return luma709(texelFetch(uColor, p, 0).rgb);
#endif
}

#ifdef SMAA_HDR
// The HDR luma (a fetch, the exposure curve and a square root) is computed once per texel: the work group's
// pixels and the border the neighbourhood reaches (two texels on the -x and -y sides, one on the +x and +y
// sides) in shared memory. The display luma is one dot product, cheaper than the tile's upkeep on a CPU
// renderer, and is read per tap.
shared float sLuma[11][11];

void loadLumas() {
    ivec2 origin = ivec2(gl_WorkGroupID.xy) * 8 - 2;
    for (uint i = gl_LocalInvocationIndex; i < 121u; i += 64u) {
        sLuma[i / 11u][i % 11u] = lumaAt(origin + ivec2(int(i % 11u), int(i / 11u)));
    }
    barrier();
}

// The luma of pixel p + o (local: p's place in the tile).
float lumaNear(ivec2 p, ivec2 local, ivec2 o) { return sLuma[local.y + o.y][local.x + o.x]; }
#else
void loadLumas() {}

float lumaNear(ivec2 p, ivec2 local, ivec2 o) { return lumaAt(p + o); }
#endif

void main() {
    loadLumas();
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(uEdges)))) {
        return;
    }
    ivec2 local = ivec2(gl_LocalInvocationID.xy) + 2;
    float l = lumaNear(p, local, ivec2(0));
    float lx = lumaNear(p, local, -ivec2(1, 0));
    float ly = lumaNear(p, local, -ivec2(0, 1));
    vec2 delta = abs(vec2(l) - vec2(lx, ly));
    vec2 edges = step(vec2(uThreshold), delta);
    if (edges.x + edges.y == 0.0) {
        imageStore(uEdges, p, vec4(0.0));
        return;
    }
    // An edge's neighbours are the other six sides of the two pixels it separates. The reference shader
    // pools one maximum for both edges from this pixel's four sides and the far sides of its -x and -y
    // neighbours: it misses the -x neighbour's -y and +y sides, which meet the -x edge at its ends (and
    // the -y neighbour's -x and +x sides for the -y edge). So a weak step that ends on a strong silhouette,
    // such as the end of a dark seam running along a shadow's edge on the testbed, survives as a crossing
    // edge, cuts the silhouette's long run in two and turns one gentle staircase into two short, steep
    // shapes that blend too much. With the full neighbourhood the testbed's edge error falls from 71% to
    // 69.5% of no AA's at the high preset, and the ultra preset's lower threshold no longer costs (72%).
    float plusX = abs(l - lumaNear(p, local, ivec2(1, 0)));
    float plusY = abs(l - lumaNear(p, local, ivec2(0, 1)));
    float lxy = lumaNear(p, local, -ivec2(1, 1));
    float aroundX = max(max(delta.y, plusX), plusY);
    aroundX = max(aroundX, abs(lx - lumaNear(p, local, -ivec2(2, 0))));
    aroundX = max(aroundX, max(abs(lx - lxy), abs(lx - lumaNear(p, local, ivec2(-1, 1)))));
    float aroundY = max(max(delta.x, plusX), plusY);
    aroundY = max(aroundY, abs(ly - lumaNear(p, local, -ivec2(0, 2))));
    aroundY = max(aroundY, max(abs(ly - lxy), abs(ly - lumaNear(p, local, ivec2(1, -1)))));
    vec2 kept = step(vec2(aroundX, aroundY), uContrastFactor * delta);
#ifdef SMAA_DEPTH
    float z = depthAt(p);
    kept = max(kept, vec2(depthStep(z, depthAt(p - ivec2(1, 0))), depthStep(z, depthAt(p - ivec2(0, 1)))));
#endif
    edges *= kept;
    if (edges.x + edges.y > 0.0) {
        listTile(uint(p.y / 8) * uint(uTilesX) + uint(p.x / 8), 0);
    }
    imageStore(uEdges, p, vec4(edges, 0.0, 0.0));
}
