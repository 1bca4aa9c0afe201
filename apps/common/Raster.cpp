#include "common/Raster.h"

#include "core/Log.h"

#define STB_IMAGE_RESIZE_STATIC
#define STB_IMAGE_RESIZE_IMPLEMENTATION
#include <stb_image_resize.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace photopic {

namespace {

void store(std::uint8_t* pixel, Rgba8 color) {
    pixel[0] = color.r;
    pixel[1] = color.g;
    pixel[2] = color.b;
    pixel[3] = color.a;
}

/// Liang-Barsky: clips the segment to [lo, hi] in both axes; false when nothing is left. Keeps Bresenham's
/// loop bounded by the image whatever the coordinates.
bool clipSegment(double& x0, double& y0, double& x1, double& y1, double lo, double hiX, double hiY) {
    double t0 = 0.0;
    double t1 = 1.0;
    const double dx = x1 - x0;
    const double dy = y1 - y0;
    const auto edge = [&](double p, double q) {
        if (p == 0.0)
            return q >= 0.0;
        const double t = q / p;
        if (p < 0.0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        return t0 <= t1;
    };
    if (!edge(-dx, x0 - lo) || !edge(dx, hiX - x0) || !edge(-dy, y0 - lo) || !edge(dy, hiY - y0))
        return false;
    x1 = x0 + t1 * dx;
    y1 = y0 + t1 * dy;
    x0 = x0 + t0 * dx;
    y0 = y0 + t0 * dy;
    return true;
}

/// stb_image_resize's filter for one axis: its box (area weights; for a non-integer ratio the cell edges
/// ramp over one source pixel) when the axis shrinks, its triangle (bilinear) when it grows.
stbir_filter filterFor(int srcSize, int dstSize) {
    return dstSize < srcSize ? STBIR_FILTER_BOX : STBIR_FILTER_TRIANGLE;
}

/// `text` shortened with "..." until it fits in maxWidth px.
std::string fitText(const std::string& text, int maxWidth) {
    if (textWidth(text) <= maxWidth)
        return text;
    std::string cut = text;
    while (!cut.empty() && textWidth(cut + "...") > maxWidth)
        cut.pop_back();
    return cut + "...";
}

} // namespace

void fillRect(Image8& dst, int x, int y, int w, int h, Rgba8 color) {
    const int x0 = std::max(x, 0);
    const int y0 = std::max(y, 0);
    const int x1 = int(std::min<long long>(static_cast<long long>(x) + w, dst.width));
    const int y1 = int(std::min<long long>(static_cast<long long>(y) + h, dst.height));
    for (int yy = y0; yy < y1; ++yy)
        for (int xx = x0; xx < x1; ++xx)
            store(dst.at(xx, yy), color);
}

void drawLine(Image8& dst, int x0, int y0, int x1, int y1, Rgba8 color, int thickness) {
    thickness = std::clamp(thickness, 1, 3);
    const int offset = (thickness - 1) / 2;
    double fx0 = x0, fy0 = y0, fx1 = x1, fy1 = y1;
    if (!clipSegment(fx0, fy0, fx1, fy1, -thickness, dst.width + thickness, dst.height + thickness))
        return;
    int ax = int(std::lround(fx0)), ay = int(std::lround(fy0));
    const int bx = int(std::lround(fx1)), by = int(std::lround(fy1));
    const int dx = std::abs(bx - ax), sx = ax < bx ? 1 : -1;
    const int dy = -std::abs(by - ay), sy = ay < by ? 1 : -1;
    for (int err = dx + dy;;) {
        fillRect(dst, ax - offset, ay - offset, thickness, thickness, color);
        if (ax == bx && ay == by)
            break;
        const int e2 = 2 * err;
        if (e2 >= dy) {
            err += dy;
            ax += sx;
        }
        if (e2 <= dx) {
            err += dx;
            ay += sy;
        }
    }
}

void drawPolyline(Image8& dst, std::span<const Point2i> points, Rgba8 color, int thickness) {
    if (points.size() == 1)
        drawLine(dst, points[0].x, points[0].y, points[0].x, points[0].y, color, thickness);
    for (std::size_t i = 1; i < points.size(); ++i)
        drawLine(dst, points[i - 1].x, points[i - 1].y, points[i].x, points[i].y, color, thickness);
}

void blit(Image8& dst, const Image8& src, int x, int y) {
    const int x0 = std::max(x, 0);
    const int x1 = std::min(x + src.width, dst.width);
    if (x0 >= x1)
        return;
    for (int yy = std::max(y, 0); yy < std::min(y + src.height, dst.height); ++yy)
        std::copy_n(src.at(x0 - x, yy - y), std::size_t(x1 - x0) * 4, dst.at(x0, yy));
}

void blitScaled(Image8& dst, const Image8& src, int x, int y, int w, int h) {
    if (src.empty() || w <= 0 || h <= 0)
        return;
    if (w == src.width && h == src.height) {
        blit(dst, src, x, y); // no resampling: every value exactly as it was
        return;
    }
    // sRGB colour space: stb decodes to linear light, filters and re-encodes. Alpha premultiplied as far as
    // stb knows, so it does not weight the colour (a transparent pixel keeps its colour's share).
    Image8 scaled(w, h);
    const int ok =
        stbir_resize(src.rgba.data(), src.width, src.height, 0, scaled.rgba.data(), w, h, 0, STBIR_TYPE_UINT8,
                     4, 3, STBIR_FLAG_ALPHA_PREMULTIPLIED, STBIR_EDGE_CLAMP, STBIR_EDGE_CLAMP,
                     filterFor(src.width, w), filterFor(src.height, h), STBIR_COLORSPACE_SRGB, nullptr);
    PHOTOPIC_ASSERT(ok == 1); // fails only when its scratch memory cannot be allocated
    blit(dst, scaled, x, y);
}

int textWidth(std::string_view text, int scale) {
    return text.empty() ? 0 : (int(text.size()) * kGlyphAdvance - 1) * std::max(scale, 1);
}

int textHeight(int scale) {
    return kGlyphHeight * std::max(scale, 1);
}

void drawText(Image8& dst, int x, int y, std::string_view text, Rgba8 color, int scale) {
    scale = std::max(scale, 1);
    for (std::size_t i = 0; i < text.size(); ++i) {
        const Glyph5x7& glyph = glyph5x7(text[i]);
        const int left = x + int(i) * kGlyphAdvance * scale;
        for (int row = 0; row < kGlyphHeight; ++row)
            for (int col = 0; col < kGlyphWidth; ++col)
                if (glyph[std::size_t(row)] >> (kGlyphWidth - 1 - col) & 1)
                    fillRect(dst, left + col * scale, y + row * scale, scale, scale, color);
    }
}

// ---------------------------------------------------------------------------------------------------------------
// Contact sheet

Image8 makeContactSheet(const std::vector<std::pair<std::string, Image8>>& labelledTiles, int columns,
                        int tileWidth) {
    if (columns < 1 || tileWidth < 1)
        throw std::invalid_argument("makeContactSheet: columns and tileWidth must be at least 1");
    if (labelledTiles.empty())
        return {};
    constexpr Rgba8 kBackground{32, 32, 32, 255};
    constexpr Rgba8 kLabelBackground{12, 12, 12, 255};
    constexpr Rgba8 kLabelText{230, 230, 230, 255};
    constexpr Rgba8 kPlaceholder{72, 72, 72, 255};
    constexpr Rgba8 kPlaceholderCross{128, 128, 128, 255};

    const int count = int(labelledTiles.size());
    const int cols = std::min(columns, count);
    const int rows = (count + cols - 1) / cols;
    std::vector<int> tileHeights;
    for (const auto& [label, tile] : labelledTiles)
        tileHeights.push_back(
            tile.empty()
                ? std::max(1, tileWidth * 9 / 16)
                : std::max(1, int(std::lround(double(tile.height) * tileWidth / double(tile.width)))));
    std::vector<int> rowHeights(std::size_t(rows), 0);
    for (int i = 0; i < count; ++i)
        rowHeights[std::size_t(i / cols)] =
            std::max(rowHeights[std::size_t(i / cols)], tileHeights[std::size_t(i)]);

    int height = kSheetGap;
    for (const int rowHeight : rowHeights)
        height += rowHeight + kSheetLabelHeight + kSheetGap;
    Image8 sheet(cols * tileWidth + (cols + 1) * kSheetGap, height);
    fillRect(sheet, 0, 0, sheet.width, sheet.height, kBackground);

    int y = kSheetGap;
    for (int row = 0; row < rows; ++row) {
        const int rowHeight = rowHeights[std::size_t(row)];
        for (int col = 0; col < cols && row * cols + col < count; ++col) {
            const std::size_t i = std::size_t(row * cols + col);
            const auto& [label, tile] = labelledTiles[i];
            const int x = kSheetGap + col * (tileWidth + kSheetGap);
            const int tileHeight = tileHeights[i];
            if (tile.empty()) {
                fillRect(sheet, x, y, tileWidth, tileHeight, kPlaceholder);
                drawLine(sheet, x, y, x + tileWidth - 1, y + tileHeight - 1, kPlaceholderCross);
                drawLine(sheet, x, y + tileHeight - 1, x + tileWidth - 1, y, kPlaceholderCross);
            } else {
                blitScaled(sheet, tile, x, y, tileWidth, tileHeight);
            }
            const int bandY = y + rowHeight;
            fillRect(sheet, x, bandY, tileWidth, kSheetLabelHeight, kLabelBackground);
            drawText(sheet, x + 3, bandY + (kSheetLabelHeight - kGlyphHeight) / 2,
                     fitText(label, tileWidth - 6), kLabelText);
        }
        y += rowHeight + kSheetLabelHeight + kSheetGap;
    }
    return sheet;
}

// ---------------------------------------------------------------------------------------------------------------
// Line plot

namespace {

struct Axis {
    double lo = 0.0;
    double hi = 1.0;
    double step = 0.5;

