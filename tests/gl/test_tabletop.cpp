// The tabletop scene: deterministic frames, light under the player token outside vs inside,
// the walk's crossings, and the whole idea on the CPU: probe under the token -> ExposureController -> the
// blow-out on stepping out and the dark lag on stepping in, with the eye-lag time constants.

#include "EyeLagChecks.h"
#include "GlTest.h"

#include "core/ExposureController.h"
#include "core/Subjects.h"
#include "common/TransitionAnalysis.h"
#include "gl/TextureIo.h"
#include "scenes/tabletop/TabletopScene.h"

#include <chrono>
#include <cmath>
#include <cstdio>

namespace photopic::test {

namespace {

constexpr float kFps = 30.0f;

struct Rendered {
    ImageF hdr;
    std::vector<double> telemetry;
};

Rendered renderFrame(TabletopScene& scene, Pipeline& pipeline, std::uint64_t frame, float fps = kFps) {
    Rendered r;
    const FrameInputs inputs = scene.render({.dt = 1.0f / fps, .frameIndex = frame}, pipeline, r.telemetry);
    r.hdr = readTextureF(*inputs.color);
    return r;
}

/// Mean Rec.709 luma of the whole frame (what "the frame looks brighter" means before tone mapping).
double meanLuma(const ImageF& image) {
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            sum += double(pixelLuminance(image, x, y));
        }
    }
    return sum / double(image.pixelCount());
}

} // namespace

TEST_F(GlTest, TabletopFramesAreDeterministic) {
    TabletopScene scene;
    Pipeline pipeline;
    scene.resize({160, 90});
    const Rendered a = renderFrame(scene, pipeline, 200);
    renderFrame(scene, pipeline, 17);
    const Rendered b = renderFrame(scene, pipeline, 200);
    EXPECT_EQ(a.hdr.rgba, b.hdr.rgba);
    EXPECT_EQ(a.telemetry, b.telemetry);
    ASSERT_EQ(a.telemetry.size(), scene.telemetryColumns().size());
    EXPECT_EQ(a.telemetry[0], double(TabletopScene::kPlayerId));
}

TEST_F(GlTest, TabletopReportsThePlayerAsTheControlledSubject) {
    TabletopScene scene;
    Pipeline pipeline;
    scene.resize({160, 90});
    const Rendered r = renderFrame(scene, pipeline, 0);
    const auto& subjects = scene.subjects();
    ASSERT_GE(subjects.size(), 4u);
    const SubjectSelection sel = selectSubject(subjects, SubjectFallback::None);
    ASSERT_EQ(sel.source, SubjectSource::Controlled);
    const Subject& player = subjects[sel.index];
    EXPECT_EQ(player.id, TabletopScene::kPlayerId);
    int controlled = 0;
    for (const Subject& s : subjects) {
        controlled += s.controlled ? 1 : 0;
    }
    EXPECT_EQ(controlled, 1);
    // The camera follows the player: it is at the centre of the view unless the map edge stops the camera.
    EXPECT_NEAR(player.screenUv.x, 0.5f, 1e-4f);
    EXPECT_NEAR(player.screenUv.y, 0.5f, 1e-4f);
    EXPECT_EQ(r.telemetry[1], double(player.world.x));
    EXPECT_EQ(r.telemetry[3], double(player.screenUv.x));
}

TEST_F(GlTest, TabletopIsMuchBrighterUnderThePlayerOutside) {
    TabletopScene scene;
    Pipeline pipeline;
    scene.resize({192, 108});
    auto probeAt = [&](double seconds) {
        const Rendered r = renderFrame(scene, pipeline, std::uint64_t(std::lround(seconds * kFps)));
        const glm::vec2 uv(float(r.telemetry[3]), float(r.telemetry[4]));
        return std::pair{probeImage(r.hdr, uv, 5, 0.02f), float(r.telemetry[5])};
    };
    const auto [inside, insideOutdoors] = probeAt(13.0);
    const auto [outside, outsideOutdoors] = probeAt(7.0);
    const auto [start, startOutdoors] = probeAt(0.0);
    EXPECT_EQ(insideOutdoors, 0.0f);
    EXPECT_EQ(startOutdoors, 0.0f);
    EXPECT_EQ(outsideOutdoors, 1.0f);
    EXPECT_GT(inside, 0.01f); // the door torch lights the token
    EXPECT_GT(outside / inside, 15.0f) << outside << " vs " << inside;
    EXPECT_GT(outside / start, 15.0f) << outside << " vs " << start;
    std::printf("luma under the player: start %.4f, outside %.4f, inside by the door %.4f\n", double(start),
                double(outside), double(inside));
}

