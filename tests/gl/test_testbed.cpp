// The testbed's rasteriser against its CPU ray tracer: depth, normals and motion agree at pixel centres away
// from object edges (so the ray tracer's other truths can be trusted against what the pipeline is fed), the
// frame is deterministic, the cut frame is flagged, and the scene's EXR frame carries the file conventions.

#include "GlTest.h"

#include "gl/TextureIo.h"
#include "scenes/SceneExr.h"
#include "scenes/testbed/TestbedRenderer.h"
#include "scenes/testbed/TestbedScene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace photopic::test {

namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 90;
constexpr float kDt = 1.0f / 30.0f;

struct Raster {
    std::vector<float> depth; ///< window depth
    ImageF normals;
    ImageF motion;
    ImageF color;
    Camera camera;
};

Raster rasterise(TestbedScene& scene, Pipeline& pipeline, std::uint64_t frame) {
    std::vector<double> telemetry;
    const FrameInputs in = scene.render({.dt = kDt, .frameIndex = frame}, pipeline, telemetry);
    return {readDepthTexture(*in.depth), readTextureF(*in.normals), readTextureF(*in.motion),
            readTextureF(*in.color), *in.camera};
}

/// Interior pixels whose 3x3 neighbourhood in the ray tracer's object ids holds one object (or only sky).
bool awayFromEdges(const ImageF& ids, int x, int y) {
    if (x < 1 || y < 1 || x >= ids.width - 1 || y >= ids.height - 1) {
        return false;
    }
    const float id = ids.at(x, y)[0];
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            if (ids.at(x + dx, y + dy)[0] != id) {
                return false;
            }
        }
    }
    return true;
}

struct Stat {
    double max = 0.0;
    double sum = 0.0;
    long count = 0;
    void add(double v) {
        max = std::max(max, v);
        sum += v;
        ++count;
    }
    [[nodiscard]] double mean() const { return count > 0 ? sum / double(count) : 0.0; }
};

class TestbedTest : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        if (IsSkipped()) {
            return;
        }
        scene = std::make_unique<TestbedScene>();
        scene->resize({kWidth, kHeight});
        pipeline = std::make_unique<Pipeline>(PipelineCreateInfo{.settings = scene->defaultSettings()});
    }
    void TearDown() override {
        pipeline.reset();
        scene.reset();
        GlTest::TearDown();
    }
    std::unique_ptr<TestbedScene> scene;
    std::unique_ptr<Pipeline> pipeline;
};

} // namespace

