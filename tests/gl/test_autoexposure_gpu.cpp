// Auto exposure through the whole GPU pipeline: adaptation against the model, GPU vs
// CPU ExposureController over a scripted sequence, histogram metering, non-finite input, and three
// readback tests (caching and continuity, auto trigger with auto exposure off, no accumulation).

#include "GlCallAudit.h"
#include "GlTest.h"

#include "core/ExposureController.h"
#include "core/Metering.h"
#include "gl/TextureIo.h"
#include "pipeline/Pipeline.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>

namespace photopic::test {

namespace {

constexpr int kSize = 8; // llvmpipe is slow; adaptation does not care about the image size

ImageF greyImage(int w, int h, float value) {
    ImageF image(w, h, value);
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) {
        image.rgba[i] = 1.0f;
    }
    return image;
}

Settings autoSettings(AdaptationMode mode = AdaptationMode::Exponential) {
    Settings s;
    s.tonemapping.mode = ToneMapper::Linear;
    s.output.dither = false;
    s.autoExposure.enabled = true;
    s.autoExposure.metering = MeteringMode::Average;
    s.autoExposure.adaptation = mode;
    s.autoExposure.minEV = -10.0f; // 0.02 and 2.0 both inside: targets are not clamped
    s.autoExposure.maxEV = 10.0f;
    return s;
}

/// Runs uniform frames of the given luminances and frame times; one telemetry record per frame.
class Sequence {
public:
    explicit Sequence(const Settings& settings)
        : mPipeline({.settings = settings, .keepTelemetryHistory = true}) {}

    void frame(float luminance, float dt) {
        auto it = mTextures.find(luminance);
        if (it == mTextures.end()) {
            it = mTextures.emplace(luminance, makeTexture(greyImage(kSize, kSize, luminance), "grey")).first;
        }
        mPipeline.execute({.color = &it->second}, {.dt = dt, .frameIndex = mFrame++});
    }
    std::vector<ExposureTelemetry> drain() { return mPipeline.drainTelemetry(); }
    Pipeline& pipeline() { return mPipeline; }

private:
    Pipeline mPipeline;
    std::map<float, Texture> mTextures;
    std::uint64_t mFrame = 0;
};

/// The half-float value the sanitise pass stores for v (the GPU meters that); glm rounds to nearest, as GL's
/// float-to-half conversion on store does.
float asHalf(float v) {
    return glm::unpackHalf1x16(glm::packHalf1x16(v));
}

struct StepCase {
    AdaptationMode mode;
    float from, to;
};

/// Distance to the target after t seconds from distance g0, per adaptation model (core/ExposureController.h).
double modelRemaining(const AutoExposureSettings& s, AdaptationMode mode, double g0, bool rising, double t) {
    switch (mode) {
    case AdaptationMode::Exponential:
        return g0 * std::exp(-t / (rising ? s.tauBrighten : s.tauDarken));
    case AdaptationMode::Speed:
        return g0 * std::exp(-(rising ? s.speedDown : s.speedUp) * t);
    case AdaptationMode::Hybrid: {
        const double speed = rising ? s.speedDown : s.speedUp;
        const double d = s.transitionEV;
        const double tl = g0 > d ? (g0 - d) / speed : 0.0;
        if (t <= tl) {
            return g0 - speed * t;
        }
        return std::min(g0, d) * std::exp(-(speed / d) * (t - tl));
    }
    }
    return 0.0;
}

std::string modeName(AdaptationMode mode) {
    return std::string(adaptationModeNames()[std::size_t(mode)]);
}
std::string stepCaseName(const ::testing::TestParamInfo<StepCase>& info) {
    return modeName(info.param.mode) + (info.param.from < info.param.to ? "_brighter" : "_darker");
}
std::string adaptationName(const ::testing::TestParamInfo<AdaptationMode>& info) {
    return modeName(info.param);
}

} // namespace

class StepResponseTest : public GlTest, public ::testing::WithParamInterface<StepCase> {};