    [[nodiscard]] int tickCount() const { return int(std::lround((hi - lo) / step)) + 1; }
    [[nodiscard]] double tick(int i) const { return lo + i * step; }
};

/// Range [lo, hi] widened to multiples of a 1, 2 or 5 x 10^k step giving at most about `maxTicks` intervals.
Axis niceAxis(double lo, double hi, int maxTicks) {
    if (!(lo <= hi)) { // no finite data
        lo = 0.0;
        hi = 1.0;
    }
    if (hi - lo <= 1e-9 * std::max(1.0, std::abs(lo))) {
        const double pad = lo == 0.0 ? 1.0 : std::abs(lo) * 0.1;
        lo -= pad;
        hi += pad;
    }
    const double raw = (hi - lo) / std::max(maxTicks, 1);
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = 10.0 * magnitude;
    for (const double m : {1.0, 2.0, 5.0}) {
        if (m * magnitude >= raw) {
            step = m * magnitude;
            break;
        }
    }
    return {std::floor(lo / step) * step, std::ceil(hi / step) * step, step};
}

std::string tickLabel(double value, double step) {
    if (std::abs(value) < step * 1e-6)
        value = 0.0; // no "-0.0"
    std::array<char, 32> text{};
    if (std::abs(value) >= 1e6 || step < 1e-4)
        std::snprintf(text.data(), text.size(), "%.3g", value);
    else
        std::snprintf(text.data(), text.size(), "%.*f",
                      std::clamp(int(std::ceil(-std::log10(step) - 1e-9)), 0, 6), value);
    return text.data();
}

constexpr Rgba8 kPlotBackground{255, 255, 255, 255};
constexpr Rgba8 kPlotInk{40, 40, 40, 255};
constexpr Rgba8 kPlotGrid{228, 228, 228, 255};
constexpr Rgba8 kPlotLegendBorder{170, 170, 170, 255};
constexpr int kPlotTick = 4; // px, tick mark length outside the frame

/// Where everything of a plot goes: the plot area in pixels and the two axes it maps.
struct PlotLayout {
    int width = 0, height = 0;
    int titleScale = 1;
    int left = 0, top = 0, plotWidth = 0, plotHeight = 0;
    Axis xAxis, yAxis;

