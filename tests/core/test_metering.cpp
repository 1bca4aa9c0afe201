#include "core/Metering.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace photopic {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

void setGrey(ImageF& image, int x, int y, float value) {
    float* p = image.at(x, y);
    p[0] = p[1] = p[2] = value;
    p[3] = 1.0f;
}

ImageF greyImage(int w, int h, float value) {
    ImageF image(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            setGrey(image, x, y, value);
        }
    }
    return image;
}

/// A disc of `value` at (u, v) with radius r in image heights, over whatever the image holds.
void paintDisc(ImageF& image, float u, float v, float r, float value) {
    const float aspect = float(image.width) / float(image.height);
    AutoExposureSettings::SpotMetering disc{u, v, r, 1};
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const float pu = (float(x) + 0.5f) / float(image.width);
            const float pv = (float(y) + 0.5f) / float(image.height);
            if (spotWeight(pu, pv, disc, aspect) > 0.0f) {
                setGrey(image, x, y, value);
            }
        }
    }
}

TEST(Metering, LuminanceIsRec709Luma) {
    ImageF image(1, 1);
    float* p = image.at(0, 0);
    p[0] = 1.0f;
    p[1] = 2.0f;
    p[2] = 4.0f;
    EXPECT_FLOAT_EQ(pixelLuminance(image, 0, 0), 0.2126f + 2.0f * 0.7152f + 4.0f * 0.0722f);
}

TEST(Metering, AverageIsTheGeometricMean) {
    ImageF image(2, 2);
    setGrey(image, 0, 0, 1.0f);
    setGrey(image, 1, 0, 4.0f);
    setGrey(image, 0, 1, 0.25f);
    setGrey(image, 1, 1, 16.0f);
    // (1 * 4 * 0.25 * 16)^(1/4) = 2
    EXPECT_NEAR(meterAverage(image), 2.0f, 2e-6f);
}

TEST(Metering, NonFiniteAndNonPositivePixelsNeverEnterAMean) {
    ImageF image(4, 2);
    setGrey(image, 0, 0, 1.0f);
    setGrey(image, 1, 0, 4.0f);
    setGrey(image, 2, 0, 0.25f);
    setGrey(image, 3, 0, 16.0f);
    setGrey(image, 0, 1, kNaN);
    setGrey(image, 1, 1, kInf);
    setGrey(image, 2, 1, 0.0f);
    setGrey(image, 3, 1, -3.0f);
    image.at(3, 1)[1] = kNaN; // a single NaN channel poisons the pixel
    EXPECT_NEAR(meterAverage(image), 2.0f, 2e-6f);
    AutoExposureSettings center;
    center.metering = MeteringMode::Center;
    EXPECT_TRUE(std::isfinite(meterImage(image, center)));

    ImageF nothing(3, 1);
    setGrey(nothing, 0, 0, kNaN);
    setGrey(nothing, 1, 0, 0.0f);
    setGrey(nothing, 2, 0, -kInf);
    EXPECT_EQ(meterAverage(nothing), 0.0f);
    EXPECT_EQ(meterAverage(ImageF{}), 0.0f);
    EXPECT_FALSE(isMeterableLuminance(std::numeric_limits<float>::denorm_min()));
    EXPECT_TRUE(isMeterableLuminance(std::numeric_limits<float>::min()));
    EXPECT_TRUE(isMeterableLuminance(std::numeric_limits<float>::max()));
}

TEST(Metering, HistogramBinsFollowTardif) {
    const float lo = -12.0f, hi = 16.0f;
    EXPECT_EQ(histogramBin(kNaN, lo, hi), -1);
    EXPECT_EQ(histogramBin(kInf, lo, hi), -1);
    EXPECT_EQ(histogramBin(-kInf, lo, hi), -1);
    EXPECT_EQ(histogramBin(0.0f, lo, hi), 0);
    EXPECT_EQ(histogramBin(-1.0f, lo, hi), 0);
    EXPECT_EQ(histogramBin(std::numeric_limits<float>::denorm_min(), lo, hi), 0);
    EXPECT_EQ(histogramBin(std::exp2(-12.5f), lo, hi), 0);
    EXPECT_EQ(histogramBin(std::exp2(-12.0f), lo, hi), 1);
    EXPECT_EQ(histogramBin(std::exp2(16.0f), lo, hi), 255);
    EXPECT_EQ(histogramBin(1e30f, lo, hi), 255);
    EXPECT_EQ(histogramBin(std::exp2(15.99f), lo, hi), 254);
    // Every bin's centre lands in that bin; centres step by range / 254.
    for (int b = 1; b <= 254; ++b) {
        EXPECT_EQ(histogramBin(std::exp2(histogramBinCentreLog2(b, lo, hi)), lo, hi), b) << b;
    }
    const float width = (hi - lo) / 254.0f;
    EXPECT_FLOAT_EQ(histogramBinCentreLog2(1, lo, hi), lo + 0.5f * width);
    EXPECT_FLOAT_EQ(histogramBinCentreLog2(0, lo, hi), lo - 0.5f * width);
    EXPECT_FLOAT_EQ(histogramBinCentreLog2(255, lo, hi), hi + 0.5f * width);
}

