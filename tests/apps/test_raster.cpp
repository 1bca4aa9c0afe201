#include "common/Raster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace photopic {
namespace {

constexpr Rgba8 kBlack{0, 0, 0, 255};
constexpr Rgba8 kWhite{255, 255, 255, 255};
constexpr Rgba8 kMagenta{200, 30, 160, 255};

bool isColor(const std::uint8_t* p, Rgba8 c) {
    return p[0] == c.r && p[1] == c.g && p[2] == c.b && p[3] == c.a;
}

int countColor(const Image8& image, Rgba8 color) {
    int count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            count += isColor(image.at(x, y), color) ? 1 : 0;
    return count;
}

struct Box {
    int left = INT32_MAX, top = INT32_MAX, right = -1, bottom = -1; ///< inclusive
};

/// Bounding box of the pixels that differ from `background`.
Box inkBox(const Image8& image, Rgba8 background) {
    Box box;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (isColor(image.at(x, y), background))
                continue;
            box.left = std::min(box.left, x);
            box.right = std::max(box.right, x);
            box.top = std::min(box.top, y);
            box.bottom = std::max(box.bottom, y);
        }
    }
    return box;
}

Image8 filled(int width, int height, Rgba8 color) {
    Image8 image(width, height);
    fillRect(image, 0, 0, width, height, color);
    return image;
}

TEST(Raster, FillRectClipsToTheImage) {
    Image8 image = filled(10, 8, kBlack);
    fillRect(image, -3, 6, 5, 10, kWhite); // covers x 0..1, y 6..7
    EXPECT_EQ(countColor(image, kWhite), 4);
    fillRect(image, 20, 20, 5, 5, kWhite);
    EXPECT_EQ(countColor(image, kWhite), 4);
}

TEST(Raster, LinesCoverEndpointsAndThickness) {
    Image8 image = filled(20, 20, kBlack);
    drawLine(image, 2, 5, 12, 5, kWhite);
    EXPECT_EQ(countColor(image, kWhite), 11);
    drawLine(image, 0, 19, 19, 0, kMagenta);
    EXPECT_TRUE(isColor(image.at(0, 19), kMagenta));
    EXPECT_TRUE(isColor(image.at(19, 0), kMagenta));
    EXPECT_EQ(countColor(image, kMagenta), 20);

    Image8 thick = filled(20, 20, kBlack);
    drawLine(thick, 3, 10, 16, 10, kWhite, 3);
    const Box box = inkBox(thick, kBlack);
    EXPECT_EQ(box.top, 9);
    EXPECT_EQ(box.bottom, 11);
    EXPECT_EQ(box.left, 2);
    EXPECT_EQ(box.right, 17);
}

TEST(Raster, FarOffscreenLineIsClippedQuickly) {
    Image8 image = filled(16, 16, kBlack);
    drawLine(image, -2000000000, 8, 2000000000, 8, kWhite);
    EXPECT_EQ(countColor(image, kWhite), 16);
    drawLine(image, -50, -50, -10, 200, kWhite);
    EXPECT_EQ(countColor(image, kWhite), 16);
}

TEST(Raster, PolylineJoinsPoints) {
    Image8 image = filled(10, 10, kBlack);
    const std::vector<Point2i> points{{1, 1}, {8, 1}, {8, 8}};
    drawPolyline(image, points, kWhite);
    EXPECT_EQ(countColor(image, kWhite), 8 + 7);
}

TEST(Raster, BlitCopiesAndClips) {
    Image8 dst = filled(6, 6, kBlack);
    const Image8 src = filled(4, 4, kMagenta);
    blit(dst, src, 4, -1); // only x 4..5, y 0..2 land
    EXPECT_EQ(countColor(dst, kMagenta), 6);
    EXPECT_TRUE(isColor(dst.at(5, 2), kMagenta));
    EXPECT_TRUE(isColor(dst.at(5, 3), kBlack));
}

TEST(Raster, BlitScaledAtSameSizeIsExact) {
    Image8 src(16, 9);
    for (std::size_t i = 0; i < src.rgba.size(); ++i)
        src.rgba[i] = std::uint8_t(i * 37 % 256);
    Image8 dst(16, 9);
    blitScaled(dst, src, 0, 0, 16, 9);
    EXPECT_EQ(dst.rgba, src.rgba) << "sRGB decode and re-encode must round-trip every 8-bit value";
}

