// Test fixture for veil.sh: how far bloom spreads over a display image. Reads the display image with bloom
// on, the same with bloom off (PNG, sRGB) and the scene-referred input it came from, and prints figures for
// the script to check.
//
//   photopic_veil_fixture ON.png OFF.png INPUT.exr
//
// Each pixel's display luminance is the relative luminance of its decoded colour, encoded back with the sRGB
// OETF as a code value of 255, so a rise is what a viewer sees on the display. Printed:
//   veil      fraction of the frame whose display luminance rises by more than 2 code values with bloom on
//   meanrise  mean rise over the frame, code values
//   glint     mean rise of the pixels next to the input's brightest pixel (between 1% and 3% of the image
//             height from it) that are not already white without bloom, code values: the highlight's own
//             bloom
//   peak      the brightest input pixel (x, y) and its luminance

#include "FixtureMain.h"
#include "core/Color.h"
#include "io/ImageIO.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

namespace {

using photopic::ImageF;

constexpr double kRiseCodeValues = 2.0;

double luminance(const float* c) {
    return photopic::luma709({c[0], c[1], c[2]});
}

/// Linear luminance as an sRGB code value in [0, 255].
double codeValue(double linear) {
    return 255.0 * photopic::srgbEncode(float(linear));
}

int run(const char* onPath, const char* offPath, const char* inputPath) {
    const ImageF on = photopic::readImage(onPath);
    const ImageF off = photopic::readImage(offPath);
    const ImageF input = photopic::readImage(inputPath);
    if (on.width != off.width || on.height != off.height || on.width != input.width ||
        on.height != input.height) {
        std::fprintf(stderr, "the three images differ in size\n");
        return 1;
    }
    double peak = -1.0;
    int peakX = 0, peakY = 0;
    for (int y = 0; y < input.height; ++y) {
        for (int x = 0; x < input.width; ++x) {
            const double l = luminance(input.at(x, y));
            if (std::isfinite(l) && l > peak) {
                peak = l;
                peakX = x;
                peakY = y;
            }
        }
    }
    const double inner = 0.01 * on.height;
    const double outer = 0.03 * on.height;
    std::size_t veiled = 0, glintCount = 0;
    double riseSum = 0.0, glintSum = 0.0;
    for (int y = 0; y < on.height; ++y) {
        for (int x = 0; x < on.width; ++x) {
            const double before = codeValue(luminance(off.at(x, y)));
            const double rise = codeValue(luminance(on.at(x, y))) - before;
            veiled += rise > kRiseCodeValues ? 1 : 0;
            riseSum += rise;
            const double d = std::hypot(double(x - peakX), double(y - peakY));
            if (d >= inner && d <= outer && before < 250.0) {
                glintSum += rise;
                ++glintCount;
            }
        }
    }
    const double pixels = double(on.width) * double(on.height);
    std::printf("veil=%.4f meanrise=%.3f glint=%.2f glintpixels=%zu peak=%d,%d,%.4g\n",
                double(veiled) / pixels, riseSum / pixels, glintCount ? glintSum / double(glintCount) : 0.0,
                glintCount, peakX, peakY, peak);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return photopic::test::fixtureMain(argc, argv, 3, "ON.png OFF.png INPUT.exr",
                                       [&] { return run(argv[1], argv[2], argv[3]); });
}