    [[nodiscard]] int plotRight() const { return left + plotWidth - 1; }
    [[nodiscard]] int plotBottom() const { return top + plotHeight - 1; }
    [[nodiscard]] int toPixelX(double v) const {
        return left + int(std::lround((v - xAxis.lo) / (xAxis.hi - xAxis.lo) * (plotWidth - 1)));
    }
    [[nodiscard]] int toPixelY(double v) const {
        return top + plotHeight - 1 -
               int(std::lround((v - yAxis.lo) / (yAxis.hi - yAxis.lo) * (plotHeight - 1)));
    }
};

struct DataBounds {
    double xMin = std::numeric_limits<double>::infinity(), xMax = -xMin, yMin = xMin, yMax = -xMin;
};

/// The range of every finite point; throws when a series' x and y differ in length.
DataBounds dataBounds(const std::vector<PlotSeries>& series) {
    DataBounds b;
    for (const PlotSeries& s : series) {
        if (s.x.size() != s.y.size())
            throw std::invalid_argument("plotLines: series \"" + s.name + "\" has " +
                                        std::to_string(s.x.size()) + " x values but " +
                                        std::to_string(s.y.size()) + " y values");
        for (std::size_t i = 0; i < s.x.size(); ++i) {
            if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i]))
                continue;
            b.xMin = std::min(b.xMin, double(s.x[i]));
            b.xMax = std::max(b.xMax, double(s.x[i]));
            b.yMin = std::min(b.yMin, double(s.y[i]));
            b.yMax = std::max(b.yMax, double(s.y[i]));
        }
    }
    return b;
}

