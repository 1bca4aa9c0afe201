// Subjects on the GPU: the probe pass against core's probeImage, probe throttling in
// frame time, `subject` metering driving exposure in the same frame, the context API after the readback, and
// the demo's acceptance -- the tabletop walk through the pipeline, judged from its telemetry and its frames.

#include "EyeLagChecks.h"
#include "GlTest.h"

#include "common/TransitionAnalysis.h"
#include "core/ExposureController.h"
#include "core/Subjects.h"
#include "gl/ReadbackRing.h"
#include "gl/TextureIo.h"
#include "pipeline/Pipeline.h"
#include "scenes/tabletop/TabletopScene.h"

#include <glm/gtc/packing.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>

namespace photopic::test {

namespace {

constexpr float kDt = 1.0f / 30.0f;

/// Values the half-float sanitise pass stores unchanged, so the GPU probes what the CPU reference reads.
float asHalf(float v) {
    return glm::unpackHalf1x16(glm::packHalf1x16(v));
}

/// A deterministic pattern with a different luma at every texel.
ImageF patternImage(int w, int h) {
    ImageF image(w, h, 0.0f);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            float* p = &image.rgba[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * 4];
            p[0] = asHalf(0.01f + 0.03f * float((x * 7 + y * 13) % 29));
            p[1] = asHalf(0.02f + 0.05f * float((x * 3 + y * 5) % 17));
            p[2] = asHalf(0.01f + 0.2f * float((x + 2 * y) % 5));
            p[3] = 1.0f;
        }
    }
    return image;
}

/// Dark (0.02) with a bright (2.0) rectangle on the left third.
ImageF spotImage(int w, int h) {
    ImageF image(w, h, 0.0f);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float v = x < w / 3 ? 2.0f : 0.02f;
            float* p = &image.rgba[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * 4];
            p[0] = p[1] = p[2] = v;
            p[3] = 1.0f;
        }
    }
    return image;
}

Settings subjectSettings() {
    Settings s;
    s.tonemapping.mode = ToneMapper::Linear;
    s.output.dither = false;
    s.autoExposure.enabled = true;
    s.autoExposure.metering = MeteringMode::Subject;
    s.autoExposure.minEV = -10.0f;
    s.autoExposure.maxEV = 10.0f;
    s.subjects.probe.deadbandEV = 0.0f;
    return s;
}

Subject subjectAt(std::uint32_t id, glm::vec2 uv, bool controlled = false) {
    Subject s;
    s.id = id;
    s.world = uv * 1000.0f;
    s.screenUv = uv;
    s.controlled = controlled;
    return s;
}

} // namespace

TEST_F(GlTest, ReadbackRingPollEachVisitsFinishedSlotsOldestFirst) {
    ReadbackRing ring(sizeof(std::uint32_t), 4, "test ring");
    for (std::uint32_t v : {10u, 20u, 30u}) {
        const Buffer source({.size = sizeof(v), .flags = 0, .data = &v, .debugName = "source"});
        ASSERT_TRUE(ring.enqueue(source, 0, v / 10));
    }
    glFinish();
    std::vector<std::pair<std::uint64_t, std::uint32_t>> seen;
    const int n = ring.pollEach([&](const ReadbackRing::Result& r) {
        std::uint32_t value = 0;
        std::memcpy(&value, r.bytes.data(), sizeof(value));
        seen.emplace_back(r.tag, value);
    });
    EXPECT_EQ(n, 3);
    const std::vector<std::pair<std::uint64_t, std::uint32_t>> expected{{1, 10}, {2, 20}, {3, 30}};
    EXPECT_EQ(seen, expected);
    EXPECT_EQ(ring.inFlight(), 0);
    EXPECT_EQ(ring.pollEach([](const ReadbackRing::Result&) {}), 0);
}

TEST_F(GlTest, GpuProbeEqualsCoreProbeImage) {
    const ImageF image = patternImage(67, 41);
    const Texture input = makeTexture(image, "pattern");
    const std::vector<glm::vec2> uvs{
        {0.5f, 0.5f}, {0.13f, 0.77f}, {0.0f, 0.0f}, {0.999f, 0.02f}, {0.4f, 1.0f}};
    for (int taps : {1, 5, 9}) {
        Settings settings = subjectSettings();
        settings.subjects.probe.taps = taps;
        settings.subjects.probe.radius = 0.07f;
        Pipeline pipeline({.settings = settings});
        std::vector<Subject> subjects;
        for (std::size_t i = 0; i < uvs.size(); ++i) {
            subjects.push_back(subjectAt(std::uint32_t(i + 1), uvs[i], i == 0));
        }
        // Frame 0 probes every subject; frame 1 polls the readback (finished: glFinish) into the contexts.
        for (std::uint64_t f = 0; f < 2; ++f) {
            pipeline.execute({.color = &input, .subjects = subjects}, {.dt = kDt, .frameIndex = f});
            glFinish();
        }
        for (std::size_t i = 0; i < uvs.size(); ++i) {
            const SubjectContext* c = pipeline.contextForSubject(std::uint32_t(i + 1));
            ASSERT_NE(c, nullptr);
            const float expected = probeImage(image, uvs[i], taps, 0.07f);
            EXPECT_NEAR(c->measuredLuma, expected, 1e-5f * expected)
                << "taps " << taps << " uv " << uvs[i].x << "," << uvs[i].y;
            EXPECT_GE(c->lastProbeAt, 0.0f);
        }
    }
}