TEST(Metering, HistogramIgnoresNonFinitePixelsAndStartsEmpty) {
    ImageF image = greyImage(8, 8, 0.5f);
    setGrey(image, 1, 1, kNaN);
    setGrey(image, 2, 2, kInf);
    setGrey(image, 3, 3, 0.0f); // black counts, in bin 0
    const Histogram a = buildHistogram(image, -12.0f, 16.0f);
    const Histogram b = buildHistogram(image, -12.0f, 16.0f);
    EXPECT_EQ(a.bins, b.bins); // building twice gives the same counts: nothing accumulates
    std::uint32_t total = 0;
    for (const auto c : a.bins) {
        total += c;
    }
    EXPECT_EQ(total, 62u);
    EXPECT_EQ(a.bins[0], 1u);
    EXPECT_EQ(a.bins[std::size_t(histogramBin(0.5f, -12.0f, 16.0f))], 61u);
    EXPECT_EQ(histogramAverage(a, 10.0f, 90.0f).counted, 62u);
}

TEST(Metering, HistogramWindowUsesFractionalEdgeBins) {
    Histogram h;
    h.bins[10] = 50;
    h.bins[20] = 50;
    const float c10 = histogramBinCentreLog2(10, h.log2Min, h.log2Max);
    const float c20 = histogramBinCentreLog2(20, h.log2Min, h.log2Max);
    EXPECT_FLOAT_EQ(histogramAverage(h, 0.0f, 40.0f).averageLog2, c10);
    EXPECT_FLOAT_EQ(histogramAverage(h, 60.0f, 100.0f).averageLog2, c20);
    EXPECT_FLOAT_EQ(histogramAverage(h, 40.0f, 60.0f).averageLog2, 0.5f * (c10 + c20));
    EXPECT_FLOAT_EQ(histogramAverage(h, 25.0f, 100.0f).averageLog2, (25.0f * c10 + 50.0f * c20) / 75.0f);
    const HistogramStats s = histogramAverage(h, 10.0f, 90.0f);
    EXPECT_EQ(s.lowLog2, c10);
    EXPECT_EQ(s.highLog2, c20);
    EXPECT_EQ(s.counted, 100u);
    // Continuous: moving the window edge across the bin boundary moves the mean a little, not a bin's worth.
    const float below = histogramAverage(h, 10.0f, 50.0f).averageLog2;
    const float above = histogramAverage(h, 10.0f, 50.1f).averageLog2;
    EXPECT_LT(above - below, 0.01f * (c20 - c10));
    EXPECT_GT(above, below);
    // Empty histogram: nothing counted.
    EXPECT_EQ(histogramAverage(Histogram{}, 10.0f, 90.0f).counted, 0u);
}

TEST(Metering, UnderflowPixelsAreTheDarkestOfTheWindow) {
    ImageF image = greyImage(10, 10, 1.0f);
    for (int y = 0; y < 5; ++y) {
        for (int x = 0; x < 10; ++x) {
            setGrey(image, x, y, 0.0f);
        }
    }
    const Histogram h = buildHistogram(image, -12.0f, 16.0f);
    const HistogramStats s = histogramAverage(h, 10.0f, 90.0f);
    EXPECT_EQ(s.counted, 100u);
    EXPECT_EQ(s.lowLog2, histogramBinCentreLog2(0, -12.0f, 16.0f));
    const float c1 = histogramBinCentreLog2(histogramBin(1.0f, -12.0f, 16.0f), -12.0f, 16.0f);
    EXPECT_NEAR(s.averageLog2, 0.5f * (histogramBinCentreLog2(0, -12.0f, 16.0f) + c1), 1e-5f);
}

