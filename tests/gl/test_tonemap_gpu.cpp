// GPU tone mapping against the CPU source of truth (core/ToneCurves.cpp), every operator, dense input grid.

#include "GlTest.h"

#include "core/Color.h"
#include "core/ToneCurves.h"
#include "gl/TextureIo.h"
#include "pipeline/Pipeline.h"

#include <cmath>

namespace photopic::test {

namespace {

/// Grey and coloured inputs over 0..64 (log-spaced) plus exact 0 and saturated primaries.
ImageF denseGrid(int width, int height) {
    ImageF image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float t = float(x) / float(width - 1);
            const float base = x == 0 ? 0.0f : std::exp2(-12.0f + 18.0f * t); // 2^-12 .. 64
            float* p = image.at(x, y);
            // Rows: grey, then colour ratios that exercise hue handling (ACES, AgX, Neutral are not
            // per-channel).
            const float ratios[8][3] = {{1, 1, 1},       {1, 0, 0},       {0, 1, 0},     {0, 0, 1},
                                        {1, 0.5f, 0.1f}, {0.2f, 0.6f, 1}, {1, 1, 0.02f}, {0.05f, 0.3f, 0.3f}};
            const auto& r = ratios[y % 8];
            p[0] = base * r[0];
            p[1] = base * r[1];
            p[2] = base * r[2];
            p[3] = 1;
        }
    }
    return image;
}

int expected8(float linearDisplay) {
    return int(std::lround(srgbEncode(std::clamp(linearDisplay, 0.0f, 1.0f)) * 255.0f));
}

} // namespace

class TonemapGpuTest : public GlTest, public ::testing::WithParamInterface<ToneMapper> {};

TEST_P(TonemapGpuTest, MatchesCpuWithinOneCodeValue) {
    const ImageF input = denseGrid(256, 16);
    Settings settings;
    settings.tonemapping.mode = GetParam();
    settings.output.dither = false; // the comparison is of the curve, not of the noise
    settings.bloom.enabled = false; // nor of the glare, which is on by default
    Pipeline pipeline({.settings = settings});
    ASSERT_EQ(pipeline.capabilities().path, ColorPath::Hdr);
    const Image8 out = processImage(pipeline, input);

    const ToneCurveParams params{.whitePoint = settings.tonemapping.whitePoint,
                                 .agxLook = settings.tonemapping.agxLook};
    int worst = 0;
    for (int y = 0; y < input.height; ++y) {
        for (int x = 0; x < input.width; ++x) {
            const float* in = input.at(x, y);
            // The HDR path stores the sanitised input as half float (relative error 2^-11): far inside 1/255.
            const glm::vec3 c = toneMap(GetParam(), {in[0], in[1], in[2]}, params);
            const std::uint8_t* got = out.at(x, y);
            for (int ch = 0; ch < 3; ++ch) {
                const int diff = std::abs(int(got[ch]) - expected8(c[ch]));
                worst = std::max(worst, diff);
                ASSERT_LE(diff, 1) << toneMapperName(GetParam()) << " at (" << x << ", " << y << ") ch " << ch
                                   << " input " << in[ch] << " expected " << expected8(c[ch]) << " got "
                                   << int(got[ch]);
            }
        }
    }
    RecordProperty("worstCodeValueDifference", worst);
}

INSTANTIATE_TEST_SUITE_P(EveryOperator, TonemapGpuTest,
                         ::testing::Values(ToneMapper::Linear, ToneMapper::Reinhard,
                                           ToneMapper::ReinhardExtended, ToneMapper::Hable,
                                           ToneMapper::Lottes, ToneMapper::Uchimura,
                                           ToneMapper::AcesNarkowicz, ToneMapper::AcesFitted,
                                           ToneMapper::Aces, ToneMapper::Agx, ToneMapper::Neutral),
                         [](const auto& info) {
                             std::string name(toneMapperName(info.param));
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

TEST_F(GlTest, AgxLooksMatchCpu) {
    const ImageF input = denseGrid(128, 8);
    for (AgxLook look : {AgxLook::Punchy, AgxLook::Golden}) {
        Settings settings;
        settings.tonemapping.mode = ToneMapper::Agx;
        settings.tonemapping.agxLook = look;
        settings.output.dither = false;
        settings.bloom.enabled = false;
        Pipeline pipeline({.settings = settings});
        const Image8 out = processImage(pipeline, input);
        for (int y = 0; y < input.height; ++y) {
            for (int x = 0; x < input.width; ++x) {
                const float* in = input.at(x, y);
                const glm::vec3 c = toneMap(ToneMapper::Agx, {in[0], in[1], in[2]}, {.agxLook = look});
                for (int ch = 0; ch < 3; ++ch) {
                    ASSERT_LE(std::abs(int(out.at(x, y)[ch]) - expected8(c[ch])), 1) << agxLookName(look);
                }
            }
        }
    }
}

} // namespace photopic::test