TEST_P(StepResponseTest, FollowsTheModel) {
    const StepCase c = GetParam();
    const Settings settings = autoSettings(c.mode);
    const AutoExposureSettings& ae = settings.autoExposure;
    const float dt = 1.0f / 30.0f;
    // 12 s after the step: the slowest case (hybrid at speedDown 1 EV/s over 6.6 EV, then exponential)
    // settles.
    const int before = 10, after = 360;
    Sequence seq(settings);
    for (int i = 0; i < before; ++i) {
        seq.frame(c.from, dt);
    }
    for (int i = 0; i < after; ++i) {
        seq.frame(c.to, dt);
    }
    const auto t = seq.drain();
    ASSERT_EQ(t.size(), std::size_t(before + after));
    // The GPU's targets (of the half-float sanitised input) are the model's. They match core's target formula
    // within 2e-3 EV: llvmpipe's log2/exp2 are not correctly rounded (about 1e-3 EV here).
    const float startTarget = t[0].targetLog2;
    const float endTarget = t[before].targetLog2;
    EXPECT_NEAR(startTarget, exposureTargetLog2(ae, asHalf(c.from)), 2e-3f);
    EXPECT_NEAR(endTarget, exposureTargetLog2(ae, asHalf(c.to)), 2e-3f);
    // The first frame snaps to its target and stays there while the scene does.
    EXPECT_EQ(t[0].appliedLog2, startTarget);
    EXPECT_TRUE(t[0].initialized);
    EXPECT_NEAR(t[before - 1].appliedLog2, startTarget, 1e-6f);

    const bool rising = endTarget > startTarget;
    const double g0 = std::abs(double(endTarget) - double(startTarget));
    for (int i = 0; i < after; ++i) {
        const ExposureTelemetry& f = t[std::size_t(before + i)];
        const double elapsed = double(i + 1) * dt; // frame `before` adapts over its own dt
        const double remaining = std::abs(double(endTarget) - double(f.appliedLog2));
        const double expected = modelRemaining(ae, c.mode, g0, rising, elapsed);
        if (expected > 0.1 * ae.deadbandEV) { // below the deadband's exit the state legitimately stops
            EXPECT_NEAR(remaining, expected, 1e-3) << "frame " << i << " after the step";
        }
        EXPECT_FLOAT_EQ(f.exposure, std::exp2(f.appliedLog2));
    }
    if (c.mode == AdaptationMode::Exponential) {
        // After one time constant the applied exposure has covered 63% of the gap (within 5%).
        const double tau = rising ? ae.tauBrighten : ae.tauDarken;
        const int frames = int(std::lround(tau / dt));
        const double covered = (double(t[std::size_t(before + frames - 1)].appliedLog2) - startTarget) /
                               (endTarget - startTarget);
        EXPECT_NEAR(covered, 1.0 - std::exp(-1.0), 0.05 * (1.0 - std::exp(-1.0)));
    }
    EXPECT_NEAR(t.back().appliedLog2, endTarget, 0.05f) << "settled within 0.05 EV";
}

INSTANTIATE_TEST_SUITE_P(Adaptation, StepResponseTest,
                         ::testing::Values(StepCase{AdaptationMode::Exponential, 0.02f, 2.0f},
                                           StepCase{AdaptationMode::Exponential, 2.0f, 0.02f},
                                           StepCase{AdaptationMode::Speed, 0.02f, 2.0f},
                                           StepCase{AdaptationMode::Speed, 2.0f, 0.02f},
                                           StepCase{AdaptationMode::Hybrid, 0.02f, 2.0f},
                                           StepCase{AdaptationMode::Hybrid, 2.0f, 0.02f}),
                         stepCaseName);

class GpuCpuAgreementTest : public GlTest, public ::testing::WithParamInterface<AdaptationMode> {};