// Depth: |rasterised linear depth - ray-traced depth| <= 0.1% of the ray-traced depth (the range to the
// surface; stricter than 0.1% of far - near). Normals within 1 degree. Motion within 0.05 px (Euclidean, in
// pixels of this target). Frames: the pan, the dolly, the cut, the second shot (spinner and mover moving).
TEST_F(TestbedTest, RasterisedDepthNormalsAndMotionAgreeWithTheRayTracer) {
    Stat depth, angle, motion;
    for (const std::uint64_t frame : {10u, 25u, 36u, 44u}) {
        const Raster r = rasterise(*scene, *pipeline, frame);
        const testbed::TruthOptions truth = scene->truthOptions({.dt = kDt, .frameIndex = frame});
        const ImageF ids = testbed::renderTruth(testbed::TruthKind::ObjectId, truth);
        const ImageF tDepth = testbed::renderTruth(testbed::TruthKind::Depth, truth);
        const ImageF tNormals = testbed::renderTruth(testbed::TruthKind::Normals, truth);
        const ImageF tMotion = testbed::renderTruth(testbed::TruthKind::Motion, truth);
        int objects = 0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                if (!awayFromEdges(ids, x, y)) {
                    continue;
                }
                const glm::vec2 mr(r.motion.at(x, y)[0] * kWidth, r.motion.at(x, y)[1] * kHeight);
                const glm::vec2 mt(tMotion.at(x, y)[0] * kWidth, tMotion.at(x, y)[1] * kHeight);
                motion.add(double(glm::length(mr - mt)));
                if (ids.at(x, y)[0] == 0.0f) {
                    EXPECT_EQ(r.depth[std::size_t(y * kWidth + x)], 1.0f) << "sky at " << x << "," << y;
                    continue;
                }
                ++objects;
                const float d = linearDepthFromWindow(r.depth[std::size_t(y * kWidth + x)],
                                                      r.camera.nearPlane, r.camera.farPlane);
                const float dt = tDepth.at(x, y)[0];
                depth.add(double(std::abs(d - dt) / dt));
                const glm::vec3 nr = glm::normalize(
                    glm::vec3(r.normals.at(x, y)[0], r.normals.at(x, y)[1], r.normals.at(x, y)[2]));
                const glm::vec3 nt(tNormals.at(x, y)[0], tNormals.at(x, y)[1], tNormals.at(x, y)[2]);
                angle.add(double(std::acos(std::clamp(glm::dot(nr, nt), -1.0f, 1.0f))) * 180.0 / 3.14159265);
            }
        }
        EXPECT_GT(objects, kWidth * kHeight / 4) << "frame " << frame;
    }
    std::printf("testbed agreement (4 frames, %ld object pixels, %ld pixels with motion):\n"
                "  depth   max %.2e mean %.2e (relative)\n"
                "  normals max %.4f mean %.4f (degrees)\n"
                "  motion  max %.4f mean %.4f (px)\n",
                depth.count, motion.count, depth.max, depth.mean(), angle.max, angle.mean(), motion.max,
                motion.mean());
    EXPECT_LE(depth.max, 1e-3);
    EXPECT_LE(angle.max, 1.0);
    EXPECT_LE(motion.max, 0.05);
}

// The GLSL shading twin matches the CPU's: rasterised colour against the ray tracer's one-sample (pixel
// centre) colour, relative to the pixel's value, over pixels away from object edges. Checker squares' own
// edges can fall either side of a pixel centre, so 99% of the pixels must agree within 0.5% (half floats
// hold 3 digits), and the mean error is that of rounding.
TEST_F(TestbedTest, RasterisedColourMatchesTheRayTracersPixelCentreColour) {
    for (const std::uint64_t frame : {10u, 44u}) {
        const Raster r = rasterise(*scene, *pipeline, frame);
        testbed::TruthOptions truth = scene->truthOptions({.dt = kDt, .frameIndex = frame});
        truth.samples = 1;
        const ImageF ids = testbed::renderTruth(testbed::TruthKind::ObjectId, truth);
        const ImageF color = testbed::renderTruth(testbed::TruthKind::Color, truth);
        Stat error;
        long within = 0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                if (!awayFromEdges(ids, x, y)) {
                    continue;
                }
                const glm::vec3 a(r.color.at(x, y)[0], r.color.at(x, y)[1], r.color.at(x, y)[2]);
                const glm::vec3 b(color.at(x, y)[0], color.at(x, y)[1], color.at(x, y)[2]);
                const double e = double(glm::length(a - b) / std::max(glm::length(b), 1e-3f));
                error.add(e);
                within += e <= 5e-3 ? 1 : 0;
            }
        }
        std::printf("frame %d colour: %.2f%% of %ld pixels within 0.5%%, mean relative error %.2e\n",
                    int(frame), 100.0 * double(within) / double(error.count), error.count, error.mean());
        EXPECT_GE(double(within), 0.99 * double(error.count)) << "frame " << frame;
        EXPECT_LE(error.mean(), 2e-3) << "frame " << frame;
    }
}

TEST_F(TestbedTest, TheSameFrameRendersBitIdentically) {
    const Raster a = rasterise(*scene, *pipeline, 40);
    rasterise(*scene, *pipeline, 7);
    const Raster b = rasterise(*scene, *pipeline, 40);
    EXPECT_EQ(a.color.rgba, b.color.rgba);
    EXPECT_EQ(a.depth, b.depth);
    EXPECT_EQ(a.normals.rgba, b.normals.rgba);
    EXPECT_EQ(a.motion.rgba, b.motion.rgba);
}