TEST(Raster, BlitScaledAveragesInLinearLight) {
    Image8 checker(8, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            fillRect(checker, x, y, 1, 1, (x + y) % 2 ? kWhite : kBlack);
    Image8 dst = filled(4, 4, kMagenta);
    blitScaled(dst, checker, 0, 0, 2, 2);
    // Half black, half white is linear 0.5, which sRGB encodes as 188 (an sRGB-space average would give 128).
    const std::uint8_t* p = dst.at(1, 1);
    EXPECT_EQ(p[0], 188);
    EXPECT_EQ(p[1], 188);
    EXPECT_EQ(p[3], 255);
    EXPECT_TRUE(isColor(dst.at(2, 2), kMagenta)) << "draws only the w x h target";
}

TEST(Raster, BlitScaledUpsamplesConstantExactly) {
    const Image8 src = filled(3, 2, kMagenta);
    Image8 dst = filled(10, 7, kBlack);
    blitScaled(dst, src, 1, 1, 8, 5);
    EXPECT_EQ(countColor(dst, kMagenta), 40);
}

TEST(Font, EveryPrintableGlyphIsDistinctAndInked) {
    std::set<Glyph5x7> seen;
    for (int c = 33; c <= 126; ++c) {
        const Glyph5x7& glyph = glyph5x7(char(c));
        int ink = 0;
        for (const std::uint8_t row : glyph) {
            EXPECT_EQ(row & ~0x1f, 0) << "glyph " << char(c) << " is wider than 5 columns";
            ink += row != 0 ? 1 : 0;
        }
        EXPECT_GT(ink, 0) << "glyph " << char(c) << " is blank";
        EXPECT_TRUE(seen.insert(glyph).second) << "glyph " << char(c) << " duplicates another";
    }
    for (const std::uint8_t row : glyph5x7(' '))
        EXPECT_EQ(row, 0);
    EXPECT_EQ(&glyph5x7('\n'), &glyph5x7('?'));
    EXPECT_EQ(&glyph5x7(char(0xe9)), &glyph5x7('?'));
}

TEST(Font, TextWidthAndHeight) {
    EXPECT_EQ(textWidth(""), 0);
    EXPECT_EQ(textWidth("A"), 5);
    EXPECT_EQ(textWidth("Hello"), 29);
    EXPECT_EQ(textWidth("Hello", 2), 58);
    EXPECT_EQ(textHeight(), 7);
    EXPECT_EQ(textHeight(3), 21);
}

TEST(Font, DrawTextInksExactlyTheMeasuredBox) {
    for (const int scale : {1, 2, 3}) {
        Image8 image = filled(64, 32, kBlack);
        drawText(image, 4, 3, "HMH", kWhite, scale); // H and M have ink in every row and in both edge columns
        const Box box = inkBox(image, kBlack);
        EXPECT_EQ(box.left, 4);
        EXPECT_EQ(box.top, 3);
        EXPECT_EQ(box.right - box.left + 1, textWidth("HMH", scale)) << "scale " << scale;
        EXPECT_EQ(box.bottom - box.top + 1, textHeight(scale)) << "scale " << scale;
        EXPECT_GT(countColor(image, kWhite), 0);
    }
}

TEST(ContactSheet, LayoutFollowsTheDocumentedSize) {
    std::vector<std::pair<std::string, Image8>> tiles;
    tiles.emplace_back("wide", filled(100, 50, kWhite));                             // -> 80 x 40
    tiles.emplace_back("tall", filled(50, 100, kMagenta));                           // -> 80 x 160
    tiles.emplace_back("a label far too long to fit under", filled(64, 64, kWhite)); // -> 80 x 80
    const Image8 sheet = makeContactSheet(tiles, 2, 80);
    EXPECT_EQ(sheet.width, 2 * 80 + 3 * kSheetGap);
    EXPECT_EQ(sheet.height,
              kSheetGap + (160 + kSheetLabelHeight + kSheetGap) + (80 + kSheetLabelHeight + kSheetGap));

    // The tall tile fills its cell; the label band under row 0 holds light text.
    const int tallX = kSheetGap + 80 + kSheetGap;
    EXPECT_TRUE(isColor(sheet.at(tallX + 40, kSheetGap + 80), kMagenta));
    int labelInk = 0;
    for (int y = kSheetGap + 160; y < kSheetGap + 160 + kSheetLabelHeight; ++y)
        for (int x = kSheetGap; x < kSheetGap + 80; ++x)
            labelInk += sheet.at(x, y)[0] > 200 ? 1 : 0;
    EXPECT_GT(labelInk, 10);

    EXPECT_EQ(makeContactSheet(tiles, 5, 80).width, 3 * 80 + 4 * kSheetGap) << "no empty columns";
    EXPECT_TRUE(makeContactSheet({}, 3, 80).empty());
    EXPECT_THROW((void)makeContactSheet(tiles, 0, 80), std::invalid_argument);
}

TEST(ContactSheet, EmptyTileBecomesPlaceholder) {
    const Image8 sheet = makeContactSheet({{"missing", Image8()}}, 1, 64);
    EXPECT_EQ(sheet.width, 64 + 2 * kSheetGap);
    EXPECT_EQ(sheet.height, kSheetGap + 36 + kSheetLabelHeight + kSheetGap);
}

TEST(Plot, HasTheAskedSizeAndDrawsTheSeries) {
    PlotSeries sine{"sine", kMagenta, {}, {}};
    PlotSeries gappy{"gappy", Rgba8{20, 140, 60, 255}, {}, {}};
    for (int i = 0; i <= 100; ++i) {
        const float x = float(i) * 0.1f;
        sine.x.push_back(x);
        sine.y.push_back(std::sin(x) * 3.0f);
        gappy.x.push_back(x);
        gappy.y.push_back(i % 10 == 5 ? NAN : std::cos(x));
    }
    const Image8 plot = plotLines({sine, gappy}, 320, 200, "Response", "time (s)");
    EXPECT_EQ(plot.width, 320);
    EXPECT_EQ(plot.height, 200);
    EXPECT_GT(countColor(plot, kMagenta), 200) << "the sine is drawn 2 px thick over most of the width";
    EXPECT_GT(countColor(plot, gappy.color), 100);
}

TEST(Plot, DegenerateInputsStillPlot) {
    const PlotSeries flat{"flat", kMagenta, {1.0f, 1.0f}, {2.0f, 2.0f}};
    const PlotSeries allNan{"nan", kBlack, {NAN}, {NAN}};
    const Image8 plot = plotLines({flat, allNan}, 160, 100, "", "");
    EXPECT_EQ(plot.width, 160);
    EXPECT_GT(countColor(plot, kMagenta), 0);
    EXPECT_EQ(plotLines({}, 120, 80, "empty", "x").height, 80);
    const PlotSeries mismatched{"bad", kBlack, {1.0f, 2.0f}, {1.0f}};
    EXPECT_THROW((void)plotLines({mismatched}, 320, 200, "", ""), std::invalid_argument);
    EXPECT_THROW((void)plotLines({}, 100, 50, "", ""), std::invalid_argument);
}

} // namespace
} // namespace photopic
