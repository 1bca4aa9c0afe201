// The testbed's CPU ray tracer (no GL): the camera path and its cut, and each truth kind behaving as its
// definition says.

#include "core/Color.h"
#include "scenes/testbed/TestbedRaytracer.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

namespace photopic::testbed {

namespace {

constexpr double kDt = 1.0 / 30.0;

TruthOptions options(std::uint64_t frame, int width = 160, int height = 90) {
    TruthOptions o;
    o.width = width;
    o.height = height;
    o.times = frameTimes(frame, kDt);
    o.dt = kDt;
    return o;
}

const Primitive& find(const std::vector<Primitive>& prims, std::uint32_t id) {
    for (const Primitive& p : prims) {
        if (p.id == id) {
            return p;
        }
    }
    throw std::logic_error("no such primitive");
}

double rmse(const ImageF& a, const ImageF& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
        for (int c = 0; c < 3; ++c) {
            const double d = double(a.rgba[i + std::size_t(c)]) - double(b.rgba[i + std::size_t(c)]);
            sum += d * d;
        }
    }
    return std::sqrt(sum / double(a.pixelCount() * 3));
}

double mean(const ImageF& a) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
        sum += double(a.rgba[i] + a.rgba[i + 1] + a.rgba[i + 2]) / 3.0;
    }
    return sum / double(a.pixelCount());
}

} // namespace

TEST(TestbedPath, OnlyTheFirstFrameOfTheSecondShotIsACut) {
    for (std::uint64_t frame = 0; frame < 48; ++frame) {
        const FrameTimes t = frameTimes(frame, kDt);
        const Camera c = testbedCamera(t.camera, t.prevCamera, 160, 90);
        EXPECT_EQ(c.cut, frame == 36) << "frame " << frame;
        EXPECT_EQ(invalidCameraReason(c), nullptr);
    }
    EXPECT_EQ(cameraPoseAt(0.5).shot, 0);
    EXPECT_EQ(cameraPoseAt(kCutTime).shot, 1);
}

TEST(TestbedPath, ClocksStartAndRunAtTheirRates) {
    const FrameTimes t = frameTimes(30, kDt, {0.5, 0.1}, {2.0, 2.0});
    EXPECT_NEAR(t.camera, 0.5 + 0.1, 1e-12);
    EXPECT_NEAR(t.prevCamera, 0.5 + 0.1 * 29.0 * kDt, 1e-12);
    EXPECT_NEAR(t.objects, 2.0 + 2.0, 1e-12);
    EXPECT_NEAR(t.prevObjects, 2.0 + 2.0 * 29.0 * kDt, 1e-12);
}

TEST(TestbedPath, StoppedClocksHoldTheFrame) {
    const FrameTimes t = frameTimes(30, kDt, {0.25, 0.0}, {0.5, 0.0});
    EXPECT_EQ(t.camera, 0.25);
    EXPECT_EQ(t.prevCamera, 0.25);
    EXPECT_EQ(t.objects, 0.5);
    EXPECT_EQ(t.prevObjects, 0.5);
    const Camera c = testbedCamera(t.camera, t.prevCamera, 160, 90);
    EXPECT_EQ(c.prevViewProjection, c.viewProjection());
}

TEST(TestbedTruth, AmbientOcclusionIsOneOnOpenGroundAndLessInTheCreaseUnderASphere) {
    const std::vector<Primitive> prims = primitivesAt(0.0, 0.0);
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    EXPECT_EQ(ambientOcclusionAt(prims, {20.0f, 0.0f, 20.0f}, up, 1.0f, 16), 1.0f);
    // 0.25 m from where the big sphere (radius 1) touches the ground.
    const glm::vec3 contact =
        glm::vec3(find(prims, ids::kBigSphere).toWorld[3]) - glm::vec3(0.0f, 1.0f, 0.0f);
    const float crease = ambientOcclusionAt(prims, contact + glm::vec3(0.25f, 0.0f, 0.0f), up, 1.0f, 16);
    EXPECT_LT(crease, 0.6f);
    EXPECT_GT(crease, 0.0f);
    // A smaller radius sees less of the sphere.
    EXPECT_GT(ambientOcclusionAt(prims, contact + glm::vec3(0.25f, 0.0f, 0.0f), up, 0.2f, 16), crease);
}

TEST(TestbedTruth, SunVisibilityIsZeroInTheCubesShadowAndHonoursTheMaximumDistance) {
    const std::vector<Primitive> prims = primitivesAt(0.0, 0.0);
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    const glm::vec3 centre(find(prims, ids::kCube).toWorld[3]);
    const glm::vec3 sun = environment().sunDirection;
    const glm::vec3 shadowed = centre - sun * (centre.y / sun.y); // on the ground, the cube's centre sunwards
    EXPECT_NEAR(shadowed.y, 0.0f, 1e-5f);
    EXPECT_EQ(sunVisibilityAt(prims, shadowed, up, 0.0f, 1), 0.0f);
    EXPECT_EQ(sunVisibilityAt(prims, shadowed, up, 0.0f, 4), 0.0f);
    EXPECT_EQ(sunVisibilityAt(prims, {20.0f, 0.0f, 20.0f}, up, 0.0f, 1), 1.0f);
    // The cube's centre is 1.2 m away along the ray: a contact-shadow distance of 0.3 m does not reach it.
    EXPECT_EQ(sunVisibilityAt(prims, shadowed, up, 0.3f, 1), 1.0f);
    EXPECT_EQ(sunVisibilityAt(prims, shadowed, up, 2.0f, 1), 0.0f);
    // A surface facing away from the sun is unlit.
    EXPECT_EQ(sunVisibilityAt(prims, {20.0f, 0.0f, 20.0f}, -sun, 0.0f, 1), 0.0f);
}