TEST_F(TestbedTest, TheCutFrameIsFlaggedAndHasNoCameraMotion) {
    for (std::uint64_t frame = 0; frame < 48; ++frame) {
        std::vector<double> telemetry;
        const FrameInputs in = scene->render({.dt = kDt, .frameIndex = frame}, *pipeline, telemetry);
        ASSERT_NE(in.camera, nullptr);
        ASSERT_NE(in.depth, nullptr);
        EXPECT_EQ(in.camera->cut, frame == 36) << "frame " << frame;
        EXPECT_EQ(telemetry.at(1), frame == 36 ? 1.0 : 0.0);
        EXPECT_EQ(invalidCameraReason(*in.camera), nullptr);
    }
    // On the cut, the sky (static, far away) has no motion: the previous camera is the current one.
    const Raster r = rasterise(*scene, *pipeline, 36);
    const float* sky = r.motion.at(kWidth / 2, 2);
    EXPECT_EQ(sky[0], 0.0f);
    EXPECT_EQ(sky[1], 0.0f);
}

// With a sub-pixel jitter the rasteriser's samples move and the ray tracer's follow them
// (TruthOptions::jitter): they still agree, and the motion has the jitter removed (it changes by far less
// than the jitter's 0.4 px).
TEST_F(TestbedTest, JitteredRasterisationAgreesWithTheJitteredTruthAndMotionIsUnjittered) {
    const FrameTime time{.dt = kDt, .frameIndex = 10};
    testbed::TruthOptions truth = scene->truthOptions(time);
    const Camera camera = testbed::truthCamera(truth);
    const std::vector<testbed::Primitive> prims =
        testbed::primitivesAt(truth.times.objects, truth.times.prevObjects);
    testbed::TestbedRenderer renderer;
    renderer.resize({kWidth, kHeight});
    truth.jitter = {0.37f, -0.21f};
    renderer.draw({.camera = &camera, .jitter = truth.jitter, .primitives = &prims});
    const std::vector<float> depth = readDepthTexture(renderer.depth());
    const ImageF jitteredMotion = readTextureF(renderer.motion());
    const ImageF ids = testbed::renderTruth(testbed::TruthKind::ObjectId, truth);
    const ImageF tDepth = testbed::renderTruth(testbed::TruthKind::Depth, truth);
    const ImageF tMotion = testbed::renderTruth(testbed::TruthKind::Motion, truth);
    Stat d, m;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            if (!awayFromEdges(ids, x, y)) {
                continue;
            }
            const glm::vec2 mr(jitteredMotion.at(x, y)[0] * kWidth, jitteredMotion.at(x, y)[1] * kHeight);
            const glm::vec2 mt(tMotion.at(x, y)[0] * kWidth, tMotion.at(x, y)[1] * kHeight);
            m.add(double(glm::length(mr - mt)));
            if (ids.at(x, y)[0] != 0.0f) {
                const float linear = linearDepthFromWindow(depth[std::size_t(y * kWidth + x)],
                                                           camera.nearPlane, camera.farPlane);
                d.add(double(std::abs(linear - tDepth.at(x, y)[0]) / tDepth.at(x, y)[0]));
            }
        }
    }
    std::printf("jittered: depth max %.2e (relative), motion max %.4f px\n", d.max, m.max);
    EXPECT_LE(d.max, 1e-3);
    EXPECT_LE(m.max, 0.05);
}