TEST_F(GlTest, GpuProbesAreThrottledInFrameTime) {
    const Texture input = makeTexture(patternImage(32, 18), "pattern");
    Settings settings = subjectSettings();
    settings.subjects.probe.hz = 5.0f; // at 30 fps: every 6th frame
    Pipeline pipeline({.settings = settings});
    const Subject subject = subjectAt(7, {0.3f, 0.6f}, true);
    std::vector<std::uint64_t> changes;
    std::vector<float> times;
    float last = -2.0f;
    for (std::uint64_t f = 0; f < 60; ++f) {
        pipeline.execute({.color = &input, .subjects = {&subject, 1}}, {.dt = kDt, .frameIndex = f});
        glFinish(); // the readback is ready by the next frame
        const SubjectContext* c = pipeline.contextForSubject(7);
        ASSERT_NE(c, nullptr);
        if (c->lastProbeAt != last) {
            changes.push_back(f);
            times.push_back(c->lastProbeAt);
            last = c->lastProbeAt;
        }
    }
    // Frame 0's probe arrives on frame 1, so frame 1 probes too (never probed yet) and its result arrives on
    // frame 2; the schedule's next probe is frame 6 (arriving on 7), then every 6 frames.
    // (changes[0] is frame 0's "never probed", -1.)
    ASSERT_GE(changes.size(), 10u);
    EXPECT_EQ(changes[1], 1u);
    EXPECT_EQ(changes[2], 2u);
    EXPECT_EQ(changes[3], 7u);
    for (std::size_t i = 4; i < changes.size(); ++i) {
        EXPECT_EQ(changes[i] - changes[i - 1], 6u) << "change " << i;
        EXPECT_NEAR(times[i] - times[i - 1], 6.0f * kDt, 1e-4f);
    }
}

TEST_F(GlTest, SubjectMeteringDrivesExposureOnTheGpu) {
    const int w = 48, h = 27;
    const Texture input = makeTexture(spotImage(w, h), "spot");
    Settings settings = subjectSettings();
    settings.subjects.probe.hz = 10.0f;
    Pipeline pipeline({.settings = settings, .keepTelemetryHistory = true});
    const glm::vec2 bright(0.15f, 0.5f), dark(0.75f, 0.5f);
    std::uint64_t frame = 0;
    auto run = [&](glm::vec2 uv, int frames) {
        const Subject s = subjectAt(1, uv, true);
        for (int i = 0; i < frames; ++i) {
            pipeline.execute({.color = &input, .subjects = {&s, 1}}, {.dt = kDt, .frameIndex = frame++});
        }
        return pipeline.drainTelemetry();
    };
    const float darkTarget = std::log2(0.18f / asHalf(0.02f));
    const float brightTarget = std::log2(0.18f / 2.0f);
    // In the dark: the first probe snaps exposure to the dark target.
    const auto inDark = run(dark, 10);
    EXPECT_NEAR(inDark.back().appliedLog2, darkTarget, 0.01f);
    EXPECT_NEAR(inDark.back().frameLuminance, asHalf(0.02f), 1e-4f); // measured_luma: the probed luma
    // Into the bright spot: the next scheduled probe (10 Hz: within 3 frames) moves the target in its own
    // frame; from then exposure falls every frame (the reading stays on the GPU between probes), with
    // tauDarken.
    const auto toBright = run(bright, 30);
    std::size_t k = 0;
    while (k < toBright.size() && toBright[k].frameLuminance < 1.0f) {
        ++k;
    }
    ASSERT_LT(k, 3u);
    EXPECT_NEAR(toBright[k].targetLog2, brightTarget, 0.01f);
    EXPECT_NEAR(toBright[k].frameLuminance, 2.0f, 1e-3f); // measured_luma: the probed luma
    for (std::size_t i = k + 1; i < toBright.size(); ++i) {
        EXPECT_LT(toBright[i].appliedLog2, toBright[i - 1].appliedLog2 - 1e-4f) << "frame " << i;
    }
    // The gap before the frame whose target moved (that frame already took its step): the frame before it,
    // the last of the dark run when the probe landed in the first frame (a GPU's reading can).
    const double gap0 = (k > 0 ? toBright[k - 1] : inDark.back()).appliedLog2 - brightTarget;
    const double steps = double(toBright.size() - k);
    EXPECT_NEAR(toBright.back().appliedLog2, brightTarget + gap0 * std::exp(-steps * kDt / 0.3), 0.02);
    // Back into the dark: it rises, with tauBrighten.
    const auto toDark = run(dark, 30);
    k = 0;
    while (k < toDark.size() && toDark[k].frameLuminance > 1.0f) {
        ++k;
    }
    ASSERT_LT(k, 3u);
    EXPECT_NEAR(toDark[k].targetLog2, darkTarget, 0.01f);
    for (std::size_t i = k + 1; i < toDark.size(); ++i) {
        EXPECT_GT(toDark[i].appliedLog2, toDark[i - 1].appliedLog2 + 1e-4f) << "frame " << i;
    }
    const double start = k > 0 ? toDark[k - 1].appliedLog2 : toBright.back().appliedLog2;
    const double risen = darkTarget - (darkTarget - start) * std::exp(-double(toDark.size() - k) * kDt / 1.0);
    EXPECT_NEAR(toDark.back().appliedLog2, risen, 0.02);
}

