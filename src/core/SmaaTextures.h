#pragma once
// The look-up tables SMAA's blending-weight step reads (Jimenez et al. 2012, "SMAA: Enhanced Subpixel
// Morphological Antialiasing", Eurographics; after Jimenez et al. 2011, "Practical Morphological
// Antialiasing", GPU Pro 2), computed here from the paper's geometry rather than shipped as binary blobs:
//
// - the orthogonal area table: for an edge run of left + right + 1 pixels whose ends cross (or not) the
//   edge line, the fraction of the pixel at `left` that the revectorised silhouette (L, Z and U shapes)
//   cuts off on each side of the edge, short U shapes smoothed as in the paper's area texture;
// - the diagonal area table: the same for 45-degree staircases;
// - the search table: decodes one bilinear fetch of the edges texture (two pixels along the edge, and the
//   row across it) into how far the edge run goes on in those two pixels.
//
// SMAA 1x only: no subsample offsets (they are 0 for 1x). Layouts are this project's own (integer texel
// fetches, no square-root distance compression), described at each table. GL-free; computed once on first
// use (well under a millisecond) and cached, so the build needs no generator step.

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace photopic::smaa {

/// How an end of an orthogonal edge run meets the edge line: bit 0, a crossing edge on the row at +y of
/// the line (the pixel row the edge belongs to); bit 1, one on the row at -y.
enum CrossingBits : int { kCrossNone = 0, kCrossPlus = 1, kCrossMinus = 2, kCrossBoth = 3 };

inline constexpr int kOrthoMaxDistance = 64; ///< distances 0..63 per side (32 search steps of 2 pixels)
inline constexpr int kOrthoSize = 4 * kOrthoMaxDistance; ///< 4 x 4 patterns of 64 x 64
inline constexpr int kDiagMaxDistance = 20;              ///< distances 0..19 per side (16 diagonal steps)
inline constexpr int kDiagSize = 4 * kDiagMaxDistance;   ///< 4 x 4 patterns of 20 x 20
inline constexpr int kSearchLevels = 33;                 ///< one bilinear fetch encodes 0..32 / 32
inline constexpr int kSearchWidth = 2 * kSearchLevels;   ///< left/up half, right/down half
inline constexpr int kSearchHeight = kSearchLevels;

/// Coverage of the pixel on each side of an edge: `plus` is cut off the pixel on the +y side of the edge
/// line (it takes that much of its -y neighbour's colour), `minus` the one on the -y side.
struct Area {
    float plus = 0.0f;
    float minus = 0.0f;
};

/// Orthogonal runs: the edge line is y = 0 between x = -left and x = right + 1 (the pixel of interest spans
/// [0, 1]); `startCross` and `endCross` (CrossingBits) at x = -left and x = right + 1.
[[nodiscard]] Area orthogonalArea(int startCross, int endCross, int left, int right);

/// Diagonal runs: the staircase whose pixels k = 0..d-1 sit at (k, k) with an edge on their -x and +y
/// sides (d = left + right + 1, the pixel of interest is k = left). `plus` is the share of the +y
/// neighbour (k, k + 1) on the staircase's side of the line, `minus` the share of the staircase pixel on
/// the other side: the two pixels of the edge between them. Start: bit 0, the outline goes on along x
/// left of (0, 1); bit 1, pixel 0 has its -x side, down to (0, 0) (without it pixel 0 is a half step that
/// closes the staircase, only its +y side on the outline). End: bit 0, on along x right of (d, d); bit 1,
/// on along y down from (d, d). 0 also where the search ran out. The ends bend the cutting line through
/// the steps' corners (the paper's diagonal patterns, see the .cpp); with neither at both ends it is 1/4
/// on each side.
[[nodiscard]] Area diagonalArea(int startEnd, int endEnd, int left, int right);

/// RG8 tables, row-major from texel (0, 0).
struct AreaTables {
    std::vector<std::uint8_t> ortho; ///< kOrthoSize^2 RG pairs
    std::vector<std::uint8_t> diag;  ///< kDiagSize^2 RG pairs
};
/// Orthogonal texel of (startCross, endCross, left, right): x = 64 * endCross + right,
/// y = 64 * startCross + left. Diagonal likewise with 20. R = plus * 255, G = minus * 255, rounded.
[[nodiscard]] const AreaTables& areaTables();

/// One edge fetch along a run: the near and far pixel's edge bits along the run, on the run's own row and
/// on the row across the line (the latter are ignored), and the crossing edges at the near and far gaps on
/// both rows. `index` packs them as the shader's round(32 * bilinear value) does.
[[nodiscard]] constexpr int searchIndex(bool nearOwn, bool farOwn, bool nearOther, bool farOther) {
    return 21 * int(nearOwn) + 7 * int(farOwn) + 3 * int(nearOther) + int(farOther);
}
/// R8UI, kSearchWidth x kSearchHeight: x = edge index (+ 33 for the right/down search), y = crossing
/// index; the value is how many of the fetch's two pixels (0, 1, 2) the run keeps.
[[nodiscard]] const std::vector<std::uint8_t>& searchTable();

/// The per-preset constants (SMAA's reference presets).
struct Preset {
    float threshold;      ///< luma contrast that makes an edge
    int searchSteps;      ///< orthogonal search steps (2 pixels each)
    int diagonalSteps;    ///< diagonal search steps (1 pixel each), 0: no diagonal patterns
    float cornerRounding; ///< percent, 0: no corner detection
    float contrastFactor; ///< local contrast adaptation: an edge is dropped where a neighbour's is this much
                          ///< larger
};
[[nodiscard]] Preset preset(int quality);

} // namespace photopic::smaa
