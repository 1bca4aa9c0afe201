#pragma once
// Small CPU drawing on Image8 for contact sheets and plots: rectangles, lines, blits and 5x7 bitmap text.
// Everything clips to the destination and writes colour and alpha as given (no blending).

#include "core/Image.h"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace photopic {

struct Rgba8 {
    std::uint8_t r, g, b, a;
};

struct Point2i {
    int x, y;
};

/// Fills the rectangle [x, x + w) x [y, y + h).
void fillRect(Image8& dst, int x, int y, int w, int h, Rgba8 color);

/// Bresenham line from (x0, y0) to (x1, y1), both ends included, stamped with a square pen of `thickness` px
/// (clamped to 1..3; odd sizes are centred on the line, 2 extends right and down).
void drawLine(Image8& dst, int x0, int y0, int x1, int y1, Rgba8 color, int thickness = 1);

/// Lines joining consecutive points; a single point draws one pen stamp.
void drawPolyline(Image8& dst, std::span<const Point2i> points, Rgba8 color, int thickness = 1);

/// Copies `src` with its top-left corner at (x, y).
void blit(Image8& dst, const Image8& src, int x, int y);

/// Draws `src` resized to w x h at (x, y), by stb_image_resize. Each axis is box filtered (area weighted)
/// when it shrinks and bilinear when it grows; at the same size `src` is copied as it is. Colour is averaged
/// in linear light (sRGB decoded, then re-encoded), so fine bright detail such as city lights keeps its
/// brightness; alpha is averaged as is and does not weight colour.
void blitScaled(Image8& dst, const Image8& src, int x, int y, int w, int h);

// ---------------------------------------------------------------------------------------------------------------
// Text: a built-in 5x7 bitmap font (Font5x7.cpp) for printable ASCII 32..126; other bytes draw as '?'.

inline constexpr int kGlyphWidth = 5;   ///< px, ink columns of a glyph at scale 1
inline constexpr int kGlyphHeight = 7;  ///< px, rows of a glyph at scale 1
inline constexpr int kGlyphAdvance = 6; ///< px, pen advance per character at scale 1 (1 px spacing)

/// Glyph rows top to bottom; bit 4 is the leftmost column, bit 0 the rightmost.
using Glyph5x7 = std::array<std::uint8_t, kGlyphHeight>;
[[nodiscard]] const Glyph5x7& glyph5x7(char c);

/// Width in px of `text` drawn at `scale` (scale < 1 counts as 1): no spacing after the last character.
[[nodiscard]] int textWidth(std::string_view text, int scale = 1);
/// Height in px of a line of text at `scale`.
[[nodiscard]] int textHeight(int scale = 1);
/// Draws one line of text with its top-left corner at (x, y); each font pixel becomes a scale x scale square.
void drawText(Image8& dst, int x, int y, std::string_view text, Rgba8 color, int scale = 1);

// ---------------------------------------------------------------------------------------------------------------
// Contact sheets and plots

inline constexpr int kSheetGap = 8;          ///< px around the sheet and between cells
inline constexpr int kSheetLabelHeight = 15; ///< px, the label band under each row of tiles

/// Lays tiles out left to right, top to bottom, in min(columns, tiles) columns. Each tile is scaled to
/// `tileWidth` keeping its aspect (an empty tile becomes a grey 16:9 placeholder) and top-aligned in its row;
/// its label sits in a dark band under the row, shortened with "..." when too wide. Size:
///   width  = c * tileWidth + (c + 1) * kSheetGap
///   height = kSheetGap + sum over rows of (tallest tile in the row + kSheetLabelHeight + kSheetGap).
/// An empty list gives an empty image; columns < 1 or tileWidth < 1 throw std::invalid_argument.
[[nodiscard]] Image8 makeContactSheet(const std::vector<std::pair<std::string, Image8>>& labelledTiles,
                                      int columns, int tileWidth);

struct PlotSeries {
    std::string name;     ///< legend entry; series with an empty name are left out of the legend
    Rgba8 color;          ///< line colour
    std::vector<float> x; ///< abscissae, same length as y
    std::vector<float> y; ///< ordinates; a non-finite x or y breaks the line there
};

/// A line plot on a white background: framed axes with "nice" (1, 2, 5 x 10^k) ticks and numeric labels, a
/// grid, the title above, `xLabel` below, and a legend in the top-right corner. Both ranges cover every
/// finite point. Throws std::invalid_argument when a series' x and y differ in length or the size is below
/// 120 x 80.
[[nodiscard]] Image8 plotLines(const std::vector<PlotSeries>& series, int width, int height,
                               std::string_view title, std::string_view xLabel);

} // namespace photopic
