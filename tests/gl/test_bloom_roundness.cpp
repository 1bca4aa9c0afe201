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

#include "GlTest.h"

#include "gl/TextureIo.h"
#include "pipeline/Pipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace photopic::test {

namespace {

constexpr int kSize = 160;

struct Source {
    float x = 80.0f; ///< centre, pixels (centres of pixels at +0.5)
    float y = 80.0f;
    float radius = 2.5f;
    float value = 2000.0f;
    float background = 0.0f;
};

/// The disc's coverage of each pixel, 8x8 supersampled, over the background.
ImageF pointLight(const Source& s) {
    ImageF image(kSize, kSize);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            int inside = 0;
            for (int j = 0; j < 8; ++j)
                for (int i = 0; i < 8; ++i)
                    inside += std::hypot(float(x) + (float(i) + 0.5f) / 8.0f - s.x,
                                         float(y) + (float(j) + 0.5f) / 8.0f - s.y) <= s.radius
                                  ? 1
                                  : 0;
            const float v = s.background + (s.value - s.background) * float(inside) / 64.0f;
            float* p = image.at(x, y);
            p[0] = p[1] = p[2] = v;
            p[3] = 1.0f;
        }
    }
    return image;
}

ImageF sceneReferred(const Settings& settings, const ImageF& image) {
    Pipeline pipeline({.settings = settings});
    const Texture input = makeTexture(image, "roundness input");
    pipeline.execute({.color = &input}, {});
    return readTextureF(pipeline.sceneReferred());
}

/// Fixed exposure, linear curve, no dither or AA: the scene-referred image is the scene and its bloom.
Settings measured(Settings s) {
    s.autoExposure.enabled = false;
    s.tonemapping.exposure = 0.0f;
    s.tonemapping.mode = ToneMapper::Linear;
    s.output.dither = false;
    s.aa.mode = AntiAliasing::None;
    return s;
}

struct Figures {
    double worstSpread = 0.0; ///< largest |sector mean - annulus mean| / annulus mean
    double worstRise = 0.0;   ///< largest rise of an annulus mean over the one inside it, relative
    int annuli = 0;
};

/// The glow (with bloom minus without) in 2-pixel annuli from the source's edge + 1 outwards, while it stays
/// above 1e-3 of the first annulus's. Each pixel's glow is divided by the radial profile at its own distance
/// (the mean over every direction of the pixels in a 0.25-pixel ring, interpolated), so that a perfectly
/// round glow gives 1 in every sector whatever pixel centres a sector holds; sectors reaching past the
/// image's edge are left out (there the profile comes from the rings' other pixels).
Figures measure(const ImageF& with, const ImageF& without, const Source& s) {
    constexpr float kBin = 0.25f;
    constexpr int kBins = 200; // 50 pixels
    std::vector<double> ringSum(kBins, 0.0);
    std::vector<int> ringCount(kBins, 0);
    const auto glow = [&](int x, int y) { return double(with.at(x, y)[1]) - double(without.at(x, y)[1]); };
    const auto radiusOf = [&](int x, int y) {
        return std::hypot(float(x) + 0.5f - s.x, float(y) + 0.5f - s.y);
    };
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const int bin = int(radiusOf(x, y) / kBin);
            if (bin < kBins) {
                ringSum[std::size_t(bin)] += glow(x, y);
                ++ringCount[std::size_t(bin)];
            }
        }
    }
    const auto profile = [&](float r) {
        // Linear between the centres of the rings that hold pixels on either side.
        const float t = r / kBin - 0.5f;
        int lo = std::clamp(int(std::floor(t)), 0, kBins - 1);
        int hi = std::clamp(lo + 1, 0, kBins - 1);
        while (lo > 0 && ringCount[std::size_t(lo)] == 0)
            --lo;
        while (hi < kBins - 1 && ringCount[std::size_t(hi)] == 0)
            ++hi;
        const double a =
            ringCount[std::size_t(lo)] ? ringSum[std::size_t(lo)] / ringCount[std::size_t(lo)] : 0.0;
        const double b =
            ringCount[std::size_t(hi)] ? ringSum[std::size_t(hi)] / ringCount[std::size_t(hi)] : a;
        const float w = hi == lo ? 0.0f : std::clamp((t - float(lo)) / float(hi - lo), 0.0f, 1.0f);
        return a + (b - a) * double(w);
    };
    Figures f;
    double first = 0.0;
    double previous = 0.0;
    for (float r0 = s.radius + 1.0f; r0 < 40.0f; r0 += 2.0f) {
        double ratio[8] = {};
        double sums = 0.0;
        int counts[8] = {};
        int total = 0;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                const float r = radiusOf(x, y);
                if (r < r0 || r >= r0 + 2.0f)
                    continue;
                const float dx = float(x) + 0.5f - s.x;
                const float dy = float(y) + 0.5f - s.y;
                // Sectors centred on the axes and the diagonals, where a square and a circle differ most.
                const int k = int((std::atan2(dy, dx) + 3.14159265f + 0.39269908f) / 6.2831853f * 8.0f) % 8;
                const double p = profile(r);
                ratio[k] += p > 0.0 ? glow(x, y) / p : 0.0;
                ++counts[k];
                sums += glow(x, y);
                ++total;
            }
        }
        bool clipped[8] = {};
        int n = 0;
        for (int k = 0; k < 8; ++k) {
            const float a = float(k) / 8.0f * 6.2831853f - 3.14159265f;
            const float ex = s.x + (r0 + 2.0f) * std::cos(a);
            const float ey = s.y + (r0 + 2.0f) * std::sin(a);
            clipped[k] = counts[k] == 0 || ex < 0.0f || ey < 0.0f || ex > float(kSize) || ey > float(kSize);
            n += clipped[k] ? 0 : 1;
        }
        const double mean = total ? sums / total : 0.0;
        if (n < 3)
            break;
        if (first == 0.0)
            first = mean;
        if (!(first > 0.0) || !(mean > 1e-3 * first))
            break;
        double meanRatio = 0.0;
        for (int k = 0; k < 8; ++k)
            meanRatio += clipped[k] ? 0.0 : ratio[k] / counts[k];
        meanRatio /= n;
        for (int k = 0; k < 8; ++k) {
            if (!clipped[k])
                f.worstSpread =
                    std::max(f.worstSpread, std::abs(ratio[k] / counts[k] - meanRatio) / meanRatio);
        }
        if (previous > 0.0)
            f.worstRise = std::max(f.worstRise, (mean - previous) / previous);
        previous = mean;
        ++f.annuli;
    }
    return f;
}

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
