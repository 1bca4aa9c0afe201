// Test fixture for volumetric_light.sh: reads the `volumetric-light` debug view's EXR (RGB: the light the
// pass added, raw values) and the frame's scene EXR (the colour the host rendered), and prints figures for
// the script to check.
//
//   photopic_volumetric_light_fixture VIEW.exr SCENE.exr
//
// sun: the brightest pixel of the scene's colour when it is the sun's disc (luminance above 1000; the
// testbed's sun has about 8000), else "none"; ring1, ring2, ring3: the view's mean luminance at 5-15%, 15-35%
// and 35-70% of the image height from the sun (the rays' falloff bands); mean and max: over the image;
// peakdist: pixels from the sun to the view's brightest pixel; then "range=ok" or "range=bad" (every value
// finite and not negative).

#include "FixtureMain.h"
#include "io/ImageIO.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

namespace {

using photopic::ImageF;

double luminance(const float* c) {
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

constexpr double kSunLuminance = 1000.0;

int run(const char* viewPath, const char* scenePath) {
    const ImageF view = photopic::readImage(viewPath);
    const ImageF scene = photopic::readImage(scenePath);
    if (view.width != scene.width || view.height != scene.height) {
        std::fprintf(stderr, "the two images differ in size\n");
        return 1;
    }
    bool inRange = true;
    double sum = 0.0, peak = 0.0, sceneMax = 0.0;
    int peakX = 0, peakY = 0, sunX = 0, sunY = 0;
    for (int y = 0; y < view.height; ++y) {
        for (int x = 0; x < view.width; ++x) {
            const float* v = view.at(x, y);
            for (int c = 0; c < 3; ++c) {
                inRange = inRange && std::isfinite(v[c]) && v[c] >= 0.0f;
            }
            const double l = luminance(v);
            sum += l;
            if (l > peak) {
                peak = l;
                peakX = x;
                peakY = y;
            }
            const double s = luminance(scene.at(x, y));
            if (s > sceneMax) {
                sceneMax = s;
                sunX = x;
                sunY = y;
            }
        }
    }
    std::printf("mean=%.6g max=%.6g range=%s\n", sum / double(view.width * view.height), peak,
                inRange ? "ok" : "bad");
    if (sceneMax < kSunLuminance) {
        std::printf("sun=none\n");
        return 0;
    }
    const double h = view.height;
    const double bands[4] = {0.05 * h, 0.15 * h, 0.35 * h, 0.7 * h};
    double ring[3] = {}, count[3] = {};
    for (int y = 0; y < view.height; ++y) {
        for (int x = 0; x < view.width; ++x) {
            const double r = std::hypot(double(x - sunX), double(y - sunY));
            for (int b = 0; b < 3; ++b) {
                if (r >= bands[b] && r < bands[b + 1]) {
                    ring[b] += luminance(view.at(x, y));
                    count[b] += 1.0;
                }
            }
        }
    }
    std::printf("sun=%d,%d peakdist=%.2f ring1=%.6g ring2=%.6g ring3=%.6g\n", sunX, sunY,
                std::hypot(double(peakX - sunX), double(peakY - sunY)), ring[0] / std::max(count[0], 1.0),
                ring[1] / std::max(count[1], 1.0), ring[2] / std::max(count[2], 1.0));
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return photopic::test::fixtureMain(argc, argv, 2, "VIEW.exr SCENE.exr",
                                       [&] { return run(argv[1], argv[2]); });
}
