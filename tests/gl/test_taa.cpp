// TAA against the testbed's ground truth: edges converge towards the supersampled image, a cut frame equals
// the no-history frame, moving objects leave no trail with motion vectors (and do without them), and broken
// inputs never reach the output.

#include "GlTest.h"

#include "gl/TextureIo.h"
#include "scenes/testbed/TestbedRaytracer.h"
#include "scenes/testbed/TestbedScene.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

namespace photopic::test {

namespace {

constexpr int kW = 160;
constexpr int kH = 90;
constexpr float kDt = 1.0f / 30.0f;

/// Display settings for measuring: fixed exposure, no bloom, no dither, so the truth and the renders go
/// through the same curve.
Settings measuring(AntiAliasing aa) {
    Settings s;
    s.tonemapping.mode = ToneMapper::AcesFitted;
    s.tonemapping.exposure = -1.0f;
    s.autoExposure.enabled = false;
    s.bloom.enabled = false;
    s.output.dither = false;
    s.aa.mode = aa;
    return s;
}

std::unique_ptr<TestbedScene> stillScene(float cameraTime) {
    auto scene = std::make_unique<TestbedScene>();
    for (const std::string& a : {std::string("cameraSpeed=0"), std::string("objectSpeed=0"),
                                 "cameraStart=" + std::to_string(cameraTime)}) {
        EXPECT_TRUE(scene->applyOverride(a).empty()) << a;
    }
    scene->resize({kW, kH});
    return scene;
}

/// Renders frames [first, last] through `pipeline`; returns the last display image.
Image8 run(TestbedScene& scene, Pipeline& pipeline, std::uint64_t first, std::uint64_t last) {
    Image8 out;
    for (std::uint64_t f = first; f <= last; ++f) {
        std::vector<double> telemetry;
        const FrameTime time{.dt = kDt, .frameIndex = f};
        const FrameInputs in = scene.render(time, pipeline, telemetry);
        const Texture& display = pipeline.execute(in, time);
        if (f == last) {
            out = readTexture8(display);
        }
    }
    return out;
}

/// Pixels whose 3x3 neighbourhood in the ray tracer's object ids holds more than one object.
std::vector<bool> edgePixels(const ImageF& ids) {
    std::vector<bool> edge(std::size_t(kW * kH), false);
    for (int y = 1; y < kH - 1; ++y) {
        for (int x = 1; x < kW - 1; ++x) {
            for (int d = 0; d < 9 && !edge[std::size_t(y * kW + x)]; ++d) {
                edge[std::size_t(y * kW + x)] = ids.at(x + d % 3 - 1, y + d / 3 - 1)[0] != ids.at(x, y)[0];
            }
        }
    }
    return edge;
}

double rmse(const Image8& a, const Image8& b, const std::vector<bool>& mask) {
    double sum = 0.0;
    long n = 0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            if (!mask[std::size_t(y * kW + x)]) {
                continue;
            }
            for (int c = 0; c < 3; ++c) {
                const double d = (double(a.at(x, y)[c]) - double(b.at(x, y)[c])) / 255.0;
                sum += d * d;
            }
            ++n;
        }
    }
    return std::sqrt(sum / double(3 * n));
}

} // namespace

// Static camera, converged after 32 frames: edge RMSE in display-referred sRGB against the 16x16 supersampled
// ray-traced truth shown through the same settings. TAA must be at most 40% of no-AA's (FXAA reported).
TEST_F(GlTest, TaaConvergesTowardsTheSupersampledTruthOnEdges) {
    auto scene = stillScene(0.3f);
    const testbed::TruthOptions truthOptions = scene->truthOptions({.dt = kDt, .frameIndex = 0});
    const ImageF ids = testbed::renderTruth(testbed::TruthKind::ObjectId, truthOptions);
    const std::vector<bool> edges = edgePixels(ids);
    Pipeline truthPipeline({.settings = measuring(AntiAliasing::None)});
    const Image8 truth =
        processImage(truthPipeline, testbed::renderTruth(testbed::TruthKind::Color, truthOptions));

    double error[3] = {};
    const AntiAliasing modes[3] = {AntiAliasing::None, AntiAliasing::Fxaa, AntiAliasing::Taa};
    for (int i = 0; i < 3; ++i) {
        Pipeline pipeline({.settings = measuring(modes[i])});
        error[i] = rmse(run(*scene, pipeline, 0, 31), truth, edges);
    }
    std::printf("edge RMSE (sRGB) vs 16x16 truth, static, 32 frames: none %.4f, fxaa %.4f (%.0f%%), "
                "taa %.4f (%.0f%%)\n",
                error[0], error[1], 100.0 * error[1] / error[0], error[2], 100.0 * error[2] / error[0]);
    EXPECT_LE(error[2], 0.40 * error[0]);
}