/// Title, plot area, tick labels, x label; the left margin fits the widest y tick label.
PlotLayout plotLayout(const DataBounds& b, int width, int height, std::string_view title,
                      std::string_view xLabel) {
    PlotLayout l;
    l.width = width;
    l.height = height;
    l.titleScale = width >= 480 ? 2 : 1;
    l.top = title.empty() ? 10 : textHeight(l.titleScale) + 14;
    const int bottom = kPlotTick + 4 + textHeight() + (xLabel.empty() ? 6 : textHeight() + 14);
    l.plotHeight = height - l.top - bottom;
    l.yAxis = niceAxis(b.yMin, b.yMax, std::max(2, l.plotHeight / 40));
    int yLabelWidth = 0;
    for (int i = 0; i < l.yAxis.tickCount(); ++i)
        yLabelWidth = std::max(yLabelWidth, textWidth(tickLabel(l.yAxis.tick(i), l.yAxis.step)));
    l.left = yLabelWidth + kPlotTick + 10;
    const int right = 16;
    l.plotWidth = width - l.left - right;
    if (l.plotWidth < 16 || l.plotHeight < 16)
        throw std::invalid_argument("plotLines: no room left for the plot area");
    l.xAxis = niceAxis(b.xMin, b.xMax, std::max(2, l.plotWidth / 70));
    return l;
}

