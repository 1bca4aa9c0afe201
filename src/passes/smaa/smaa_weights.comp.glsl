// SMAA 1x, step 2: blending weights (Jimenez et al. 2012, "SMAA: Enhanced Subpixel Morphological
// Antialiasing", sections 3.1-3.3; the morphological reconstruction of Jimenez et al. 2011, "Practical
// Morphological Antialiasing", GPU Pro 2).
// For the edge on a pixel's -y side (edges.g) and on its -x side (edges.r):
//  1. diagonal patterns first (edges.g only): 45-degree staircases of four pixels or more through the
//     pixel, searched one pixel per step; when one is found its weights replace the orthogonal ones;
//  2. orthogonal searches both ways along the edge, two pixels per bilinear fetch of the edges texture,
//     decoded by the search table (the fetch at 3/4 near pixel, 7/8 the run's row, so each channel's
//     four bits land on distinct 32nds);
//  3. the crossing edges at the run's ends (L, Z or U shape) and the two distances index the area table:
//     the share of this pixel, and of its neighbour across the edge, that the revectorised silhouette cuts;
//  4. corner rounding: at the nearer end, a crossing edge that goes on past the next row is a real corner,
//     so its weights are scaled down (by 1 - rounding) to keep it sharp.
// Output RGBA8: r, g for the -y edge (this pixel's share, the -y neighbour's share); b, a for the -x edge;
// written over the tiles the edge step listed (smaa_tiles.h.glsl), zero elsewhere.

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uEdges;     // linear filtering: the searches fetch two pixels at once
// The tables, read texel by texel as images (a load skips the sampler's level and filtering logic).
layout(binding = 1, rg8) uniform readonly image2D uAreaOrtho;
layout(binding = 2, rg8) uniform readonly image2D uAreaDiag;
layout(binding = 3, r8ui) uniform readonly uimage2D uSearch;
layout(binding = 0, rgba8) uniform writeonly image2D uWeights;

#include "passes/smaa/smaa_parameters.h.glsl"
#define SMAA_TILES_WRITE
#include "passes/smaa/smaa_tiles.h.glsl"

const int kOrthoMax = 64;
const int kDiagMax = 20;
const int kLevels = 33;

// The weights image is the size of the edges texture. (A global set in main() is read uninitialised as far
// as the compiler can tell from the helper functions, and Mesa warns about it.)
ivec2 gridSize() {
    return imageSize(uWeights);
}

vec2 edgeAt(ivec2 p) {
    return texelFetch(uEdges, clamp(p, ivec2(0), gridSize() - 1), 0).rg;
}
bool edgeR(ivec2 p) {
    return edgeAt(p).r > 0.5;
}
bool edgeG(ivec2 p) {
    return edgeAt(p).g > 0.5;
}

// A pixel or a position from (along the edge, across it).
ivec2 pixel(bool vertical, int along, int across) {
    return vertical ? ivec2(across, along) : ivec2(along, across);
}
// Edge bits along the run and crossing it, at a pixel.
float crossingAt(bool vertical, int along, int across) {
    vec2 e = edgeAt(pixel(vertical, along, across));
    return vertical ? e.g : e.r;
}
// One bilinear fetch: x, the edges along the run; y, the crossing edges; as 32nds.
ivec2 fetchPair(bool vertical, float along, float across) {
    vec2 pos = vertical ? vec2(across, along) : vec2(along, across);
    vec2 e = textureLod(uEdges, pos / vec2(gridSize()), 0.0).rg;
    e = vertical ? e.rg : e.gr;
    return ivec2(round(e * 32.0));
}

// The first pixel of the run (along the edge), searching towards -along.
int searchBackward(bool vertical, int along, int across) {
    int a = along;
    int last = a;
    int value = 2;
    for (int i = 0; i < uSearchSteps; ++i) {
        ivec2 e = fetchPair(vertical, float(a) + 0.25, float(across) + 0.375);
        last = a;
        if (e.x < 28 || e.y != 0) {
            value = int(imageLoad(uSearch, ivec2(e.x, e.y)).r);
            break;
        }
        a -= 2;
    }
    return max(last + 1 - value, 0);
}

// The last pixel of the run, searching towards +along.
int searchForward(bool vertical, int along, int across, int limit) {
    int b = along + 1;
    int last = b;
    int value = 2;
    for (int i = 0; i < uSearchSteps; ++i) {
        ivec2 e = fetchPair(vertical, float(b) + 0.75, float(across) + 0.375);
        last = b;
        if (e.x < 28 || e.y != 0) {
            value = int(imageLoad(uSearch, ivec2(kLevels + e.x, e.y)).r);
            break;
        }
        b += 2;
    }
    return min(last - 1 + value, limit);
}

int crossingBits(bool vertical, int along, int across) {
    return int(crossingAt(vertical, along, across) > 0.5) |
           (int(crossingAt(vertical, along, across - 1) > 0.5) << 1);
}

vec2 orthogonalWeights(ivec2 p, bool vertical) {
    int along = vertical ? p.y : p.x;
    int across = vertical ? p.x : p.y;
    int limit = (vertical ? gridSize().y : gridSize().x) - 1;
    int first = searchBackward(vertical, along, across);
    int last = searchForward(vertical, along, across, limit);
    int left = along - first;
    int right = last - along;
    int e1 = crossingBits(vertical, first, across);
    int e2 = crossingBits(vertical, last + 1, across);
    ivec2 texel =
        ivec2(kOrthoMax * e2 + min(right, kOrthoMax - 1), kOrthoMax * e1 + min(left, kOrthoMax - 1));
    vec2 area = imageLoad(uAreaOrtho, texel).rg;
    if (uCornerRounding < 1.0 && area.x + area.y > 0.0) {
        vec2 nearer = vec2(left <= right ? 1.0 : 0.0, right <= left ? 1.0 : 0.0);
        vec2 rounding = (1.0 - uCornerRounding) * nearer / (nearer.x + nearer.y);
        vec2 factor = vec2(1.0);
        factor.x -= rounding.x * crossingAt(vertical, first, across + 1) +
                    rounding.y * crossingAt(vertical, last + 1, across + 1);
        factor.y -= rounding.x * crossingAt(vertical, first, across - 2) +
                    rounding.y * crossingAt(vertical, last + 1, across - 2);
        area *= clamp(factor, 0.0, 1.0);
    }
    return area;
}