TEST_P(GpuCpuAgreementTest, ScriptedSequenceWithin1e3EV) {
    Settings settings = autoSettings(GetParam());
    settings.autoExposure.compensationEV = 0.5f;
    settings.autoExposure.compensationCurve = {{-8.0f, 1.0f}, {0.0f, 0.0f}, {4.0f, -0.5f}};
    settings.autoExposure.minEV = -4.0f; // some targets clamp
    settings.autoExposure.maxEV = 6.0f;
    settings.autoExposure.deadbandEV = 0.05f;
    settings.tonemapping.exposure = -0.5f;
    Sequence seq(settings);
    ExposureController cpu(settings.autoExposure);
    constexpr int kFrames = 300;
    std::vector<float> scripted;
    for (int i = 0; i < kFrames; ++i) {
        // Steps both ways, a slow log-space sine, a plateau for the deadband, wildly varying frame times
        // (0, beyond maxDt, 144 Hz) and a camera cut at frame 200.
        float stops = i < 40    ? -6.0f
                      : i < 80  ? 3.0f
                      : i < 120 ? -1.0f
                      : i < 170 ? 2.0f * std::sin(float(i) * 0.1f)
                      : i < 230 ? 0.02f
                                : -9.0f;
        const float luminance = std::exp2(stops);
        const float dt = i % 17 == 0 ? 0.0f : i % 23 == 0 ? 0.25f : i % 3 == 0 ? 1.0f / 144.0f : 1.0f / 30.0f;
        if (i == 200) {
            seq.pipeline().resetExposure();
        }
        seq.frame(luminance, dt);
        scripted.push_back(dt);
    }
    const auto gpu = seq.drain();
    ASSERT_EQ(gpu.size(), std::size_t(kFrames));
    double worst = 0.0;
    for (int i = 0; i < kFrames; ++i) {
        const ExposureTelemetry& g = gpu[std::size_t(i)];
        if (i == 200) {
            cpu.reset();
        }
        // Both controllers take the GPU's own metered luminance, so only the adaptation math is compared.
        const ExposureState& c =
            cpu.update(g.frameLuminance, scripted[std::size_t(i)], settings.tonemapping.exposure);
        ASSERT_EQ(g.frame, std::uint64_t(i));
        EXPECT_NEAR(g.targetLog2, c.targetLog2, 1e-3f) << "frame " << i;
        EXPECT_NEAR(g.appliedLog2, c.appliedLog2, 1e-3f) << "frame " << i;
        EXPECT_NEAR(std::log2(g.exposure), std::log2(c.exposure), 1e-3f) << "frame " << i;
        EXPECT_EQ(g.initialized, c.initialized != 0) << "frame " << i;
        worst = std::max(worst, double(std::abs(g.appliedLog2 - c.appliedLog2)));
    }
    RecordProperty("worst_applied_difference_ev", std::to_string(worst));
    EXPECT_NEAR(gpu[200].appliedLog2, gpu[200].targetLog2, 1e-5f) << "resetExposure snaps";
}

INSTANTIATE_TEST_SUITE_P(Adaptation, GpuCpuAgreementTest,
                         ::testing::Values(AdaptationMode::Exponential, AdaptationMode::Speed,
                                           AdaptationMode::Hybrid),
                         adaptationName);

TEST_F(GlTest, HistogramMeteringIgnoresAHotArea) {
    // 85% of the frame at 0.1, 15% at 1000 (bright sky, lamps). The geometric mean is pulled ~2 stops up.
    // With the default 10/90 window, 5 of the window's 80 percentage points still fall on the hot pixels
    // (they hold 85..100%), so the histogram mean moves ~0.8 stop, much less than the mean but not zero;
    // with highPercent 80 (anything <= 85) the window holds no hot pixel and the reading is the bulk's.
    const int w = 40, h = 20;
    ImageF image = greyImage(w, h, 0.1f);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < 6; ++x) { // 6 of 40 columns = 15%
            image.at(x, y)[0] = image.at(x, y)[1] = image.at(x, y)[2] = 1000.0f;
        }
    }
    const Texture input = makeTexture(image, "hot");
    const auto meter = [&](MeteringMode mode, float highPercent) {
        Settings s = autoSettings();
        s.autoExposure.metering = mode;
        s.autoExposure.highPercent = highPercent;
        Pipeline p({.settings = s, .keepTelemetryHistory = true});
        p.execute({.color = &input}, {});
        return p.drainTelemetry().at(0).frameLuminance;
    };
    const float bulk = std::log2(0.1f);
    const float mean = std::log2(meter(MeteringMode::Average, 90.0f));
    const float defaults = std::log2(meter(MeteringMode::Histogram, 90.0f));
    const float strict = std::log2(meter(MeteringMode::Histogram, 80.0f));
    EXPECT_GT(mean - bulk, 1.9f) << "the geometric mean follows the hot area";
    EXPECT_LT(defaults - bulk, 1.0f) << "10/90 leaves 5 points of the window on the hot area";
    EXPECT_LT(defaults - bulk, 0.5f * (mean - bulk));
    const float binWidth = (16.0f - -12.0f) / 254.0f;
    EXPECT_NEAR(strict, bulk, binWidth) << "10/80 ignores the hot area";
}