/// Grid lines, ticks and their labels, then the frame.
void drawAxes(Image8& image, const PlotLayout& l) {
    for (int i = 0; i < l.xAxis.tickCount(); ++i) {
        const int px = l.toPixelX(l.xAxis.tick(i));
        drawLine(image, px, l.top, px, l.plotBottom(), kPlotGrid);
        drawLine(image, px, l.plotBottom(), px, l.plotBottom() + kPlotTick, kPlotInk);
        const std::string label = tickLabel(l.xAxis.tick(i), l.xAxis.step);
        drawText(image, px - textWidth(label) / 2, l.plotBottom() + kPlotTick + 4, label, kPlotInk);
    }
    for (int i = 0; i < l.yAxis.tickCount(); ++i) {
        const int py = l.toPixelY(l.yAxis.tick(i));
        drawLine(image, l.left, py, l.plotRight(), py, kPlotGrid);
        drawLine(image, l.left - kPlotTick, py, l.left, py, kPlotInk);
        const std::string label = tickLabel(l.yAxis.tick(i), l.yAxis.step);
        drawText(image, l.left - kPlotTick - 4 - textWidth(label), py - kGlyphHeight / 2, label, kPlotInk);
    }
    const int r = l.plotRight(), b = l.plotBottom();
    const std::array<Point2i, 5> frame{{{l.left, l.top}, {r, l.top}, {r, b}, {l.left, b}, {l.left, l.top}}};
    drawPolyline(image, frame, kPlotInk);
}

/// Each series as runs of finite points; a run of one point is a dot.
void drawSeries(Image8& image, const std::vector<PlotSeries>& series, const PlotLayout& l) {
    for (const PlotSeries& s : series) {
        std::vector<Point2i> run;
        const auto flush = [&] {
            if (run.size() == 1)
                fillRect(image, run[0].x - 1, run[0].y - 1, 3, 3, s.color);
            else
                drawPolyline(image, run, s.color, 2);
            run.clear();
        };
        for (std::size_t i = 0; i < s.x.size(); ++i) {
            if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
                run.push_back({l.toPixelX(s.x[i]), l.toPixelY(s.y[i])});
            else
                flush();
        }
        flush();
    }
}

/// The named series in a box in the top-right corner of the plot area.
void drawLegend(Image8& image, const std::vector<PlotSeries>& series, const PlotLayout& l) {
    int legendEntries = 0;
    int legendTextWidth = 0;
    for (const PlotSeries& s : series) {
        if (!s.name.empty()) {
            ++legendEntries;
            legendTextWidth = std::max(legendTextWidth, textWidth(s.name));
        }
    }
    if (legendEntries == 0)
        return;
    constexpr int kRow = 12;
    const int boxWidth = 8 + 16 + 6 + legendTextWidth + 8;
    const int boxX = l.plotRight() - 6 - boxWidth;
    const int boxY = l.top + 6;
    fillRect(image, boxX, boxY, boxWidth, 6 + legendEntries * kRow, kPlotLegendBorder);
    fillRect(image, boxX + 1, boxY + 1, boxWidth - 2, 4 + legendEntries * kRow, kPlotBackground);
    int entryY = boxY + 6;
    for (const PlotSeries& s : series) {
        if (s.name.empty())
            continue;
        drawLine(image, boxX + 8, entryY + 3, boxX + 24, entryY + 3, s.color, 2);
        drawText(image, boxX + 30, entryY, s.name, kPlotInk);
        entryY += kRow;
    }
}

} // namespace

Image8 plotLines(const std::vector<PlotSeries>& series, int width, int height, std::string_view title,
                 std::string_view xLabel) {
    if (width < 120 || height < 80)
        throw std::invalid_argument("plotLines: the plot must be at least 120 x 80 px");
    const PlotLayout layout = plotLayout(dataBounds(series), width, height, title, xLabel);
    Image8 image(width, height);
    fillRect(image, 0, 0, width, height, kPlotBackground);
    drawAxes(image, layout);
    drawSeries(image, series, layout);
    drawLegend(image, series, layout);
    if (!title.empty())
        drawText(image, (width - textWidth(title, layout.titleScale)) / 2, 7, title, kPlotInk,
                 layout.titleScale);
    if (!xLabel.empty())
        drawText(image, layout.left + (layout.plotWidth - textWidth(xLabel)) / 2, height - 7 - textHeight(),
                 xLabel, kPlotInk);
    return image;
}

} // namespace photopic