// Edges around the pixel q, at offset d from it, in q's own image (mirror false) or in that image mirrored
// across the column of q (mirror true): there a -x edge is the original's +x edge, the -x edge of the
// next pixel to the right.
bool diagEdgeR(ivec2 q, ivec2 d, bool mirror) {
    return edgeR(q + (mirror ? ivec2(1 - d.x, d.y) : d));
}
bool diagEdgeG(ivec2 q, ivec2 d, bool mirror) {
    return edgeG(q + (mirror ? ivec2(-d.x, d.y) : d));
}

bool diagStep(ivec2 q, ivec2 d, bool mirror) {
    return diagEdgeG(q, d, mirror) && diagEdgeR(q, d, mirror);
}

// The staircase whose steps have edges on their -x and -y sides, going on along (1, -1), through this
// pixel q. With `mirror`, the same pattern in the image mirrored across q's column, i.e. steps with edges
// on their +x and -y sides going on along (1, 1). Both weights belong to the edge on q's -y side (its -y
// neighbour's share first in the table, so they swap), which the mirror leaves where it was: one area table
// serves both directions.
// The search follows the reference shader. At the (-1, 1) end a staircase may close with a half step, a
// pixel with only its -y edge where the outline turns along x: q itself may be one (the search towards
// (-1, 1) only starts from a q with its -x edge), and the search takes the pixel it stopped at when that
// pixel has its -y edge. That end's continuations are read at the first pixel's (-x, -y) corner, on along
// x, and down its own -x side; the other end's at the last step's (+x, -y) corner. The area table's
// patterns are drawn from those lookups. Four pixels make a staircase: three are mostly a corner, which
// the orthogonal patterns handle (with three, the testbed's edge error is 0.1 points of no AA's higher).
vec2 diagonalWeights(ivec2 q, bool mirror) {
    int fwd = 0;
    while (fwd < uDiagSteps && diagStep(q, ivec2(fwd + 1, -fwd - 1), mirror)) {
        ++fwd;
    }
    bool fwdOpen = fwd == uDiagSteps;
    fwd = min(fwd, uDiagSteps - 1);
    int back = 0;
    bool backOpen = false;
    if (diagEdgeR(q, ivec2(0), mirror)) {
        while (back < uDiagSteps && diagStep(q, ivec2(-back - 1, back + 1), mirror)) {
            ++back;
        }
        backOpen = back == uDiagSteps;
        back = min(back, uDiagSteps - 1);
        if (backOpen || diagEdgeG(q, ivec2(-back - 1, back + 1), mirror)) {
            ++back; // the half step, or the search's last pixel where it ran out
        }
    }
    if (fwd + back < 3) {
        return vec2(0.0);
    }
    // The ends' continuations (bit 0 along x, bit 1 along y); none where the search ran out, as the
    // reference drops the crossing edges of an end it did not find.
    ivec2 first = ivec2(-back, back);
    ivec2 last = ivec2(fwd, -fwd);
    int e1 = backOpen ? 0
                      : int(diagEdgeG(q, first + ivec2(-1, 0), mirror)) |
                            (int(diagEdgeR(q, first, mirror)) << 1);
    int e2 = fwdOpen ? 0
                     : int(diagEdgeG(q, last + ivec2(1, 0), mirror)) |
                           (int(diagEdgeR(q, last + ivec2(1, -1), mirror)) << 1);
    ivec2 texel = ivec2(kDiagMax * e2 + min(fwd, kDiagMax - 1), kDiagMax * e1 + min(back, kDiagMax - 1));
    return imageLoad(uAreaDiag, texel).gr;
}

// One work group per listed tile (an indirect dispatch over the tile list); the weights of every other
// pixel are the zeros the image was cleared to. The group's first invocation lists the tiles the blend
// step runs on: this one, the one to its left and the one below it.
void main() {
    ivec2 p = listedPixel(0, gl_WorkGroupID.x);
    if (gl_LocalInvocationIndex == 0u) {
        ivec2 tile = p / 8;
        listTile(uint(tile.y * uTilesX + tile.x), 1);
        if (tile.x > 0) {
            listTile(uint(tile.y * uTilesX + tile.x - 1), 1);
        }
        if (tile.y > 0) {
            listTile(uint((tile.y - 1) * uTilesX + tile.x), 1);
        }
    }
    if (any(greaterThanEqual(p, gridSize()))) {
        return;
    }
    vec2 e = edgeAt(p);
    vec4 w = vec4(0.0);
    if (e.g > 0.5) {
        if (uDiagSteps > 0) {
            // Both directions, summed as the reference does (a pixel rarely sits on both).
            w.rg = diagonalWeights(p, false) + diagonalWeights(p, true);
        }
        if (w.r + w.g == 0.0) {
            w.rg = orthogonalWeights(p, false);
        }
    }
    if (e.r > 0.5) {
        w.ba = orthogonalWeights(p, true);
    }
    imageStore(uWeights, p, w);
}
