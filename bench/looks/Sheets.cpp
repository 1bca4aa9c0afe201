// Contact sheets and crops for docs/looks.md: small, so the folder stays in the repository's size budget.

#include "ImageRuns.h"

#include "core/Color.h"

#include <algorithm>
#include <cmath>

namespace looks {

using photopic::Image8;

Image8 shrink(const Image8& image, int width) {
    // Averaged in linear light: averaging sRGB codes darkens fine bright detail (lamps, window leading).
    const int height = std::max(1, int(std::lround(double(image.height) * width / image.width)));
    Image8 out(width, height, 255);
    for (int y = 0; y < height; ++y) {
        const int y0 = y * image.height / height, y1 = std::max(y0 + 1, (y + 1) * image.height / height);
        for (int x = 0; x < width; ++x) {
            const int x0 = x * image.width / width, x1 = std::max(x0 + 1, (x + 1) * image.width / width);
            float sum[3] = {0, 0, 0};
            for (int sy = y0; sy < y1; ++sy) {
                for (int sx = x0; sx < x1; ++sx) {
                    for (int k = 0; k < 3; ++k) {
                        sum[k] += photopic::srgbDecode(float(image.at(sx, sy)[k]) / 255.0f);
                    }
                }
            }
            const float n = float((y1 - y0) * (x1 - x0));
            for (int k = 0; k < 3; ++k) {
                out.at(x, y)[k] = std::uint8_t(std::lround(photopic::srgbEncode(sum[k] / n) * 255.0f));
            }
        }
    }
    return out;
}

Image8 crop4x(const Image8& image, int cx, int cy, int size) {
    const int x0 = std::clamp(cx - size / 2, 0, std::max(0, image.width - size));
    const int y0 = std::clamp(cy - size / 2, 0, std::max(0, image.height - size));
    Image8 out(size * 4, size * 4, 255);
    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) {
            const int sx = std::min(x0 + x / 4, image.width - 1), sy = std::min(y0 + y / 4, image.height - 1);
            std::copy_n(image.at(sx, sy), 3, out.at(x, y));
        }
    }
    return out;
}

Image8 tile(const std::vector<Image8>& cells, int columns) {
    const int cellW = cells.front().width, cellH = cells.front().height;
    const int rows = (int(cells.size()) + columns - 1) / columns;
    Image8 out(columns * cellW + (columns - 1) * kTileGutter, rows * cellH + (rows - 1) * kTileGutter, 0);
    for (std::size_t i = 0; i < out.rgba.size(); i += 4) {
        out.rgba[i + 3] = 255;
    }
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const int ox = int(i) % columns * (cellW + kTileGutter),
                  oy = int(i) / columns * (cellH + kTileGutter);
        for (int y = 0; y < std::min(cellH, cells[i].height); ++y) {
            for (int x = 0; x < std::min(cellW, cells[i].width); ++x) {
                std::copy_n(cells[i].at(x, y), 3, out.at(ox + x, oy + y));
            }
        }
    }
    return out;
}

} // namespace looks
