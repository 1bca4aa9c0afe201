// output.bitDepth 16: the display domain (tone mapping and every pass after it) stores RGBA16, so a smooth
// ramp comes back with far more than 256 levels, and the same picture as the 8-bit path within its
// quantisation and dither.

#include "GlTest.h"

#include "gl/Capabilities.h"
#include "gl/StateScope.h"
#include "gl/TextureIo.h"
#include "passes/DisplayProgram.h"
#include "pipeline/Pipeline.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace photopic::test {

namespace {

/// 64x48 pixels, each a different grey in raster order from 0 to 1: 3072 levels in.
ImageF greyRamp() {
    ImageF image(64, 48);
    const float last = float(image.pixelCount() - 1);
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        const float v = float(i) / last;
        image.rgba[i * 4 + 0] = v;
        image.rgba[i * 4 + 1] = v;
        image.rgba[i * 4 + 2] = v;
        image.rgba[i * 4 + 3] = 1.0f;
    }
    return image;
}

struct Rendered {
    Image8 display8;
    Image16 display16;
};

/// The ramp through a pipeline at 8 and at 16 bits, everything else as `settings` says.
Rendered renderBoth(Settings settings) {
    settings.tonemapping.mode = ToneMapper::Linear; // display = the input: levels in, levels out
    settings.bloom.enabled = false;
    const ImageF input = greyRamp();
    Rendered out;
    for (const int bits : {8, 16}) {
        settings.output.bitDepth = bits;
        Pipeline pipeline({.settings = settings});
        const GlStateScope hostState;
        const Texture texture = makeTexture(input, "ramp");
        const Texture& display = pipeline.execute({.color = &texture}, {});
        EXPECT_EQ(display.format(), GLenum(bits == 16 ? GL_RGBA16 : GL_RGBA8));
        if (bits == 16) {
            out.display16 = readTexture16(display);
        } else {
            out.display8 = readTexture8(display);
        }
    }
    return out;
}

std::size_t distinctRedLevels(const Image16& image) {
    std::set<std::uint16_t> levels;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        levels.insert(image.rgba[i]);
    }
    return levels.size();
}

/// Largest and mean |16-bit - 8-bit| over RGB, in 8-bit code values.
std::pair<double, double> difference(const Rendered& r) {
    double largest = 0.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < r.display8.rgba.size(); ++i) {
        if (i % 4 == 3) {
            continue;
        }
        const double d = std::abs(double(r.display16.rgba[i]) / 65535.0 - double(r.display8.rgba[i]) / 255.0);
        largest = std::max(largest, d * 255.0);
        sum += d * 255.0;
    }
    return {largest, sum / (double(r.display8.rgba.size()) * 0.75)};
}

} // namespace

TEST_F(GlTest, SixteenBitDisplayHasMoreThan256LevelsAndMatchesEightBit) {
    const Rendered r = renderBoth(Settings{}); // the 8-bit side dithered, as by default
    ASSERT_EQ(r.display16.width, 64);
    ASSERT_EQ(r.display16.height, 48);
    // 3072 greys in; the sRGB encode spreads them over the code values, merging a few in the highlights.
    EXPECT_GT(distinctRedLevels(r.display16), 2000u);
    const auto [largest, mean] = difference(r);
    // The 8-bit value is the 16-bit one rounded (half a code value) after a TPDF dither of up to one code
    // value either way: 1.5 at most, 1/255 of rounding plus the dither's tolerance.
    EXPECT_LE(largest, 1.5 + 1e-3);
    EXPECT_LT(mean, 0.75);
}

TEST_F(GlTest, SixteenBitDisplayHoldsTheExactSrgbEncode) {
    // The shaders encode sRGB with a polynomial rather than pow() (passes/common/color.h.glsl). At 16 bits,
    // each of the ramp's 3072 greys comes back within 0.05 of a code of the exact encode past the half code
    // of rounding: an error of 7.6e-7 at most, where the polynomial's is 1.7e-7 and float arithmetic's about
    // as much. A fit of two degrees lower (error 2.1e-6) fails it (0.56 of a code off on one grey);
    // llvmpipe's pow() moves 7 greys to the next code, the polynomial 12.
    Settings settings;
    settings.output.dither = false;
    const Rendered r = renderBoth(settings);
    const ImageF input = greyRamp();
    int off = 0;
    for (std::size_t i = 0; i < input.pixelCount(); ++i) {
        const double v = input.rgba[i * 4];
        const double exact = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
        const double code = exact * 65535.0;
        const int got = r.display16.rgba[i * 4];
        ASSERT_LE(std::abs(double(got) - code), 0.5 + 0.05)
            << "grey " << v << ": exact " << code << ", got " << got;
        off += got != int(std::lround(code));
    }
    EXPECT_LE(off, 31) << "of 3072 greys off the rounded exact encode (1% allowed)";
    RecordProperty("offByOneCode", off);
}

