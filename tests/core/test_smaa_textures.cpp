// SMAA's look-up tables against the geometry of the paper (Jimenez et al. 2012, after Jimenez et al. 2011):
// areas of L, Z and U shapes worked out by hand, the tables' symmetries and range, the search table's
// decoding of a bilinear edge fetch, and the reference presets.

#include "core/SmaaTextures.h"

#include <gtest/gtest.h>

namespace photopic::smaa {

namespace {
constexpr float kEps = 1e-6f;

void expectArea(Area a, float plus, float minus, const char* what) {
    EXPECT_NEAR(a.plus, plus, kEps) << what;
    EXPECT_NEAR(a.minus, minus, kEps) << what;
}
} // namespace

// L: a crossing on the +y row at the start only; the silhouette runs from (0, 0.5) to the middle of the
// run (2, 0) over a 4-pixel run, so pixel 0 keeps a trapezoid 0.5 -> 0.25 and pixel 1 a triangle.
TEST(SmaaTextures, LShapeAreas) {
    expectArea(orthogonalArea(kCrossPlus, kCrossNone, 0, 3), 0.375f, 0.0f, "pixel 0");
    expectArea(orthogonalArea(kCrossPlus, kCrossNone, 1, 2), 0.125f, 0.0f, "pixel 1");
    expectArea(orthogonalArea(kCrossPlus, kCrossNone, 2, 1), 0.0f, 0.0f, "pixel 2: the other half");
    expectArea(orthogonalArea(kCrossPlus, kCrossNone, 3, 0), 0.0f, 0.0f, "pixel 3");
    // On the -y row the same area goes to the other side of the edge.
    expectArea(orthogonalArea(kCrossMinus, kCrossNone, 0, 3), 0.0f, 0.375f, "mirrored across the edge");
    // A single-pixel L: the line from (0, 0.5) to (0.5, 0) cuts a triangle of 1/8.
    expectArea(orthogonalArea(kCrossPlus, kCrossNone, 0, 0), 0.125f, 0.0f, "one pixel");
}

// Z: from (0, 0.5) to (d, -0.5). Even d: trapezoids; odd d: the middle pixel holds two triangles of 1/24.
TEST(SmaaTextures, ZShapeAreas) {
    expectArea(orthogonalArea(kCrossPlus, kCrossMinus, 0, 3), 0.375f, 0.0f, "d 4 pixel 0");
    expectArea(orthogonalArea(kCrossPlus, kCrossMinus, 1, 2), 0.125f, 0.0f, "d 4 pixel 1");
    expectArea(orthogonalArea(kCrossPlus, kCrossMinus, 2, 1), 0.0f, 0.125f, "d 4 pixel 2");
    expectArea(orthogonalArea(kCrossPlus, kCrossMinus, 3, 0), 0.0f, 0.375f, "d 4 pixel 3");
    expectArea(orthogonalArea(kCrossPlus, kCrossMinus, 1, 1), 1.0f / 24.0f, 1.0f / 24.0f, "d 3 middle");
    // A crossing on both rows at one end reads as the Z the other end implies.
    expectArea(orthogonalArea(kCrossBoth, kCrossMinus, 0, 3), 0.375f, 0.0f, "+ then minus");
}

// U: both crossings on one row; two half-lines meet in the middle (0.375 and 0.125 on each half of a
// 4-pixel run, twice an L's), and, as in the paper's area texture, short U's are smoothed: a share a
// becomes sqrt(2a)/2, blended back to a by 32 pixels (weight d/32). For d = 4: 0.375 -> 7/8 * sqrt(0.75)/2
// + 1/8 * 0.375 = 0.42576; 0.125 -> 7/8 * 1/4 + 1/8 * 1/8 = 0.234375. From 32 pixels on it is the plain U.
TEST(SmaaTextures, UShapeAreas) {
    expectArea(orthogonalArea(kCrossMinus, kCrossMinus, 0, 3), 0.0f, 0.425761f, "pixel 0");
    expectArea(orthogonalArea(kCrossMinus, kCrossMinus, 1, 2), 0.0f, 0.234375f, "pixel 1");
    expectArea(orthogonalArea(kCrossMinus, kCrossMinus, 2, 1), 0.0f, 0.234375f, "pixel 2");
    expectArea(orthogonalArea(kCrossMinus, kCrossMinus, 3, 0), 0.0f, 0.425761f, "pixel 3");
    // d = 32: pixel 0 is cut by the line from (0, -1/2) to (16, 0): (0.5 + 15/32) / 2 = 31/64.
    expectArea(orthogonalArea(kCrossPlus, kCrossPlus, 0, 31), 31.0f / 64.0f, 0.0f, "long, pixel 0");
}

// Straight edges and crossings that say nothing are not touched: SMAA leaves pixel-aligned edges alone.
TEST(SmaaTextures, StraightEdgesAreLeftAlone) {
    for (int left = 0; left < 10; ++left) {
        for (int right = 0; right < 10; ++right) {
            expectArea(orthogonalArea(kCrossNone, kCrossNone, left, right), 0, 0, "none");
            expectArea(orthogonalArea(kCrossBoth, kCrossBoth, left, right), 0, 0, "both");
            expectArea(orthogonalArea(kCrossBoth, kCrossNone, left, right), 0, 0, "both, none");
        }
    }
}

// Symmetries: reversing the run swaps the ends; mirroring across the edge swaps + and - rows and the
// sides. Over a whole Z run, each side holds a triangle of (d / 2) * 0.5 / 2 = d / 8.
TEST(SmaaTextures, OrthogonalSymmetriesRangeAndTotals) {
    auto mirror = [](int c) { return c == kCrossPlus ? kCrossMinus : c == kCrossMinus ? kCrossPlus : c; };
    for (int e1 = 0; e1 < 4; ++e1) {
        for (int e2 = 0; e2 < 4; ++e2) {
            for (int left = 0; left < 40; ++left) {
                for (int right = 0; right < 40; ++right) {
                    const Area a = orthogonalArea(e1, e2, left, right);
                    const Area reversed = orthogonalArea(e2, e1, right, left);
                    const Area flipped = orthogonalArea(mirror(e1), mirror(e2), left, right);
                    ASSERT_NEAR(a.plus, reversed.plus, kEps);
                    ASSERT_NEAR(a.minus, reversed.minus, kEps);
                    ASSERT_NEAR(a.plus, flipped.minus, kEps);
                    ASSERT_NEAR(a.minus, flipped.plus, kEps);
                    ASSERT_GE(a.plus, 0.0f);
                    ASSERT_GE(a.minus, 0.0f);
                    ASSERT_LE(a.plus + a.minus, 0.5f);
                }
            }
        }
    }
    for (int d = 1; d < 50; ++d) {
        double plus = 0.0, minus = 0.0;
        for (int left = 0; left < d; ++left) {
            const Area a = orthogonalArea(kCrossPlus, kCrossMinus, left, d - 1 - left);
            plus += a.plus;
            minus += a.minus;
        }
        EXPECT_NEAR(plus, d / 8.0, 1e-5) << d;
        EXPECT_NEAR(minus, d / 8.0, 1e-5) << d;
    }
}

// Diagonals (the staircase (k, k), k = 0..d-1, outline (0, 0) -> (0, 1) -> (1, 1) -> ... -> (d, d)), worked
// by hand:
// - pixel 0 a full step at the start, on along x at the end: the line through the outer corners, y = x;
//   it halves every staircase pixel and misses the +y neighbours: (plus, minus) = (0, 1/2);
// - on along x at the start, along y at the end: the inner corners, y = x + 1: (1/2, 0);
// - neither at both ends: the blend of those two, (1/4, 1/4);
// - on along x at both ends, d = 3: the line (0, 1) -> (3, 3), y = 1 + 2x/3, flatter than the staircase.
//   Pixel 0: the neighbour (0, 1) keeps the part below the line, the integral of 2x/3 over [0, 1] = 1/3;
//   the staircase pixel (0, 0) lies wholly above it: (1/3, 0). Pixel 1: the line enters (1, 1) at
//   y = 5/3 and leaves its bottom at x = 3/2; the triangle cut off, the integral of 1 - 2x/3 over
//   [1, 3/2], is 1/12, and likewise the neighbour's over [3/2, 2]: (1/12, 1/12). Pixel 2 mirrors pixel 0.
TEST(SmaaTextures, DiagonalAreas) {
    for (int left = 0; left < 10; ++left) {
        expectArea(diagonalArea(2, 1, left, 9 - left), 0.0f, 0.5f, "outer corners");
        expectArea(diagonalArea(1, 2, left, 9 - left), 0.5f, 0.0f, "inner corners");
        expectArea(diagonalArea(0, 0, left, 9 - left), 0.25f, 0.25f, "open ends");
    }
    expectArea(diagonalArea(1, 1, 0, 2), 1.0f / 3.0f, 0.0f, "along x at both ends, pixel 0");
    expectArea(diagonalArea(1, 1, 1, 1), 1.0f / 12.0f, 1.0f / 12.0f, "along x at both ends, pixel 1");
    expectArea(diagonalArea(1, 1, 2, 0), 0.0f, 1.0f / 3.0f, "along x at both ends, pixel 2");
    // Along y at both ends, d = 3: the line (0, 0) -> (3, 4), y = 4x/3, steeper. Pixel 0: it leaves the
    // staircase pixel's bottom at x = 3/4, cutting off the integral of 1 - 4x/3 over [0, 3/4] = 3/8; the
    // neighbour keeps the integral of 4x/3 - 1 over [3/4, 1] = 1/24.
    expectArea(diagonalArea(2, 2, 0, 2), 1.0f / 24.0f, 3.0f / 8.0f, "along y at both ends, pixel 0");
    for (int e1 = 0; e1 < 4; ++e1) {
        for (int e2 = 0; e2 < 4; ++e2) {
            for (int left = 0; left < kDiagMaxDistance; ++left) {
                for (int right = 0; right < kDiagMaxDistance; ++right) {
                    const Area a = diagonalArea(e1, e2, left, right);
                    ASSERT_GE(a.plus, 0.0f);
                    ASSERT_GE(a.minus, 0.0f);
                    ASSERT_LE(a.plus, 0.5f);
                    ASSERT_LE(a.minus, 0.5f);
                }
            }
        }
    }
}

// The RG8 tables hold the functions at the documented texels.
TEST(SmaaTextures, TablesHoldTheAreasAtTheirTexels) {
    const AreaTables& t = areaTables();
    ASSERT_EQ(t.ortho.size(), std::size_t(kOrthoSize * kOrthoSize * 2));
    ASSERT_EQ(t.diag.size(), std::size_t(kDiagSize * kDiagSize * 2));
    auto texel = [](const std::vector<std::uint8_t>& table, int size, int x, int y) {
        const std::size_t i = (std::size_t(y) * std::size_t(size) + std::size_t(x)) * 2;
        return std::pair{table[i], table[i + 1]};
    };
    // Z, pixel 0 of 4: plus 0.375 -> 96.
    auto z =
        texel(t.ortho, kOrthoSize, kOrthoMaxDistance * kCrossMinus + 3, kOrthoMaxDistance * kCrossPlus + 0);
    EXPECT_EQ(z.first, 96);
    EXPECT_EQ(z.second, 0);
    auto u =
        texel(t.ortho, kOrthoSize, kOrthoMaxDistance * kCrossMinus + 2, kOrthoMaxDistance * kCrossMinus + 1);
    EXPECT_EQ(u.first, 0);
    EXPECT_EQ(u.second, 60); // smoothed U, 0.234375 * 255 = 59.8
    auto diag = texel(t.diag, kDiagSize, kDiagMaxDistance * 0 + 5, kDiagMaxDistance * 0 + 5);
    EXPECT_EQ(diag.first, 64); // 0.25 * 255 = 63.75
    EXPECT_EQ(diag.second, 64);
    auto bent = texel(t.diag, kDiagSize, kDiagMaxDistance * 1 + 2, kDiagMaxDistance * 1 + 0);
    EXPECT_EQ(bent.first, 85); // 1/3
    EXPECT_EQ(bent.second, 0);
    EXPECT_EQ(&areaTables(), &t) << "computed once";
}

// The search table decodes one bilinear fetch: near pixel weight 3/4, run row 7/8, so the four bits of a
// channel land on 21, 7, 3 and 1 thirty-seconds.
TEST(SmaaTextures, SearchTableKnownEntries) {
    const std::vector<std::uint8_t>& s = searchTable();
    ASSERT_EQ(s.size(), std::size_t(kSearchWidth * kSearchHeight));
    auto backward = [&s](int edge, int cross) { return int(s[std::size_t(cross * kSearchWidth + edge)]); };
    auto forward = [&s](int edge, int cross) {
        return int(s[std::size_t(cross * kSearchWidth + kSearchLevels + edge)]);
    };
    const int both = searchIndex(true, true, false, false);
    const int nearOnly = searchIndex(true, false, false, false);
    const int farOnly = searchIndex(false, true, false, false);
    EXPECT_EQ(both, 28);
    EXPECT_EQ(backward(both, 0), 2);
    EXPECT_EQ(forward(both, 0), 2);
    EXPECT_EQ(backward(nearOnly, 0), 1);
    EXPECT_EQ(forward(nearOnly, 0), 1);
    EXPECT_EQ(backward(farOnly, 0), 0);
    EXPECT_EQ(forward(farOnly, 0), 0);
    EXPECT_EQ(backward(0, 0), 0);
    // The other row's edges do not extend the run.
    EXPECT_EQ(backward(searchIndex(false, false, true, true), 0), 0);
    EXPECT_EQ(backward(searchIndex(true, true, true, true), 0), 2);
    // A crossing between the two pixels: backward it keeps the near pixel; forward it sits before the near.
    EXPECT_EQ(backward(both, searchIndex(true, false, false, false)), 1);
    EXPECT_EQ(forward(both, searchIndex(true, false, false, false)), 0);
    // The far gap: backward it lies beyond both pixels, forward between them; either row counts.
    EXPECT_EQ(backward(both, searchIndex(false, true, false, false)), 2);
    EXPECT_EQ(forward(both, searchIndex(false, false, false, true)), 1);
    // Every index a fetch can produce is distinct: 16 combinations per channel, 0..32.
    std::array<bool, kSearchLevels> seen{};
    for (int bits = 0; bits < 16; ++bits) {
        const int i = searchIndex(bits & 1, bits & 2, bits & 4, bits & 8);
        EXPECT_FALSE(seen[std::size_t(i)]);
        seen[std::size_t(i)] = true;
    }
}

TEST(SmaaTextures, ReferencePresets) {
    const Preset low = preset(0), medium = preset(1), high = preset(2), ultra = preset(3);
    EXPECT_FLOAT_EQ(low.threshold, 0.15f);
    EXPECT_EQ(low.searchSteps, 4);
    EXPECT_EQ(low.diagonalSteps, 0);
    EXPECT_FLOAT_EQ(medium.threshold, 0.1f);
    EXPECT_EQ(medium.searchSteps, 8);
    EXPECT_EQ(medium.diagonalSteps, 0);
    EXPECT_FLOAT_EQ(high.threshold, 0.1f);
    EXPECT_EQ(high.searchSteps, 16);
    EXPECT_EQ(high.diagonalSteps, 8);
    EXPECT_FLOAT_EQ(high.cornerRounding, 25.0f);
    EXPECT_FLOAT_EQ(ultra.threshold, 0.05f);
    EXPECT_EQ(ultra.searchSteps, 32);
    EXPECT_EQ(ultra.diagonalSteps, 16);
    EXPECT_FLOAT_EQ(ultra.cornerRounding, 25.0f);
    EXPECT_LE(2 * ultra.searchSteps, kOrthoMaxDistance);
    EXPECT_LE(ultra.diagonalSteps, kDiagMaxDistance);
}

} // namespace photopic::smaa