TEST_F(GlTest, SubjectMeteringHoldsWithoutASubjectUnlessTheCentreIsTheFallback) {
    const Texture input = makeTexture(spotImage(48, 27), "spot");
    Settings settings = subjectSettings();
    Pipeline pipeline({.settings = settings, .keepTelemetryHistory = true});
    for (std::uint64_t f = 0; f < 5; ++f) {
        pipeline.execute({.color = &input}, {.dt = kDt, .frameIndex = f});
    }
    for (const ExposureTelemetry& t : pipeline.drainTelemetry()) {
        EXPECT_EQ(t.frameLuminance, 0.0f); // no reading: exposure holds
        EXPECT_EQ(t.appliedLog2, 0.0f);
    }
    EXPECT_EQ(pipeline.subjectContext(), nullptr);

    settings.subjects.fallback = SubjectFallback::Center;
    pipeline.setSettings(settings);
    for (std::uint64_t f = 5; f < 8; ++f) {
        pipeline.execute({.color = &input}, {.dt = kDt, .frameIndex = f});
        glFinish();
    }
    const auto rows = pipeline.drainTelemetry();
    EXPECT_NEAR(rows.back().frameLuminance, asHalf(0.02f), 1e-4f); // the centre is in the dark part
    const SubjectContext* c = pipeline.subjectContext();
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->id, kCenterSubjectId);
    EXPECT_NEAR(c->measuredLuma, asHalf(0.02f), 1e-4f);
}

TEST_F(GlTest, ContextApiReturnsTheSubjectsValuesAfterTheReadback) {
    const Texture input = makeTexture(spotImage(48, 27), "spot");
    Settings settings = subjectSettings();
    Pipeline pipeline({.settings = settings, .keepTelemetryHistory = true});
    // A mask that is outdoors on the left half of a 1000 x 1000 map (row 0 = bottom; same on every row).
    std::vector<std::uint8_t> texels(4 * 4);
    for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) {
            texels[std::size_t(j * 4 + i)] = i < 2 ? 255 : 0;
        }
    }
    const OutdoorsMask mask(4, 4, texels, {0.0f, 0.0f, 1000.0f, 1000.0f});
    pipeline.setOutdoorsMask(&mask);
    Subject player = subjectAt(1, {0.15f, 0.5f}, true);
    player.world = {100.0f, 500.0f};
    Subject other = subjectAt(2, {0.8f, 0.4f});
    other.world = {900.0f, 400.0f};
    other.outdoors = 0.25f; // the host's own value wins over the mask
    const Subject both[] = {other, player};
    for (std::uint64_t f = 0; f < 3; ++f) {
        pipeline.execute({.color = &input, .subjects = both}, {.dt = kDt, .frameIndex = f});
        glFinish();
    }
    const ExposureTelemetry telemetry = pipeline.drainTelemetry().back();
    pipeline.execute({.color = &input, .subjects = both}, {.dt = kDt, .frameIndex = 3});
    const SubjectContext* c = pipeline.subjectContext();
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c, pipeline.contextForSubject(1));
    EXPECT_EQ(c->id, 1u);
    EXPECT_EQ(c->world, player.world);
    EXPECT_EQ(c->screenUv, player.screenUv);
    EXPECT_FLOAT_EQ(c->outdoors, 1.0f);
    EXPECT_NEAR(c->measuredLuma, 2.0f, 1e-3f);
    EXPECT_NEAR(c->targetLog2, exposureTargetLog2(settings.autoExposure, c->measuredLuma), 1e-5f);
    EXPECT_GT(c->lastProbeAt, 0.0f);
    EXPECT_NEAR(c->appliedLog2, telemetry.appliedLog2, 0.5f); // the newest exposure that came back
    const SubjectContext* o = pipeline.contextForSubject(2);
    ASSERT_NE(o, nullptr);
    EXPECT_FLOAT_EQ(o->outdoors, 0.25f);
    EXPECT_NEAR(o->measuredLuma, asHalf(0.02f), 1e-4f);
    EXPECT_EQ(pipeline.contextForSubject(99), nullptr);
    EXPECT_FLOAT_EQ(pipeline.outdoorsAtWorld(100.0f, 500.0f), 1.0f);
    EXPECT_FLOAT_EQ(pipeline.outdoorsAtWorld(900.0f, 500.0f), 0.0f);
}