// 15% of the frame is a very hot light: the geometric mean follows it, the percentile window drops it. The
// window's top is 80% here: the default 90% drops only the top 10%, and 5% of a 15% area would stay in.
TEST(Metering, HistogramPercentilesIgnoreHotAreaThatTheMeanDoesNot) {
    constexpr int kW = 100, kH = 100;
    ImageF clean(kW, kH);
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            // Mid grey with +-0.5 EV of texture.
            setGrey(clean, x, y, 0.18f * std::exp2(0.5f * std::sin(0.37f * float(x) + 0.91f * float(y))));
        }
    }
    ImageF hot = clean;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < 15; ++x) {
            setGrey(hot, x, y, 2000.0f); // 15% of the area, ~13 EV above mid grey
        }
    }
    AutoExposureSettings settings;
    settings.lowPercent = 10.0f;
    settings.highPercent = 80.0f;
    settings.metering = MeteringMode::Histogram;
    const float histClean = std::log2(meterImage(clean, settings));
    const float histHot = std::log2(meterImage(hot, settings));
    const float meanClean = std::log2(meterAverage(clean));
    const float meanHot = std::log2(meterAverage(hot));
    EXPECT_GT(meanHot - meanClean, 1.5f);            // the mean moves ~2 EV
    EXPECT_LT(std::abs(histHot - histClean), 0.15f); // the histogram barely moves
    EXPECT_NEAR(histClean, std::log2(0.18f), 0.25f); // and sits on the scene's mid grey
}

TEST(Metering, SpotFollowsItsDisc) {
    constexpr int kW = 160, kH = 90;
    ImageF image = greyImage(kW, kH, 0.05f);
    paintDisc(image, 0.25f, 0.5f, 0.15f, 8.0f);
    AutoExposureSettings::SpotMetering spot{0.25f, 0.5f, 0.1f, 13};
    EXPECT_NEAR(meterSpot(image, spot), 8.0f, 1e-4f);
    spot.u = 0.75f;
    EXPECT_NEAR(meterSpot(image, spot), 0.05f, 1e-6f);
    // Move the bright disc under the spot: the reading follows.
    ImageF moved = greyImage(kW, kH, 0.05f);
    paintDisc(moved, 0.75f, 0.5f, 0.15f, 8.0f);
    EXPECT_NEAR(meterSpot(moved, spot), 8.0f, 1e-4f);
    // Half on the disc edge: with 5 taps at (+-0.5, 0) the disc edge between them splits the taps.
    ImageF half = greyImage(kW, kH, 0.05f);
    paintDisc(half, 0.75f + 0.3f * float(kH) / float(kW), 0.5f, 0.3f, 8.0f); // left edge at u = 0.75
    AutoExposureSettings::SpotMetering five{0.75f, 0.5f, 0.2f, 5};
    const float reading = meterSpot(half, five); // taps: centre and +x bright -> 2 of 5 bright
    EXPECT_NEAR(std::log2(reading), (2.0f * std::log2(8.0f) + 3.0f * std::log2(0.05f)) / 5.0f, 1e-4f);

    AutoExposureSettings settings;
    settings.metering = MeteringMode::Spot;
    settings.spot = spot;
    EXPECT_EQ(meterImage(moved, settings), meterSpot(moved, spot));
}

TEST(Metering, SpotTapsAndWeightsFollowTheTable) {
    const AutoExposureSettings::SpotMetering spot{0.5f, 0.5f, 0.1f, 13};
    // 200 x 100: radius 0.1 = 10 pixels in both axes (radius is in image heights).
    const TexelCoord c = spotTapTexel(spot, 0, 200, 100);
    EXPECT_EQ(c.x, 100);
    EXPECT_EQ(c.y, 50);
    const TexelCoord right = spotTapTexel(spot, 9, 200, 100); // (1, 0)
    EXPECT_EQ(right.x, 110);
    EXPECT_EQ(right.y, 50);
    const TexelCoord down = spotTapTexel(spot, 11, 200, 100); // (0, 1)
    EXPECT_EQ(down.x, 100);
    EXPECT_EQ(down.y, 60);
    // Clamped to the image.
    const AutoExposureSettings::SpotMetering corner{0.0f, 1.0f, 0.5f, 13};
    const TexelCoord clamped = spotTapTexel(corner, 11, 200, 100);
    EXPECT_EQ(clamped.x, 0);
    EXPECT_EQ(clamped.y, 99);
    // Every tap lies in the closed unit disc; taps 1/5/9/13 are prefixes with a centred pattern.
    float sx = 0.0f, sy = 0.0f;
    for (const auto& t : kSpotTaps) {
        EXPECT_LE(t[0] * t[0] + t[1] * t[1], 1.0f);
        sx += t[0];
        sy += t[1];
    }
    EXPECT_EQ(sx, 0.0f);
    EXPECT_EQ(sy, 0.0f);
    for (const int n : {1, 5, 9}) {
        float px = 0.0f, py = 0.0f;
        for (int i = 0; i < n; ++i) {
            px += kSpotTaps[std::size_t(i)][0];
            py += kSpotTaps[std::size_t(i)][1];
        }
        EXPECT_EQ(px, 0.0f) << n;
        EXPECT_EQ(py, 0.0f) << n;
    }
    // spotWeight: aspect-corrected disc.
    EXPECT_EQ(spotWeight(0.5f, 0.5f, spot, 2.0f), 1.0f);
    EXPECT_EQ(spotWeight(0.54f, 0.5f, spot, 2.0f), 1.0f); // 0.08 heights
    EXPECT_EQ(spotWeight(0.56f, 0.5f, spot, 2.0f), 0.0f); // 0.12 heights
    EXPECT_EQ(spotWeight(0.5f, 0.59f, spot, 2.0f), 1.0f);
    EXPECT_EQ(spotWeight(0.5f, 0.61f, spot, 2.0f), 0.0f);
}