// The adaptation pass's histogram statistics (one bin per invocation, an integer scan, the float sums in bin
// order) are the CPU's histogramAverage to the bit: the count, both percentile bins and the window's mean,
// over a frame whose luminances spread across the histogram's range, for three windows.
TEST_F(GlTest, HistogramStatisticsOnTheGpuAreTheCpusToTheBit) {
    const int w = 97, h = 61;
    ImageF image(w, h);
    std::uint32_t state = 12345u;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            state = state * 1664525u + 1013904223u;
            const float l = std::exp2(-13.0f + 28.0f * float(state >> 8) / float(1u << 24)); // finite halves
            float* p = image.at(x, y);
            p[0] = p[1] = p[2] = asHalf(l);
            p[3] = 1.0f;
        }
    }
    const Texture input = makeTexture(image, "histogram spread");
    for (const auto [low, high] :
         {std::pair{10.0f, 90.0f}, std::pair{0.0f, 100.0f}, std::pair{37.5f, 62.5f}}) {
        Settings s = autoSettings();
        s.autoExposure.metering = MeteringMode::Histogram;
        s.autoExposure.lowPercent = low;
        s.autoExposure.highPercent = high;
        Pipeline pipeline({.settings = s, .keepTelemetryHistory = true});
        pipeline.execute({.color = &input}, {});
        const ExposureTelemetry t = pipeline.drainTelemetry().at(0);
        const Histogram cpu =
            buildHistogram(image, s.autoExposure.histogramLog2Min, s.autoExposure.histogramLog2Max);
        ASSERT_EQ(t.histogram, cpu.bins);
        const HistogramStats stats = histogramAverage(cpu, low, high);
        EXPECT_EQ(t.histogramCount, stats.counted);
        EXPECT_EQ(t.histogramLowLog2, stats.lowLog2) << low << "-" << high;
        EXPECT_EQ(t.histogramHighLog2, stats.highLog2) << low << "-" << high;
        EXPECT_EQ(t.histogramAverageLog2, stats.averageLog2) << low << "-" << high;
        EXPECT_NE(stats.lowLog2, stats.highLog2);
    }
}

TEST_F(GlTest, NonFiniteFramesLeaveTelemetryFinite) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<ImageF> frames;
    frames.push_back(greyImage(kSize, kSize, 0.2f));
    frames.push_back(greyImage(kSize, kSize, nan));
    frames.push_back(greyImage(kSize, kSize, inf));
    ImageF mixed = greyImage(kSize, kSize, 0.5f);
    mixed.at(1, 1)[0] = nan;
    mixed.at(2, 2)[1] = inf;
    mixed.at(3, 3)[2] = -inf;
    mixed.at(4, 4)[1] = -5.0f;
    frames.push_back(mixed);
    frames.push_back(greyImage(kSize, kSize, 0.0f));
    for (MeteringMode mode : {MeteringMode::Average, MeteringMode::Histogram, MeteringMode::Spot,
                              MeteringMode::Center, MeteringMode::Mask}) {
        Settings s = autoSettings();
        s.autoExposure.metering = mode;
        s.debug.view = DebugView::Histogram;
        Pipeline p({.settings = s, .keepTelemetryHistory = true});
        std::uint64_t index = 0;
        for (const ImageF& f : frames) {
            const Texture t = makeTexture(f, "frame");
            p.execute({.color = &t}, {.dt = std::nanf(""), .frameIndex = index++});
        }
        for (const ExposureTelemetry& t : p.drainTelemetry()) {
            for (float v : {t.frameLuminance, t.meteredLuminance, t.targetLog2, t.appliedLog2, t.exposure,
                            t.minLuminance, t.maxLuminance, t.histogramLowLog2, t.histogramHighLog2,
                            t.histogramAverageLog2}) {
                EXPECT_TRUE(std::isfinite(v)) << "mode " << int(mode) << " frame " << t.frame;
            }
            EXPECT_TRUE(t.exposure > 0.0f);
        }
    }
}