// The lighting stage's hook: an ambient-occlusion texture multiplies the ambient term and a sun-visibility
// texture the sun term; both at 0 leave only emission on objects, and the sky untouched.
TEST_F(TestbedTest, LightingTexturesMultiplyTheAmbientAndSunTerms) {
    const FrameTime time{.dt = kDt, .frameIndex = 10};
    const testbed::TruthOptions truth = scene->truthOptions(time);
    const Camera camera = testbed::truthCamera(truth);
    const std::vector<testbed::Primitive> prims =
        testbed::primitivesAt(truth.times.objects, truth.times.prevObjects);
    testbed::TestbedRenderer renderer;
    renderer.resize({kWidth, kHeight});
    renderer.draw({.camera = &camera, .primitives = &prims});
    const ImageF plain = readTextureF(renderer.color());
    const Texture one = makeTexture(ImageF(kWidth, kHeight, 1.0f), "ones");
    renderer.draw({.camera = &camera, .primitives = &prims, .ambientOcclusion = &one, .sunVisibility = &one});
    EXPECT_EQ(readTextureF(renderer.color()).rgba, plain.rgba);
    const Texture zero = makeTexture(ImageF(kWidth, kHeight, 0.0f), "zeros");
    renderer.draw(
        {.camera = &camera, .primitives = &prims, .ambientOcclusion = &zero, .sunVisibility = &zero});
    const ImageF dark = readTextureF(renderer.color());
    const ImageF ids = testbed::renderTruth(testbed::TruthKind::ObjectId, truth);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const float id = ids.at(x, y)[0];
            if (!awayFromEdges(ids, x, y)) {
                continue;
            }
            if (id == 0.0f) {
                EXPECT_EQ(dark.at(x, y)[0], plain.at(x, y)[0]);
            } else if (id != float(testbed::ids::kMover)) {
                EXPECT_EQ(dark.at(x, y)[0], 0.0f) << x << "," << y;
            }
        }
    }
}

// The scene's frame as an EXR frame: linear Z, world normals, motion in pixels with y down.
TEST_F(TestbedTest, TheExrFrameUsesTheFileConventions) {
    std::vector<double> telemetry;
    const FrameInputs in = scene->render({.dt = kDt, .frameIndex = 10}, *pipeline, telemetry);
    const ExrFrame f = exrFrameFromInputs(in);
    const testbed::TruthOptions truth = scene->truthOptions({.dt = kDt, .frameIndex = 10});
    const ImageF tDepth = testbed::renderTruth(testbed::TruthKind::Depth, truth);
    const ImageF tMotion = testbed::renderTruth(testbed::TruthKind::Motion, truth);
    const int x = kWidth / 2;
    const int y = kHeight - 10; // the ground in front of the camera
    const std::size_t i = std::size_t(y * kWidth + x);
    EXPECT_NEAR(f.depth[i], tDepth.at(x, y)[0], 1e-3f * tDepth.at(x, y)[0]);
    EXPECT_NEAR(f.normals[3 * i + 1], 1.0f, 1e-3f); // the ground's world normal is +y
    EXPECT_NEAR(f.motion[2 * i], tMotion.at(x, y)[0] * kWidth, 0.05f);
    EXPECT_NEAR(f.motion[2 * i + 1], -tMotion.at(x, y)[1] * kHeight, 0.05f);
    EXPECT_TRUE(f.camera.worldToCamera.has_value());
    EXPECT_TRUE(f.camera.worldToNDC.has_value());
}