TEST(Metering, CenterWeightIsAGaussianAroundTheCentre) {
    EXPECT_FLOAT_EQ(centerWeight(0.5f, 0.5f, 16.0f / 9.0f), 1.0f);
    EXPECT_FLOAT_EQ(centerWeight(0.5f, 0.0f, 16.0f / 9.0f), std::exp(-2.0f)); // top edge: d = 0.5
    EXPECT_FLOAT_EQ(centerWeight(0.75f, 0.5f, 2.0f), std::exp(-2.0f));        // d = 0.25 * 2
    EXPECT_GT(centerWeight(0.0f, 0.0f, 16.0f / 9.0f), 0.0f);

    ImageF image = greyImage(64, 36, 0.05f);
    paintDisc(image, 0.5f, 0.5f, 0.2f, 4.0f);
    AutoExposureSettings settings;
    settings.metering = MeteringMode::Center;
    const float centre = meterImage(image, settings);
    EXPECT_GT(centre, meterAverage(image));
    EXPECT_LT(centre, 4.0f);
    // A uniform image meters its value whatever the weights.
    EXPECT_NEAR(meterCenter(greyImage(64, 36, 0.3f)), 0.3f, 1e-6f);
}

TEST(Metering, MaskWeightsThePixels) {
    ImageF image = greyImage(8, 4, 0.1f);
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) {
            setGrey(image, x, y, 3.0f); // left half bright
        }
    }
    ImageF mask(2, 1); // stretched: left half white, right half black
    setGrey(mask, 0, 0, 1.0f);
    setGrey(mask, 1, 0, 0.0f);
    EXPECT_NEAR(meterMasked(image, mask), 3.0f, 1e-5f);
    setGrey(mask, 0, 0, 0.0f);
    setGrey(mask, 1, 0, 0.5f);
    EXPECT_NEAR(meterMasked(image, mask), 0.1f, 1e-6f);
    setGrey(mask, 1, 0, kNaN); // a NaN weight is 0: nothing left
    EXPECT_EQ(meterMasked(image, mask), 0.0f);

    AutoExposureSettings settings;
    settings.metering = MeteringMode::Mask;
    setGrey(mask, 0, 0, 1.0f);
    setGrey(mask, 1, 0, 1.0f);
    EXPECT_NEAR(meterImage(image, settings, &mask), meterAverage(image), 1e-6f);
    // No mask loaded: meters like average.
    EXPECT_EQ(meterImage(image, settings, nullptr), meterAverage(image));
}

TEST(Metering, MeterImageDispatchesOnTheMode) {
    ImageF image = greyImage(16, 16, 0.2f);
    paintDisc(image, 0.3f, 0.3f, 0.2f, 5.0f);
    AutoExposureSettings settings;
    EXPECT_EQ(meterImage(image, settings), meterAverage(image));
    settings.metering = MeteringMode::Histogram;
    const HistogramStats stats = histogramAverage(
        buildHistogram(image, settings.histogramLog2Min, settings.histogramLog2Max), 10.0f, 90.0f);
    EXPECT_EQ(meterImage(image, settings), std::exp2(stats.averageLog2));
    EXPECT_EQ(meterImage(ImageF{}, settings), 0.0f);
}

} // namespace
} // namespace photopic