// The last result stays readable while no new one has arrived, and updates when one does.
TEST_F(GlTest, TelemetryCachingAndContinuity) {
    Settings s = autoSettings();
    s.debug.view = DebugView::Histogram;
    Pipeline p({.settings = s});
    EXPECT_FALSE(p.telemetry().valid) << "nothing before the first frame";
    const Texture dark = makeTexture(greyImage(kSize, kSize, 0.05f), "dark");
    const Texture bright = makeTexture(greyImage(kSize, kSize, 3.0f), "bright");
    p.execute({.color = &dark}, {.dt = 0.1f, .frameIndex = 0});
    glFinish();
    const ExposureTelemetry first = p.telemetry();
    ASSERT_TRUE(first.valid);
    EXPECT_EQ(first.frame, 0u);
    EXPECT_NEAR(first.frameLuminance, 0.05f, 1e-4f);

    bool ready = false; // hold every slot "unsignalled"
    p.setTelemetryReadyOverride([&] { return ready; });
    for (std::uint64_t i = 1; i <= 3; ++i) {
        p.execute({.color = &bright}, {.dt = 0.1f, .frameIndex = i});
        glFinish();
        const ExposureTelemetry& held = p.telemetry();
        EXPECT_TRUE(held.valid) << "the last result keeps being returned";
        EXPECT_EQ(held.frame, 0u);
        EXPECT_EQ(held.frameLuminance, first.frameLuminance);
        EXPECT_EQ(held.histogram, first.histogram);
    }
    ready = true;
    const ExposureTelemetry& updated = p.telemetry();
    EXPECT_EQ(updated.frame, 3u) << "the newest finished frame, not the oldest";
    EXPECT_NEAR(updated.frameLuminance, 3.0f, 3e-3f);
    EXPECT_NE(updated.histogram, first.histogram);
}

// The debug histogram is measured even with auto exposure off.
TEST_F(GlTest, TelemetryHistogramRunsForTheDebugViewWithAutoExposureOff) {
    Settings s;
    s.autoExposure.enabled = false;
    s.tonemapping.exposure = 1.5f;
    const ImageF image = greyImage(12, 10, 0.3f);
    const Texture input = makeTexture(image, "input");

    Pipeline off({.settings = s});
    off.execute({.color = &input}, {});
    glFinish();
    const ExposureTelemetry none = off.telemetry();
    ASSERT_TRUE(none.valid);
    EXPECT_EQ(none.histogramCount, 0u)
        << "nothing is metered without auto exposure, telemetry or a view needing it";
    EXPECT_EQ(none.frameLuminance, 0.0f);
    EXPECT_FLOAT_EQ(none.exposure, std::exp2(1.5f));

    // A host that keeps every frame's telemetry (the CLI's --telemetry) gets the readings in the configured
    // mode (average here); exposure stays manual.
    Pipeline telemetry({.settings = s, .keepTelemetryHistory = true});
    telemetry.execute({.color = &input}, {});
    const ExposureTelemetry metered = telemetry.drainTelemetry().at(0);
    EXPECT_NEAR(metered.frameLuminance, asHalf(0.3f), 1e-3f); // a geometric mean: log2 and exp2 in float
    EXPECT_NEAR(metered.meteredLuminance, asHalf(0.3f), 1e-3f);
    EXPECT_GT(metered.maxLuminance, 0.0f);
    EXPECT_FALSE(metered.autoEnabled);
    EXPECT_FLOAT_EQ(metered.exposure, std::exp2(1.5f)) << "auto exposure stays off";

    s.debug.view = DebugView::Histogram;
    Pipeline withView({.settings = s, .keepTelemetryHistory = true});
    withView.execute({.color = &input}, {});
    const ExposureTelemetry t = withView.drainTelemetry().at(0);
    EXPECT_EQ(t.histogramCount, 120u);
    const Histogram cpu = buildHistogram(greyImage(12, 10, asHalf(0.3f)), s.autoExposure.histogramLog2Min,
                                         s.autoExposure.histogramLog2Max);
    EXPECT_EQ(t.histogram, cpu.bins);
    EXPECT_FALSE(t.autoEnabled);
    EXPECT_FLOAT_EQ(t.exposure, std::exp2(1.5f)) << "auto exposure stays off";
    EXPECT_GT(t.maxLuminance, 0.0f);
}