TEST(TestbedTruth, AoImageIsAVisibilityWithOpenSky) {
    TruthOptions o = options(10, 80, 45);
    o.aoSamples = 6;
    const ImageF ao = renderTruth(TruthKind::Ao, o);
    const ImageF ids = renderTruth(TruthKind::ObjectId, o);
    int below = 0;
    for (int y = 0; y < ao.height; ++y) {
        for (int x = 0; x < ao.width; ++x) {
            const float v = ao.at(x, y)[0];
            ASSERT_GE(v, 0.0f);
            ASSERT_LE(v, 1.0f);
            if (ids.at(x, y)[0] == 0.0f) {
                EXPECT_EQ(v, 1.0f);
            }
            below += v < 0.95f ? 1 : 0;
        }
    }
    EXPECT_GT(below, 20); // creases and corners exist in view
}

TEST(TestbedTruth, ShutterWithNoMotionEqualsColourAndDiffersWithMotion) {
    TruthOptions o = options(10, 64, 36);
    o.samples = 4;
    o.times = frameTimes(10, kDt, {0.3, 0.0}, {0.3, 0.0});
    EXPECT_EQ(renderTruth(TruthKind::Shutter, o).rgba, renderTruth(TruthKind::Color, o).rgba);
    o.times = frameTimes(10, kDt);
    EXPECT_GT(rmse(renderTruth(TruthKind::Shutter, o), renderTruth(TruthKind::Color, o)), 1e-3);
}

// shutterTimes instants per position: at the pixel centre (samples = 1), still, it is the rasteriser's colour
// exactly; moving, it differs, and one instant per position (the default) is the frame's still colour.
TEST(TestbedTruth, ShutterTimesAtThePixelCentre) {
    TruthOptions o = options(10, 64, 36);
    o.samples = 1;
    o.shutterTimes = 16;
    o.times = frameTimes(10, kDt, {0.3, 0.0}, {0.3, 0.0});
    EXPECT_EQ(renderTruth(TruthKind::Shutter, o).rgba, renderTruth(TruthKind::Color, o).rgba);
    o.times = frameTimes(10, kDt);
    const ImageF colour = renderTruth(TruthKind::Color, o);
    EXPECT_GT(rmse(renderTruth(TruthKind::Shutter, o), colour), 1e-3);
    o.shutterTimes = 1;
    EXPECT_EQ(renderTruth(TruthKind::Shutter, o).rgba, colour.rgba);
}

TEST(TestbedTruth, ThinLensAtF256IsThePinholeAndBlursWhenOpen) {
    TruthOptions o = options(10, 64, 36);
    o.samples = 4;
    const ImageF pinhole = renderTruth(TruthKind::Color, o);
    o.lens.fNumber = 256.0f;
    const double closed = rmse(renderTruth(TruthKind::ThinLens, o), pinhole);
    o.lens.fNumber = 0.7f;
    o.focusDistance = 1.0f; // everything in view is far behind the plane in focus
    const double open = rmse(renderTruth(TruthKind::ThinLens, o), pinhole);
    const double m = mean(pinhole);
    EXPECT_LT(closed, 0.01 * m);
    EXPECT_GT(open, 5.0 * closed);
}

TEST(TestbedTruth, PixelCentreKindsAreWellFormedAndDeterministic) {
    const TruthOptions o = options(44, 80, 45);
    const ImageF depth = renderTruth(TruthKind::Depth, o);
    const ImageF normals = renderTruth(TruthKind::Normals, o);
    const ImageF ids = renderTruth(TruthKind::ObjectId, o);
    const ImageF reflection = renderTruth(TruthKind::Reflection, o);
    for (int y = 0; y < o.height; ++y) {
        for (int x = 0; x < o.width; ++x) {
            const bool sky = ids.at(x, y)[0] == 0.0f;
            EXPECT_EQ(std::isinf(depth.at(x, y)[0]), sky);
            if (!sky) {
                const float* n = normals.at(x, y);
                EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0f, 1e-4f);
            }
            const float a = reflection.at(x, y)[3];
            EXPECT_TRUE(a == 0.0f || a == 1.0f);
        }
    }
    EXPECT_EQ(renderTruth(TruthKind::Depth, o).rgba, depth.rgba);
    EXPECT_EQ(renderTruth(TruthKind::Normals, o).rgba, normals.rgba);
}

// Not a check: the time of each kind at 160x90 with the defaults, for the record (disabled; run with
// --gtest_also_run_disabled_tests --gtest_filter='*TimesAt160x90').
TEST(TestbedTruth, DISABLED_TimesAt160x90) {
    const TruthOptions o = options(40);
    for (const TruthKind kind : allTruthKinds()) {
        const auto begin = std::chrono::steady_clock::now();
        const ImageF image = renderTruth(kind, o);
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        std::printf("  %-10s %.3f s\n", std::string(truthKindName(kind)).c_str(), s);
        EXPECT_EQ(image.width, 160);
    }
}

} // namespace photopic::testbed
