#include "core/SmaaTextures.h"

#include <algorithm>
#include <cmath>

namespace photopic::smaa {

namespace {

struct Point {
    double x;
    double y;
};

/// Integral over [x0, x1] of the line through a and b, split into the parts above (y > 0) and below
/// (y < 0) the edge line: a trapezoid, or two triangles where the line crosses y = 0 inside the pixel.
Area lineArea(Point a, Point b, double x0, double x1) {
    const double slope = (b.y - a.y) / (b.x - a.x);
    const double y0 = a.y + slope * (x0 - a.x);
    const double y1 = a.y + slope * (x1 - a.x);
    Area area;
    auto add = [&area](double signedArea) {
        if (signedArea > 0.0) {
            area.plus += float(signedArea);
        } else {
            area.minus += float(-signedArea);
        }
    };
    if ((y0 >= 0.0) == (y1 >= 0.0) || y0 == 0.0 || y1 == 0.0) {
        add(0.5 * (y0 + y1) * (x1 - x0));
    } else {
        const double xc = x0 + (x1 - x0) * y0 / (y0 - y1);
        add(0.5 * y0 * (xc - x0));
        add(0.5 * y1 * (x1 - xc));
    }
    return area;
}

/// The area the segment a -> b cuts off pixel [x, x + 1], zero where the pixel is outside the segment.
Area segmentArea(Point a, Point b, double x) {
    const double x0 = std::max(x, a.x);
    const double x1 = std::min(x + 1.0, b.x);
    if (x1 <= x0) {
        return {};
    }
    return lineArea(a, b, x0, x1);
}

Area sum(Area a, Area b) {
    return {a.plus + b.plus, a.minus + b.minus};
}

/// The height a crossing edge pulls the silhouette to at its end: half a pixel into the row it lies in.
double crossingHeight(int cross) {
    return cross == kCrossPlus ? 0.5 : cross == kCrossMinus ? -0.5 : 0.0;
}

/// Fraction of the unit square at (x, y) on the side of the line a -> b where the cross product is
/// positive (to the left of the direction), by clipping the square against the half-plane.
double halfPlaneCoverage(Point a, Point b, double x, double y) {
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    auto side = [&](Point p) { return dx * (p.y - a.y) - dy * (p.x - a.x); };
    const std::array<Point, 4> square{{{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}}};
    std::array<Point, 8> poly{};
    int n = 0;
    for (int i = 0; i < 4; ++i) {
        const Point p = square[std::size_t(i)];
        const Point q = square[std::size_t((i + 1) % 4)];
        const double sp = side(p);
        const double sq = side(q);
        if (sp >= 0.0) {
            poly[std::size_t(n++)] = p;
        }
        if ((sp >= 0.0) != (sq >= 0.0)) {
            const double t = sp / (sp - sq);
            poly[std::size_t(n++)] = {p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
        }
    }
    double twiceArea = 0.0;
    for (int i = 0; i < n; ++i) {
        const Point p = poly[std::size_t(i)];
        const Point q = poly[std::size_t((i + 1) % n)];
        twiceArea += p.x * q.y - q.x * p.y;
    }
    return std::abs(0.5 * twiceArea);
}

std::uint8_t unorm8(float v) {
    return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

} // namespace

Area orthogonalArea(int startCross, int endCross, int left, int right) {
    // Pixel of interest at [left, left + 1] on a run [0, d] (the header's frame shifted by `left`).
    const double d = double(left + right + 1);
    const double x = double(left);
    // A crossing on both sides of an end says nothing about the silhouette's direction there: the run is
    // read as the Z the other end implies, and left alone when the other end says nothing either.
    auto opposite = [](int cross) {
        return cross == kCrossPlus ? kCrossMinus : cross == kCrossMinus ? kCrossPlus : kCrossNone;
    };
    if (startCross == kCrossBoth) {
        startCross = opposite(endCross);
    } else if (endCross == kCrossBoth) {
        endCross = opposite(startCross);
    }
    if (startCross == kCrossNone && endCross == kCrossNone) {
        return {}; // a straight edge (or crossings that say nothing): nothing to reconstruct
    }
    const double h1 = crossingHeight(startCross);
    const double h2 = crossingHeight(endCross);
    const Point start{0.0, h1};
    const Point middle{0.5 * d, 0.0};
    const Point end{d, h2};
    if (h1 != 0.0 && h2 != 0.0 && h1 != h2) {
        return segmentArea(start, end, x); // Z: one line from end to end
    }
    // L (one end) or U (both ends on the same side): the silhouette runs from each crossing to the middle
    // of the edge, and only the pixels of that half are cut.
    if (h1 == h2) {
        // U: short ones are smoothed (the paper's area texture): each half's share a becomes
        // sqrt(2 a) / 2 for a one-pixel run, blending linearly back to a by 32 pixels, so a small bump
        // is blended more than its two half-lines alone say.
        const double p = std::clamp(d / 32.0, 0.0, 1.0);
        auto smooth = [p](Area a) {
            auto one = [p](float v) {
                return float((1.0 - p) * std::sqrt(2.0 * double(v)) * 0.5 + p * double(v));
            };
            return Area{one(a.plus), one(a.minus)};
        };
        return sum(smooth(segmentArea(start, middle, x)), smooth(segmentArea(middle, end, x)));
    }
    Area a;
    if (h1 != 0.0) {
        a = sum(a, segmentArea(start, middle, x));
    }
    if (h2 != 0.0) {
        a = sum(a, segmentArea(middle, end, x));
    }
    return a;
}

Area diagonalArea(int startEnd, int endEnd, int left, int right) {
    // Staircase pixels (k, k), k = 0..d-1 (x right, y down); the staircase's outline runs (0, 0) -> (0, 1)
    // -> (1, 1) -> ... -> (d, d), its outer corners on y = x and its inner ones on y = x + 1. As for
    // orthogonal runs, the edges that go on at the ends say which way the silhouette bends (the paper's
    // diagonal patterns), and it is a line through step corners:
    //  - start, pixel 0 a full step (its -x side, down to (0, 0)): the line leaves from (0, 0); the outline
    //    on along x left of (0, 1): from (0, 1), a flatter line; neither (pixel 0 a half step and the
    //    outline turning away): from (-1, 0) or (0, 0), both possibilities blended;
    //  - end, on along x (right from (d, d)): the line arrives at (d, d); on along y (down from (d, d)): at
    //    (d, d + 1), a steeper line; neither: at (d - 1, d) or (d, d), blended;
    //  - both at one end: the two possibilities, each paired with one line; neither at both ends: the two
    //    45-degree lines through the outer and the inner corners, blended (1/4 on each side).
    const int d = left + right + 1;
    const double dd = double(d);
    const Point s0{-1.0, 0.0}, sAlongY{0.0, 0.0}, sAlongX{0.0, 1.0};
    const Point e0{dd - 1.0, dd}, eAlongX{dd, dd}, eAlongY{dd, dd + 1.0};
    struct Line {
        Point a;
        Point b;
    };
    // [start][end], CrossingBits-like: 0 neither, 1 along x, 2 along y, 3 both. One or two lines, blended.
    const std::array<std::array<std::array<Line, 2>, 4>, 4> patterns{{
        {{{{{sAlongX, eAlongY}, {sAlongY, eAlongX}}},
          {{{s0, eAlongX}, {sAlongY, eAlongX}}},
          {{{s0, eAlongY}, {sAlongY, eAlongY}}},
          {{{s0, eAlongY}, {sAlongY, eAlongX}}}}},
        {{{{{sAlongX, e0}, {sAlongX, eAlongX}}},
          {{{sAlongX, eAlongX}, {sAlongX, eAlongX}}},
          {{{sAlongX, eAlongY}, {sAlongX, eAlongY}}},
          {{{sAlongX, eAlongY}, {sAlongX, eAlongX}}}}},
        {{{{{sAlongY, e0}, {sAlongY, eAlongX}}},
          {{{sAlongY, eAlongX}, {sAlongY, eAlongX}}},
          {{{sAlongY, eAlongY}, {sAlongY, eAlongY}}},
          {{{sAlongY, eAlongY}, {sAlongY, eAlongX}}}}},
        {{{{{sAlongX, e0}, {sAlongY, eAlongX}}},
          {{{sAlongX, eAlongX}, {sAlongY, eAlongX}}},
          {{{sAlongX, eAlongY}, {sAlongY, eAlongY}}},
          {{{sAlongX, eAlongY}, {sAlongY, eAlongX}}}}},
    }};
    const double k = double(left);
    double plus = 0.0;
    double minus = 0.0;
    for (const Line& line : patterns[std::size_t(startEnd & 3)][std::size_t(endEnd & 3)]) {
        if (line.a.x == line.b.x && line.a.y == line.b.y) {
            continue; // a one-pixel run with an open end: no line (never looked up, the shader needs 3 steps)
        }
        // Left of a -> b (x right, y down) is the +y neighbours' side.
        minus += halfPlaneCoverage(line.a, line.b, k, k);
        plus += 1.0 - halfPlaneCoverage(line.a, line.b, k, k + 1.0);
    }
    return {float(0.5 * plus), float(0.5 * minus)};
}

const AreaTables& areaTables() {
    static const AreaTables tables = [] {
        AreaTables t;
        t.ortho.resize(std::size_t(kOrthoSize) * kOrthoSize * 2);
        t.diag.resize(std::size_t(kDiagSize) * kDiagSize * 2);
        auto fill = [](std::vector<std::uint8_t>& out, int size, int maxDistance, auto&& area) {
            for (int e1 = 0; e1 < 4; ++e1) {
                for (int e2 = 0; e2 < 4; ++e2) {
                    for (int left = 0; left < maxDistance; ++left) {
                        for (int right = 0; right < maxDistance; ++right) {
                            const Area a = area(e1, e2, left, right);
                            const int x = maxDistance * e2 + right;
                            const int y = maxDistance * e1 + left;
                            const std::size_t i = (std::size_t(y) * std::size_t(size) + std::size_t(x)) * 2;
                            out[i] = unorm8(a.plus);
                            out[i + 1] = unorm8(a.minus);
                        }
                    }
                }
            }
        };
        fill(t.ortho, kOrthoSize, kOrthoMaxDistance, orthogonalArea);
        fill(t.diag, kDiagSize, kDiagMaxDistance, diagonalArea);
        return t;
    }();
    return tables;
}

const std::vector<std::uint8_t>& searchTable() {
    static const std::vector<std::uint8_t> table = [] {
        std::vector<std::uint8_t> t(std::size_t(kSearchWidth) * kSearchHeight, 0);
        // Every combination of the fetch's eight edge bits: along-run edges of the near and far pixel on
        // the run's row and the row across the line, and the crossing edges at the near and far gaps on
        // both rows (either row's crossing ends the run).
        for (int bits = 0; bits < 256; ++bits) {
            auto bit = [bits](int i) { return ((bits >> i) & 1) != 0; };
            const bool nearEdge = bit(0), farEdge = bit(1);
            const bool nearCross = bit(4) || bit(6), farCross = bit(5) || bit(7);
            const int edgeIndex = searchIndex(bit(0), bit(1), bit(2), bit(3));
            const int crossIndex = searchIndex(bit(4), bit(5), bit(6), bit(7));
            // Left/up: the fetch is (far, near) with the near gap between them; the far gap lies beyond
            // the far pixel, so it ends the run without shortening it.
            const int backward = !nearEdge ? 0 : (nearCross || !farEdge) ? 1 : 2;
            // Right/down: the fetch is (near, far); the near gap lies before the near pixel, the far gap
            // between the two.
            const int forward = (nearCross || !nearEdge) ? 0 : (farCross || !farEdge) ? 1 : 2;
            t[std::size_t(crossIndex) * kSearchWidth + std::size_t(edgeIndex)] = std::uint8_t(backward);
            t[std::size_t(crossIndex) * kSearchWidth + std::size_t(kSearchLevels + edgeIndex)] =
                std::uint8_t(forward);
        }
        return t;
    }();
    return table;
}

Preset preset(int quality) {
    // The reference presets low, medium, high, ultra; the local contrast adaptation factor is 2 for all.
    static constexpr std::array<Preset, 4> kPresets{{
        {0.15f, 4, 0, 0.0f, 2.0f},
        {0.10f, 8, 0, 0.0f, 2.0f},
        {0.10f, 16, 8, 25.0f, 2.0f},
        {0.05f, 32, 16, 25.0f, 2.0f},
    }};
    return kPresets[std::size_t(std::clamp(quality, 0, 3))];
}

} // namespace photopic::smaa
