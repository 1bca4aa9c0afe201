// Bloom's glow of a point of light, in every mode and preset: how far from radially symmetric it is (the
// means of 8 sectors of each annulus, each pixel divided by the glow's radial profile at its own distance,
// against their mean) and whether it falls off monotonically from the core, wherever the point sits against
// the pixel grid, at several sizes and intensities, on dark and lit backgrounds and near a border. Measured
// on the scene-referred image (linear, exposure fixed) with bloom against the same without.
//
// A report, not yet a bound (disabled: run with --gtest_also_run_disabled_tests): the mip chain is not shift
// invariant, so a point off the coarse levels' grid gets an asymmetric glow, worst for sub-pixel points (a
// Karis-weighted, thresholded first level). Today (llvmpipe): realtime 28%, stills 362%, threshold with 5
// levels 105%, energy-conserving with 2 levels at radius 0.5 120% worst sector spread (sectors centred on the
// axes and diagonals); no annulus rises over the one inside it. The bound a round glow is held to is 10%.

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
    Settings tight = measured(Settings{});
    tight.bloom.radius = 0.5f;
    tight.bloom.mipCount = 2;
    out.push_back({"energy-conserving, 2 levels, radius 0.5", tight});
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

TEST_F(GlTest, DISABLED_BloomOfAPointRoundnessReport) {
    std::vector<Source> sources;
    for (const float radius : {0.7f, 2.5f})
        for (const float value : {100.0f, 2000.0f})
            for (const auto& [dx, dy] : {std::pair{0.0f, 0.0f}, {0.25f, 0.5f}, {0.5f, 0.5f}})
                for (const float background : {0.0f, 0.18f})
                    sources.push_back({.x = 80.0f + dx,
                                       .y = 80.0f + dy,
                                       .radius = radius,
                                       .value = value,
                                       .background = background});
    sources.push_back({.x = 10.3f, .y = 80.0f, .radius = 2.5f, .value = 2000.0f}); // near the left edge
    for (const Look& look : looks()) {
        Settings none = look.settings;
        none.bloom.enabled = false;
        double spread = 0.0;
        double rise = 0.0;
        for (const Source& s : sources) {
            const ImageF image = pointLight(s);
            const Figures f = measure(sceneReferred(look.settings, image), sceneReferred(none, image), s);
            EXPECT_GE(f.annuli, 2) << look.name << ": no glow around the point at (" << s.x << ", " << s.y
                                   << ")";
            if (f.worstSpread > 0.10 || f.worstRise > 0.02)
                std::printf(
                    "  %s: point at (%.2f, %.2f), radius %.1f, %g on %g: spread %.1f%%, rise %.1f%%\n",
                    look.name.c_str(), double(s.x), double(s.y), double(s.radius), double(s.value),
                    double(s.background), 100.0 * f.worstSpread, 100.0 * f.worstRise);
            spread = std::max(spread, f.worstSpread);
            rise = std::max(rise, f.worstRise);
        }
        std::printf("%s: worst sector spread %.1f%%, worst rise between annuli %.1f%% over %zu points\n",
                    look.name.c_str(), 100.0 * spread, 100.0 * rise, sources.size());
    }
}

} // namespace photopic::test