TEST_F(GlTest, SixteenBitDisplayIsNotDithered) {
    Settings settings;
    settings.output.dither = true;
    const Rendered r = renderBoth(settings);
    // Without a dither the ramp is monotonic in raster order: noise of even one 16-bit step would break it
    // somewhere over 3072 pixels.
    int reversals = 0;
    for (std::size_t i = 4; i < r.display16.rgba.size(); i += 4) {
        reversals += r.display16.rgba[i] < r.display16.rgba[i - 4];
    }
    EXPECT_EQ(reversals, 0);
}

TEST_F(GlTest, EveryDisplayPassKeepsSixteenBits) {
    struct Case {
        std::string name;
        Settings settings;
    };
    std::vector<Case> cases(4);
    cases[0].name = "fxaa";
    cases[0].settings.aa.mode = AntiAliasing::Fxaa;
    cases[1].name = "smaa";
    cases[1].settings.aa.mode = AntiAliasing::Smaa;
    cases[2].name = "vignette";
    cases[2].settings.vignette.enabled = true;
    cases[3].name = "histogram overlay";
    cases[3].settings.debug.view = DebugView::Histogram;
    for (Case& c : cases) {
        c.settings.output.dither = false;
        const Rendered r = renderBoth(c.settings);
        // Each pass reads and writes RGBA16: a pass left at RGBA8 would cut the ramp to at most 256 levels.
        EXPECT_GT(distinctRedLevels(r.display16), 1000u) << c.name;
        // Undithered, the 8-bit image is rounded twice, half a code value each time: where the tone map
        // stores the display image and where the pass stores its result (of an input already rounded).
        EXPECT_LE(difference(r).first, 1.5 + 1e-3) << c.name;
    }
}

TEST_F(GlTest, SixteenBitSceneDebugViewIsSixteenBits) {
    Settings settings;
    settings.debug.view = DebugView::Luma;
    settings.output.bitDepth = 16;
    Pipeline pipeline({.settings = settings});
    const GlStateScope hostState;
    const Texture texture = makeTexture(greyRamp(), "ramp");
    const Texture& display = pipeline.execute({.color = &texture}, {});
    EXPECT_EQ(display.format(), GLenum(GL_RGBA16));
    EXPECT_GT(distinctRedLevels(readTexture16(display)), 1000u); // luma as grey: the ramp again
}

} // namespace photopic::test

namespace photopic::test {

// The display passes round to their code themselves only where the store might not (displayStoresRound: on
// GPUs). A software renderer's store rounds to nearest even, so forcing the rounding on there must change no
// bit of any display pass's output, at 8 and 16 bits, dithered or not: what lets it skip the instructions.
TEST_F(GlTest, DisplayRoundingChangesNoBitWhereTheStoreRoundsItself) {
    if (!isSoftwareRenderer()) {
        GTEST_SKIP() << "a GPU's store need not round to nearest even; the rounding is on there";
    }
    struct Case {
        std::string name;
        Settings settings;
    };
    std::vector<Case> cases(5);
    cases[0].name = "default";
    cases[1].name = "fxaa, grain, vignette";
    cases[1].settings.aa.mode = AntiAliasing::Fxaa;
    cases[1].settings.grain.enabled = true;
    cases[1].settings.vignette.enabled = true;
    cases[2].name = "smaa, agx";
    cases[2].settings.aa.mode = AntiAliasing::Smaa;
    cases[2].settings.tonemapping.mode = ToneMapper::Agx;
    cases[3].name = "histogram overlay";
    cases[3].settings.debug.view = DebugView::Histogram;
    cases[4].name = "ev view";
    cases[4].settings.debug.view = DebugView::Ev;
    ImageF input = greyRamp();
    for (std::size_t i = 0; i < input.pixelCount(); ++i) { // 0 to 8, past white, so bloom and curves bite
        for (int c = 0; c < 3; ++c) {
            input.rgba[i * 4 + std::size_t(c)] *= 8.0f * float(c + 1) / 3.0f;
        }
    }
    for (const Case& c : cases) {
        for (const int bits : {8, 16}) {
            Settings settings = c.settings;
            settings.output.bitDepth = bits;
            std::vector<std::uint16_t> images[2];
            for (const bool round : {false, true}) {
                forceDisplayRounding(round);
                Pipeline pipeline({.settings = settings});
                const Texture texture = makeTexture(input, "ramp past white");
                const Texture& display = pipeline.execute({.color = &texture}, {.dt = 0.1f, .frameIndex = 3});
                if (bits == 16) {
                    images[round ? 1 : 0] = readTexture16(display).rgba;
                } else {
                    const Image8 image = readTexture8(display);
                    images[round ? 1 : 0].assign(image.rgba.begin(), image.rgba.end());
                }
            }
            forceDisplayRounding(std::nullopt);
            EXPECT_FALSE(images[0].empty());
            EXPECT_EQ(images[0], images[1]) << c.name << ", " << bits << " bits";
        }
    }
}

} // namespace photopic::test