// The frame after a camera cut (frame 36 of the path) equals the frame a pipeline with no history renders.
TEST_F(GlTest, TaaFrameAfterACutEqualsTheNoHistoryFrame) {
    TestbedScene scene;
    scene.resize({kW, kH});
    Pipeline running({.settings = measuring(AntiAliasing::Taa)});
    const Image8 afterCut = run(scene, running, 28, 36);
    Pipeline fresh({.settings = measuring(AntiAliasing::Taa)});
    const Image8 noHistory = run(scene, fresh, 36, 36);
    EXPECT_EQ(afterCut.rgba, noHistory.rgba);
    // And frame 35, with history, differs from its no-history frame (the test can fail).
    Pipeline running35({.settings = measuring(AntiAliasing::Taa)});
    Pipeline fresh35({.settings = measuring(AntiAliasing::Taa)});
    EXPECT_NE(run(scene, running35, 28, 35).rgba, run(scene, fresh35, 35, 35).rgba);
}

// NaN and infinity in colour and in motion never reach the output.
TEST_F(GlTest, TaaOutputStaysFiniteWithBrokenInputs) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    ImageF color(32, 18, 0.5f);
    ImageF motion(32, 18, 0.0f);
    for (int i = 0; i < 32 * 18; i += 5) {
        color.rgba[std::size_t(i) * 4] = i % 2 ? nan : inf;
        motion.rgba[std::size_t(i) * 4 + 1] = i % 3 ? nan : -inf;
    }
    const Texture colorTexture = makeTexture(color, "color");
    const Texture motionTexture = makeTexture(motion, "motion");
    Settings s = measuring(AntiAliasing::Taa);
    s.debug.view = DebugView::TaaHistoryWeight; // shows that history was used on the later frames
    Pipeline pipeline({.settings = s});
    for (std::uint64_t f = 0; f < 4; ++f) {
        pipeline.beginFrame({.frameIndex = f});
        pipeline.execute({.color = &colorTexture, .motion = &motionTexture}, {.dt = kDt, .frameIndex = f});
    }
    EXPECT_TRUE(pipeline.status().skipped.empty());
    const ImageF scene = readTextureF(pipeline.sceneReferred());
    for (float v : scene.rgba) {
        ASSERT_TRUE(std::isfinite(v));
    }
    const Image8 weight = readTexture8(
        pipeline.execute({.color = &colorTexture, .motion = &motionTexture}, {.dt = kDt, .frameIndex = 4}));
    EXPECT_NEAR(weight.at(16, 9)[0], 0.9 * 255, 1.0); // blendFactor on a pixel with history
}

TEST_F(GlTest, TaaWithoutMotionOrDepthIsSkippedAndReported) {
    const Texture color = makeTexture(ImageF(16, 16, 0.5f), "color");
    Pipeline pipeline({.settings = measuring(AntiAliasing::Taa)});
    pipeline.beginFrame({});
    pipeline.execute({.color = &color}, {});
    const PipelineStatus st = pipeline.status();
    ASSERT_EQ(st.skipped.size(), 1u);
    EXPECT_EQ(st.skipped[0].pass, "taa");
    EXPECT_EQ(st.skipped[0].missing, (std::vector<std::string>{"motion"}));
}

} // namespace photopic::test