// With auto exposure off and nothing metered, a frame's metering clears and adaptation dispatch write what
// the buffers already hold when the frame before was such a frame with the same manual EV: they are skipped
// then, and only then. After a metered frame the bins are cleared once; a new EV (or a reset) runs the
// adaptation.
TEST_F(GlTest, ManualExposureFramesSkipTheMeteringAndAdaptationThatWouldChangeNothing) {
    Settings s = autoSettings();
    s.autoExposure.metering = MeteringMode::Histogram;
    Pipeline p({.settings = s});
    const Texture input = makeTexture(greyImage(kSize, kSize, 0.3f), "grey");
    struct Frame {
        int dispatches, bufferClears, bufferCopies;
        ExposureTelemetry telemetry;
        Image8 display;
    };
    std::uint64_t index = 0;
    const auto frame = [&](float ev) {
        s.autoExposure.enabled = false;
        s.tonemapping.exposure = ev;
        p.setSettings(s);
        GlCallAudit audit;
        const Texture& out = p.execute({.color = &input}, {.frameIndex = index++});
        Frame f{audit.dispatches(), audit.bufferClears(), audit.bufferCopies(), {}, readTexture8(out)};
        glFinish();
        f.telemetry = p.telemetry();
        return f;
    };
    p.execute({.color = &input}, {.frameIndex = index++}); // metered: the bins hold the frame's histogram
    glFinish();
    ASSERT_GT(p.telemetry().histogramCount, 0u);

    const Frame first = frame(1.5f); // after a metered frame: clears, and adapts to the manual EV
    const Frame again = frame(1.5f); // nothing to change
    const Frame other = frame(0.5f); // a new EV: the adaptation runs
    const Frame settled = frame(0.5f);

    for (const Frame* f : {&first, &again, &other, &settled}) {
        ASSERT_TRUE(f->telemetry.valid);
        EXPECT_EQ(f->telemetry.histogramCount, 0u);
        EXPECT_EQ(f->telemetry.maxLuminance, 0.0f);
        EXPECT_EQ(f->telemetry.frameLuminance, 0.0f);
        EXPECT_TRUE(std::all_of(f->telemetry.histogram.begin(), f->telemetry.histogram.end(),
                                [](std::uint32_t c) { return c == 0; }))
            << "the metered frame's bins are cleared";
    }
    EXPECT_FLOAT_EQ(first.telemetry.exposure, std::exp2(1.5f));
    EXPECT_FLOAT_EQ(again.telemetry.exposure, std::exp2(1.5f));
    EXPECT_FLOAT_EQ(other.telemetry.exposure, std::exp2(0.5f));
    EXPECT_FLOAT_EQ(settled.telemetry.exposure, std::exp2(0.5f));
    EXPECT_EQ(again.display.rgba, first.display.rgba);
    EXPECT_EQ(settled.display.rgba, other.display.rgba);
    EXPECT_NE(other.display.rgba, first.display.rgba);

    // One adaptation dispatch, one bin clear and one header copy fewer than in a frame that needs them.
    EXPECT_EQ(again.dispatches, first.dispatches - 1);
    EXPECT_EQ(again.bufferClears, first.bufferClears - 1);
    EXPECT_EQ(again.bufferCopies, first.bufferCopies - 1);
    EXPECT_EQ(other.dispatches, first.dispatches);
    EXPECT_EQ(other.bufferClears, again.bufferClears) << "the bins stayed clear";
    EXPECT_EQ(settled.dispatches, again.dispatches);

    // A reset runs the adaptation again.
    p.reset();
    const Frame afterReset = frame(0.5f);
    EXPECT_EQ(afterReset.dispatches, first.dispatches);
    EXPECT_FLOAT_EQ(afterReset.telemetry.exposure, std::exp2(0.5f));
}

// Each frame's histogram starts empty: counts never climb over frames.
TEST_F(GlTest, TelemetryHistogramDoesNotAccumulate) {
    Settings s = autoSettings();
    s.autoExposure.metering = MeteringMode::Histogram;
    Pipeline p({.settings = s, .keepTelemetryHistory = true});
    const Texture a = makeTexture(greyImage(10, 6, 0.02f), "a");
    const Texture b = makeTexture(greyImage(10, 6, 5.0f), "b");
    for (std::uint64_t i = 0; i < 6; ++i) {
        p.execute({.color = i < 4 ? &a : &b}, {.frameIndex = i});
        const ExposureTelemetry& latest = p.telemetry(); // the cache a UI would read every frame
        if (latest.valid) {
            std::uint64_t sum = 0;
            for (auto c : latest.histogram) {
                sum += c;
            }
            EXPECT_EQ(sum, 60u) << "frame " << i;
        }
    }
    const auto all = p.drainTelemetry();
    ASSERT_FALSE(all.empty());
    const ExposureTelemetry& last = all.back();
    EXPECT_EQ(last.frame, 5u);
    int nonEmpty = 0;
    for (auto c : last.histogram) {
        nonEmpty += c > 0 ? 1 : 0;
    }
    EXPECT_EQ(nonEmpty, 1) << "only the new image's bin, nothing left from the old one";
    EXPECT_EQ(last.histogramCount, 60u);
}

} // namespace photopic::test