// What the CLI writes for a frame reads back: the camera (view, projection, previous view-projection from the
// previous frame's file) and the layers.
TEST_F(TestbedTest, TheExrFrameRoundTripsThroughTheReader) {
    const std::filesystem::path dir = std::filesystem::path(PHOTOPIC_BINARY_DIR) / "test-testbed-exr";
    std::filesystem::create_directories(dir);
    std::vector<double> telemetry;
    const ExrFrame before =
        exrFrameFromInputs(scene->render({.dt = kDt, .frameIndex = 9}, *pipeline, telemetry));
    const FrameInputs in = scene->render({.dt = kDt, .frameIndex = 10}, *pipeline, telemetry);
    const ExrFrame written = exrFrameFromInputs(in);
    writeExrFrame(dir / "frame_0009.exr", before);
    writeExrFrame(dir / "frame_0010.exr", written);
    const ExrFrame previous = readExrFrame(dir / "frame_0009.exr");
    const ExrFrame read = readExrFrame(dir / "frame_0010.exr");
    ASSERT_EQ(read.depth.size(), written.depth.size());
    EXPECT_EQ(read.depth, written.depth);
    EXPECT_EQ(read.motion, written.motion);
    const std::optional<Camera> camera = cameraFromExr(read.camera, kWidth, kHeight, &previous.camera);
    ASSERT_TRUE(camera.has_value());
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            EXPECT_NEAR(camera->view[c][r], in.camera->view[c][r], 1e-4f) << c << r;
            EXPECT_NEAR(camera->projection[c][r], in.camera->projection[c][r], 1e-3f) << c << r;
            EXPECT_NEAR(camera->prevViewProjection[c][r], in.camera->prevViewProjection[c][r], 1e-3f)
                << c << r;
        }
    }
    EXPECT_NEAR(camera->nearPlane, in.camera->nearPlane, 1e-6f);
    EXPECT_NEAR(camera->farPlane, in.camera->farPlane, 1e-2f);
    EXPECT_NEAR(camera->lens.fNumber, in.camera->lens.fNumber, 1e-6f);
    EXPECT_NEAR(camera->lens.focusDistance, in.camera->lens.focusDistance, 1e-4f);
}

// The viewer's orbit camera: the first move holds the path's current view (a zero orbit keeps the eye, the
// view direction and the image), then orbits about the focused point at the same distance and zooms.
TEST_F(TestbedTest, TheInteractiveCameraHoldsThePathsViewThenOrbitsIt) {
    scene->applyOverride("cameraSpeed=0");
    const Raster before = rasterise(*scene, *pipeline, 3);
    InteractiveCamera* camera = scene->interactiveCamera();
    ASSERT_NE(camera, nullptr);
    camera->orbit(0.0f, 0.0f);
    ASSERT_TRUE(scene->settings().fixedCamera);
    const glm::vec3 eye = scene->settings().eye;
    const glm::vec3 pathEye = glm::vec3(glm::inverse(before.camera.view)[3]);
    EXPECT_LT(glm::length(eye - pathEye), 1e-4f);
    const float distance = glm::length(scene->settings().target - eye);
    EXPECT_NEAR(distance, testbed::cameraPoseAt(0.0).focusDistance, 1e-3f);
    // The held view is rebuilt with lookAt, which differs from the path's matrix by ~2e-6: a few samples on
    // thin edges (the fence's wires) flip, nothing else moves (measured: 91 of 57600 values).
    const Raster held = rasterise(*scene, *pipeline, 3);
    std::size_t moved = 0;
    for (std::size_t i = 0; i < held.color.rgba.size(); ++i) {
        moved += std::abs(held.color.rgba[i] - before.color.rgba[i]) > 1e-3f ? 1 : 0;
    }
    EXPECT_LE(double(moved), 0.005 * double(held.color.rgba.size()))
        << "holding the path's view moved the image";
    // Orbiting by a visible angle moves far more of the image.

    camera->orbit(0.5f, 0.2f);
    EXPECT_NEAR(glm::length(scene->settings().target - scene->settings().eye), distance, 1e-3f);
    EXPECT_GT(glm::length(scene->settings().eye - eye), 0.5f);
    const Raster orbited = rasterise(*scene, *pipeline, 3);
    std::size_t turned = 0;
    for (std::size_t i = 0; i < orbited.color.rgba.size(); ++i) {
        turned += std::abs(orbited.color.rgba[i] - before.color.rgba[i]) > 1e-3f ? 1 : 0;
    }
    EXPECT_GT(double(turned), 0.3 * double(orbited.color.rgba.size()));
    camera->zoom(0.5f);
    EXPECT_NEAR(glm::length(scene->settings().target - scene->settings().eye), distance * 0.5f, 1e-3f);
    // The held view is valid settings: it saves and loads back.
    EXPECT_TRUE(scene->applyOverride("sensorHeight=24").empty());
}

} // namespace photopic::test