TEST_F(GlTest, TabletopWalkCrossesBothWaysWithinTwentySeconds) {
    TabletopScene scene;
    const OutdoorsMask& mask = scene.outdoorsMask();
    std::vector<double> out, in;
    float previous = mask.atWorld(TabletopScene::playerWorldAt(0.0).x, TabletopScene::playerWorldAt(0.0).y);
    EXPECT_LT(previous, 0.5f); // starts indoors
    for (int i = 1; i <= 20 * 30; ++i) {
        const double t = double(i) / 30.0;
        const glm::vec2 p = TabletopScene::playerWorldAt(t);
        const float o = mask.atWorld(p.x, p.y);
        if (previous < 0.5f && o >= 0.5f) {
            out.push_back(t);
        } else if (previous >= 0.5f && o < 0.5f) {
            in.push_back(t);
        }
        previous = o;
    }
    ASSERT_EQ(out.size(), 1u);
    ASSERT_EQ(in.size(), 1u);
    EXPECT_NEAR(out[0], 4.0, 0.5);
    EXPECT_NEAR(in[0], 12.0, 0.5);
}

// The acceptance test in miniature: ~24 s of the walk at 96x54, the light under the token probed on the CPU
// (SubjectTracker's schedule, probeImage), core's ExposureController with its defaults.
TEST_F(GlTest, TabletopEyeLagOnTheCpu) {
    TabletopScene scene;
    Pipeline pipeline;
    scene.resize({96, 54});
    AutoExposureSettings ae; // key 0.18, -2..+2 EV, tauBrighten 1 s, tauDarken 0.3 s
    ae.enabled = true;
    ExposureController controller(ae);
    SubjectSettings subjectSettings = scene.defaultSettings().subjects;
    SubjectTracker tracker(subjectSettings);
    tracker.setOutdoorsMask(&scene.outdoorsMask());

    const int frames = int(24.0f * kFps);
    std::vector<TelemetrySample> samples;
    std::vector<double> meanExposed; // frame mean luma x exposure: how bright the frame looks
    const auto begin = std::chrono::steady_clock::now();
    for (int i = 0; i < frames; ++i) {
        const Rendered r = renderFrame(scene, pipeline, std::uint64_t(i));
        tracker.beginFrame(1.0f / kFps);
        for (const Subject& s : scene.subjects()) {
            tracker.addSubject(s);
        }
        for (const ProbeRequest& p : tracker.scheduleProbes()) {
            tracker.recordProbe(
                p.id, probeImage(r.hdr, p.screenUv, subjectSettings.probe.taps, subjectSettings.probe.radius),
                tracker.time());
        }
        const SubjectContext* c = tracker.subjectContext();
        ASSERT_NE(c, nullptr);
        const ExposureState& s = controller.update(c->measuredLuma, 1.0f / kFps);
        tracker.updateExposure(ae, s.appliedLog2);
        samples.push_back({float(i) / kFps, c->measuredLuma, s.targetLog2, s.appliedLog2, c->outdoors});
        meanExposed.push_back(meanLuma(r.hdr) * double(s.exposure));
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    std::printf("%d frames at 96x54 rendered, read back and probed in %.2f s (%.2f ms/frame)\n", frames,
                seconds, 1e3 * seconds / frames);

    const auto crossings = expectEyeLag(samples, ae);
    ASSERT_EQ(crossings.size(), 2u);
    const Transition& out = crossings[0];
    const Transition& in = crossings[1];

    // The frames show it: right after stepping out the frame is clearly brighter than once settled.
    const double blown = meanExposed[out.startIndex];
    const double settledOut = meanExposed[out.settledIndex];
    EXPECT_GT(blown, 2.0 * settledOut) << blown << " vs " << settledOut;
    const double dark = meanExposed[in.startIndex];
    const double settledIn = meanExposed[in.settledIndex];
    EXPECT_LT(dark, 0.5 * settledIn) << dark << " vs " << settledIn;
    std::printf("frame mean (exposed): stepping out %.3f -> settled %.3f; stepping in %.3f -> settled %.3f\n",
                blown, settledOut, dark, settledIn);
}

} // namespace photopic::test
