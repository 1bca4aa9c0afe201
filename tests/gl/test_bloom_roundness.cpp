// Bloom's glow of a point of light, in every mode, preset and quality tier that runs the chain: radially
// symmetric (the means of 8 sectors of each annulus within 10% of their mean, each pixel divided by the
// glow's radial profile at its own distance), falling off monotonically from the core, and leaving the core
// to the source's own pixels, wherever the point sits against the pixel grid, at several sizes and
// intensities, on dark and lit backgrounds and near a border. Measured on the scene-referred image (linear,
// exposure fixed) with bloom against the same without (tests/gl/PointGlow.h).

#include "PointGlow.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace photopic::test {

using namespace glow;

namespace {

struct Look {
    std::string name;
    Settings settings;
};

std::vector<Look> looks() {
    std::vector<Look> out;
    out.push_back({"realtime", measured(Settings{})});
    Settings stills;
    stills.applyLook(Settings::stills());
    out.push_back({"stills", measured(stills)});
    Settings threshold5 = measured(stills);
    threshold5.bloom.mipCount = 5;
    out.push_back({"threshold, 5 levels", threshold5});
    Settings oneLevel = measured(stills);
    oneLevel.bloom.mipCount = 1;
    oneLevel.bloom.intensity = 3.0f;
    out.push_back({"threshold, 1 level, intensity 3", oneLevel});
    Settings tight = measured(Settings{});
    tight.bloom.radius = 0.5f;
    tight.bloom.mipCount = 2;
    out.push_back({"energy-conserving, 2 levels, radius 0.5", tight});
    for (const float radius : {0.0f, 1.0f}) {
        Settings r = measured(Settings{});
        r.bloom.radius = radius;
        out.push_back({radius == 0.0f ? "energy-conserving, radius 0" : "energy-conserving, radius 1", r});
    }
    Settings medium = measured(Settings{});
    medium.quality = Quality::Medium; // level 0 a quarter of the frame
    out.push_back({"quality medium", medium});
    Settings lowStills = measured(stills);
    lowStills.quality = Quality::Low;
    out.push_back({"stills, quality low", lowStills});
    return out;
}

std::vector<Source> sources() {
    std::vector<Source> out;
    for (const float radius : {0.7f, 2.5f})
        for (const float value : {100.0f, 2000.0f})
            for (const auto& [dx, dy] : {std::pair{0.0f, 0.0f}, {0.25f, 0.5f}, {0.5f, 0.5f}, {3.3f, 1.75f}})
                for (const float background : {0.0f, 0.18f})
                    out.push_back({.x = 80.0f + dx,
                                   .y = 80.0f + dy,
                                   .radius = radius,
                                   .value = value,
                                   .background = background});
    out.push_back({.x = 10.3f, .y = 80.0f, .radius = 2.5f, .value = 2000.0f});   // near the left edge
    out.push_back({.x = 150.6f, .y = 6.2f, .radius = 0.7f, .value = 2000.0f});   // near a corner
    return out;
}

} // namespace

// The measure itself: an analytic round glow added to the point reads as round wherever the point sits, a
// square one (a function of the larger of |dx| and |dy|) as far from it.
TEST(BloomRoundnessMeasure, SeesARoundGlowAsRoundAndASquareOneAsNot) {
    for (const auto& [dx, dy] : {std::pair{0.0f, 0.0f}, {0.25f, 0.5f}, {0.5f, 0.5f}}) {
        const Source s{.x = 80.0f + dx, .y = 80.0f + dy, .radius = 0.7f, .value = 100.0f};
        const ImageF point = pointLight(s);
        ImageF round = point;
        ImageF square = point;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                const float ox = float(x) + 0.5f - s.x;
                const float oy = float(y) + 0.5f - s.y;
                for (int c = 0; c < 3; ++c) {
                    round.at(x, y)[c] += 10.0f * std::exp(-std::hypot(ox, oy) / 4.0f);
                    square.at(x, y)[c] += 10.0f * std::exp(-std::max(std::abs(ox), std::abs(oy)) / 4.0f);
                }
            }
        }
        const Figures r = measure(round, point, s);
        const Figures q = measure(square, point, s);
        EXPECT_GE(r.annuli, 5);
        EXPECT_LE(r.worstSpread, 0.02) << dx << ", " << dy;
        EXPECT_LE(r.worstRise, 0.0);
        EXPECT_GT(q.worstSpread, 0.10) << dx << ", " << dy;
    }
}

TEST_F(GlTest, BloomOfAPointIsRoundEverywhereInEveryLook) {
    const std::vector<Source> points = sources();
    for (const Look& look : looks()) {
        Settings none = look.settings;
        none.bloom.enabled = false;
        double spread = 0.0;
        for (const Source& s : points) {
            const ImageF image = pointLight(s);
            const ImageF with = sceneReferred(look.settings, image);
            const ImageF without = sceneReferred(none, image);
            const Figures f = measure(with, without, s);
            const std::string where = look.name + ": point at (" + std::to_string(s.x) + ", " +
                                      std::to_string(s.y) + "), radius " + std::to_string(s.radius) + ", " +
                                      std::to_string(s.value) + " on " + std::to_string(s.background);
            EXPECT_GE(f.annuli, 2) << where << ": no glow around the point";
            EXPECT_LE(f.worstSpread, 0.10) << where;
            EXPECT_LE(f.worstRise, 0.01) << where;
            if (look.settings.bloom.mode == BloomMode::Threshold && s.value >= 2000.0f && s.background == 0.0f) {
                // The core is the source's own pixels: the glow it adds there is a small part of what the
                // intensity hands out, not a plateau that replaces it.
                const int cx = int(s.x), cy = int(s.y);
                EXPECT_LT(with.at(cx, cy)[1] - without.at(cx, cy)[1],
                          0.25f * look.settings.bloom.intensity * without.at(cx, cy)[1])
                    << where;
            }
            spread = std::max(spread, f.worstSpread);
        }
        std::printf("%s: worst sector spread %.1f%% over %zu points\n", look.name.c_str(), 100.0 * spread,
                    points.size());
    }
}

} // namespace photopic::test
