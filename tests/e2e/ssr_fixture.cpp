// Test fixture for ssr.sh: reads the `ssr` debug view's EXR (RGB: the reflected radiance, A: the confidence,
// raw values) and the testbed's `reflection` truth (RGB: the mirror ray's radiance, A: 1 on metals), and
// prints figures for the script to check.
//
//   photopic_ssr_fixture VIEW.exr REFLECTION.exr OBJECTID.exr
//
// metal: pixels of the mirror strip (object id 3, roughness 0.05) the truth marks (A = 1); the rougher metals
// (poles, wires) are left out, their reflections being glossy where the truth is a mirror's; covered: those
// with a confidence above 0; within10: the fraction of covered pixels whose luminance is within 10% of the
// truth's; then "range=ok" or "range=bad" (every value finite, confidences in [0, 1]).

#include "FixtureMain.h"
#include "io/ImageIO.h"

#include <cmath>
#include <cstdio>
#include <exception>

namespace {

using photopic::ImageF;

double luminance(const float* c) {
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

/// The testbed's mirror strip.
constexpr float kStripId = 3.0f;

int run(const char* viewPath, const char* truthPath, const char* idPath) {
    const ImageF view = photopic::readImage(viewPath);
    const ImageF truth = photopic::readImage(truthPath);
    const ImageF ids = photopic::readImage(idPath);
    if (view.width != truth.width || view.height != truth.height || ids.width != view.width ||
        ids.height != view.height) {
        std::fprintf(stderr, "the three images differ in size\n");
        return 1;
    }
    long metal = 0, covered = 0, within = 0, confident = 0;
    bool inRange = true;
    for (int y = 0; y < view.height; ++y) {
        for (int x = 0; x < view.width; ++x) {
            const float* v = view.at(x, y);
            for (int c = 0; c < 4; ++c) {
                inRange = inRange && std::isfinite(v[c]);
            }
            inRange = inRange && v[3] >= 0.0f && v[3] <= 1.0f;
            confident += v[3] > 0.0f ? 1 : 0;
            if (truth.at(x, y)[3] < 0.5f || ids.at(x, y)[0] != kStripId) {
                continue;
            }
            ++metal;
            if (v[3] > 0.0f) {
                ++covered;
                const double t = luminance(truth.at(x, y));
                within += std::abs(luminance(v) - t) <= 0.1 * t ? 1 : 0;
            }
        }
    }
    std::printf("metal=%ld covered=%ld within10=%.4f confident=%ld\n", metal, covered,
                covered ? double(within) / double(covered) : 0.0, confident);
    std::printf("range=%s\n", inRange ? "ok" : "bad");
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return photopic::test::fixtureMain(argc, argv, 3, "VIEW.exr REFLECTION.exr OBJECTID.exr",
                                       [&] { return run(argv[1], argv[2], argv[3]); });
}