TEST_F(GlTest, OutdoorsCouplingTightensExposureOnTheGpuPath) {
    const Texture input = makeTexture(spotImage(48, 27), "spot");
    Settings settings = subjectSettings();
    settings.subjects.outdoorsCoupling.enabled = true;
    settings.subjects.outdoorsCoupling.maxEV = 1.0f;
    Pipeline pipeline({.settings = settings, .keepTelemetryHistory = true});
    Subject s = subjectAt(1, {0.75f, 0.5f}, true); // dark: target log2(9) = 3.17 > 1
    s.outdoors = 1.0f;
    for (std::uint64_t f = 0; f < 3; ++f) {
        pipeline.execute({.color = &input, .subjects = {&s, 1}}, {.dt = kDt, .frameIndex = f});
    }
    EXPECT_NEAR(pipeline.drainTelemetry().back().targetLog2, 1.0f, 1e-4f);
}

// Issue 5's "Done when", through the GPU pipeline: the tabletop walk at 96x54, 30 fps, 22 s, exposure by
// subject metering with the scene's defaults (the eye-lag constants).
TEST_F(GlTest, TabletopWalkThroughTheGpuPipeline) {
    TabletopScene scene;
    const Settings settings = scene.defaultSettings();
    ASSERT_EQ(settings.autoExposure.metering, MeteringMode::Subject);
    const AutoExposureSettings& ae = settings.autoExposure;
    Pipeline pipeline({.settings = settings, .keepTelemetryHistory = true});
    scene.resize({96, 54});
    const int frames = 22 * 30;
    std::vector<std::vector<double>> values(static_cast<std::size_t>(frames));
    std::vector<double> brightness; // mean display value: how bright the frame looks
    for (int i = 0; i < frames; ++i) {
        const FrameTime time{.dt = kDt, .frameIndex = std::uint64_t(i)};
        const FrameInputs frame = scene.render(time, pipeline, values[std::size_t(i)]);
        const Image8 display = readTexture8(pipeline.execute(frame, time));
        double sum = 0.0;
        for (std::size_t p = 0; p < display.rgba.size(); p += 4) {
            sum += display.rgba[p] + display.rgba[p + 1] + display.rgba[p + 2];
        }
        brightness.push_back(sum / (3.0 * double(display.rgba.size() / 4)));
        const SubjectContext* c = pipeline.subjectContext();
        ASSERT_NE(c, nullptr);
        ASSERT_EQ(c->id, TabletopScene::kPlayerId);
    }
    const auto rows = pipeline.drainTelemetry();
    ASSERT_EQ(rows.size(), std::size_t(frames));
    std::vector<TelemetrySample> samples;
    for (const ExposureTelemetry& t : rows) {
        samples.push_back({float(t.frame) * kDt, t.frameLuminance, t.targetLog2, t.appliedLog2,
                           float(values[std::size_t(t.frame)][5])});
    }
    const auto crossings = expectEyeLag(samples, ae);
    ASSERT_EQ(crossings.size(), 2u);
    const Transition& out = crossings[0];
    const Transition& in = crossings[1];

    // The frames show it: blown out right after stepping out, too dark right after stepping in.
    EXPECT_GT(brightness[out.startIndex], 1.3 * brightness[out.settledIndex])
        << brightness[out.startIndex] << " vs " << brightness[out.settledIndex];
    EXPECT_LT(brightness[in.startIndex], 0.7 * brightness[in.settledIndex])
        << brightness[in.startIndex] << " vs " << brightness[in.settledIndex];
    std::printf("display mean: stepping out %.1f -> settled %.1f; stepping in %.1f -> settled %.1f\n",
                brightness[out.startIndex], brightness[out.settledIndex], brightness[in.startIndex],
                brightness[in.settledIndex]);
}

} // namespace photopic::test
