// Test fixture for ocio.sh: how far a display PNG lies from the plain sRGB encoding of a scene-referred EXR.
//
//   photopic_ocio_fixture SCENE.exr DISPLAY.png
//
// Each colour channel of the scene image is clamped to [0, 1], encoded with the sRGB OETF (IEC 61966-2-1) and
// scaled to 255; printed: maxdiff and meandiff, the largest and the mean absolute difference from the PNG's
// stored bytes in code values, over every colour channel of every pixel.

#include "FixtureMain.h"
#include "core/Color.h"
#include "io/ImageIO.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

namespace {

double srgbCodeValue(float linear) {
    return 255.0 * photopic::srgbEncode(linear); // clamps to [0, 1] first
}

int run(const char* scenePath, const char* displayPath) {
    const photopic::ImageF scene = photopic::readImage(scenePath);
    const photopic::Image8 display = photopic::readPng8(displayPath);
    if (scene.width != display.width || scene.height != display.height) {
        std::fprintf(stderr, "the two images differ in size\n");
        return 1;
    }
    double maxDiff = 0.0, sum = 0.0;
    for (int y = 0; y < scene.height; ++y) {
        for (int x = 0; x < scene.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double d = std::abs(srgbCodeValue(scene.at(x, y)[c]) - double(display.at(x, y)[c]));
                maxDiff = std::max(maxDiff, d);
                sum += d;
            }
        }
    }
    std::printf("maxdiff=%.3f meandiff=%.4f\n", maxDiff, sum / (3.0 * scene.width * scene.height));
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return photopic::test::fixtureMain(argc, argv, 2, "SCENE.exr DISPLAY.png",
                                       [&] { return run(argv[1], argv[2]); });
}
