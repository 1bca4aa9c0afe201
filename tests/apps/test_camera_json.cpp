#include "CameraJson.h"
#include "InputError.h"

#include "common/TempFolder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

namespace photopic::cli {
namespace {

constexpr const char* kName = "cam.json";

/// The InputError parseCameraJson throws for `text`, or "" when it accepts it.
std::string error(const std::string& text) {
    try {
        (void)parseCameraJson(text, kName);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

/// `key`'s value replaced in a valid camera (position and target given).
std::string with(const std::string& key, const std::string& value) {
    std::string text = R"({"position": [1, 2, 3], "target": [0, 0, 0])";
    return text + ", \"" + key + "\": " + value + "}";
}

void expectBadKey(const std::string& text, const std::string& key) {
    const std::string what = error(text);
    EXPECT_EQ(what.rfind(kName, 0), 0u) << text << " -> " << what;
    EXPECT_NE(what.find("camera key \"" + key + "\""), std::string::npos) << text << " -> " << what;
}

TEST(CameraJson, ReadsEveryKey) {
    const CameraJson c = parseCameraJson(R"({"position": [0, 1.6, 5], "target": [0, 1, 0], "up": [0, 0, 1],
        "verticalFovDeg": 40, "near": 0.5, "far": null, "lens": {"fNumber": 4, "iso": 800}})",
                                         kName);
    EXPECT_EQ(c.position, glm::vec3(0.0f, 1.6f, 5.0f));
    EXPECT_EQ(c.up, glm::vec3(0.0f, 0.0f, 1.0f));
    EXPECT_EQ(c.verticalFovDeg, 40.0f);
    EXPECT_EQ(c.nearPlane, 0.5f);
    EXPECT_TRUE(std::isinf(c.farPlane));
    EXPECT_EQ(c.lens.fNumber, 4.0f);
    EXPECT_EQ(c.lens.iso, 800.0f);
    EXPECT_EQ(invalidCameraReason(c.camera(160, 90)), nullptr);
}

TEST(CameraJson, ErrorsNameTheFileAndTheKey) {
    expectBadKey(with("verticalFovDeg", "180"), "verticalFovDeg");
    expectBadKey(with("near", "0"), "near");
    expectBadKey(with("colour", "1"), "colour");
    expectBadKey(R"({"position": [0, 0, 0]})", "target");
    expectBadKey(with("lens", R"({"fNumber": 0.1})"), "lens");
}

// Values beyond single precision, vectors too short or too long to normalise, and planes and angles whose
// projection overflows are each refused under their own key, not passed on as a non-finite camera or blamed
// on the lens.
TEST(CameraJson, ValuesBeyondSinglePrecisionNameTheirKey) {
    expectBadKey(with("near", "1e39"), "near");
    expectBadKey(with("lens", R"({"focusDistance": 1e300})"), "lens.focusDistance");
    expectBadKey(R"({"position": [1e39, 0, 0], "target": [0, 0, 0]})", "position");
    expectBadKey(R"({"position": [3e38, 0, 0], "target": [-3e38, 0, 0]})", "target");
    expectBadKey(with("up", "[0, 0, 0]"), "up");
    expectBadKey(with("up", "[1e-30, 1e-30, 0]"), "up");
    // A view whose translation overflows, and one whose product with a very wide frame's projection does.
    expectBadKey(R"({"position": [3e38, -3e38, 0], "target": [3e38, -3e38, -1], "up": [1, 1, 0]})",
                 "position");
    expectBadKey(R"({"position": [1e34, 0, 0], "target": [1e34, 0, -1]})", "position");
    expectBadKey(with("verticalFovDeg", "1e-36"), "verticalFovDeg");
    expectBadKey(with("far", "3e38"), "far");
}

TEST(CameraJson, AcceptedCamerasAreValidAtEveryFrameShape) {
    // A narrow field of view and a position far out: near the limits, yet finite for every frame.
    const CameraJson c = parseCameraJson(
        R"({"position": [1e30, 0, 0], "target": [1e30, 0, -1], "verticalFovDeg": 0.2})", kName);
    for (const auto& [width, height] : {std::pair{1, 1}, {kCameraJsonMaxSide, 1}, {1, kCameraJsonMaxSide}})
        EXPECT_EQ(invalidCameraReason(c.camera(width, height)), nullptr) << width << "x" << height;
}

TEST(CameraJson, LoadNamesAMissingFile) {
    const test::TempFolder folder;
    EXPECT_THROW((void)loadCameraJson(folder / "none.json"), InputError);
    std::ofstream(folder / "c.json") << R"({"position": [1, 2, 3], "target": [0, 0, 0], "near": -1})";
    try {
        (void)loadCameraJson(folder / "c.json");
        ADD_FAILURE() << "a negative near was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find((folder / "c.json").string() + ": camera key \"near\""),
                  std::string::npos)
            << e.what();
    }
}

// A physical camera as Blender gives it: cameraToWorld, focal length over a sensor with a fit, and a shift of
// the view window in fractions of the fitted side. A world point projects where the pinhole puts it.
TEST(CameraTrack, PhysicalCamerasProjectAsAPinhole) {
    const CameraJson c = parseCameraJson(
        R"({"cameraToWorld": [[1, 0, 0, 0.5], [0, 1, 0, 1], [0, 0, 1, 4], [0, 0, 0, 1]], "focalLengthMm": 50,
            "sensor": {"widthMm": 36, "heightMm": 24, "fit": "auto"}, "shift": [0.1, 0.05], "near": 0.1,
            "far": 100, "lens": {"fNumber": 2}, "sunDirection": [0, 2, 0]})",
        kName);
    ASSERT_TRUE(c.cameraToWorld.has_value());
    ASSERT_TRUE(c.sunDirection.has_value());
    EXPECT_EQ(*c.sunDirection, glm::vec3(0.0f, 1.0f, 0.0f));
    const Camera camera = c.camera(160, 90);
    // 2 m in front of the camera, 0.3 right and 0.2 up of its axis.
    const glm::vec4 clip = camera.viewProjection() * glm::vec4(0.5f + 0.3f, 1.0f + 0.2f, 4.0f - 2.0f, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    const float pixels = 50.0f / 36.0f * 160.0f; // the focal length in pixels: the sensor width spans 160
    const float u = 80.0f - 0.1f * 160.0f + pixels * 0.3f / 2.0f; // u right, v down
    const float v = 45.0f + 0.05f * 160.0f - pixels * 0.2f / 2.0f;
    EXPECT_NEAR((ndc.x * 0.5f + 0.5f) * 160.0f, u, 1e-3f);
    EXPECT_NEAR((0.5f - ndc.y * 0.5f) * 90.0f, v, 1e-3f);
    EXPECT_NEAR(camera.lens.focalLengthMm, 50.0f, 1e-5f);
    EXPECT_NEAR(camera.lens.sensorHeightMm, 36.0f * 90.0f / 160.0f, 1e-4f);
    EXPECT_EQ(camera.lens.fNumber, 2.0f);
    // Fit vertical: the sensor height spans the frame's height.
    const CameraJson vertical = parseCameraJson(
        R"({"position": [0, 0, 0], "target": [0, 0, -1], "focalLengthMm": 24,
            "sensor": {"widthMm": 36, "heightMm": 24, "fit": "vertical"}})",
        kName);
    EXPECT_NEAR(glm::degrees(vertical.camera(160, 90).verticalFov), 2.0f * glm::degrees(std::atan(0.5f)),
                1e-3f);
}

TEST(CameraTrack, FramesAreKeyedByFrameNumber) {
    const CameraTrack track = parseCameraTrack(
        R"({"fps": 24, "source": "a test", "frames": {
            "1001": {"position": [0, 0, 5], "target": [0, 0, 0]},
            "1002": {"position": [1, 0, 5], "target": [0, 0, 0], "lens": {"fNumber": 4}}}})",
        kName);
    EXPECT_FALSE(track.single.has_value());
    ASSERT_EQ(track.frames.size(), 2u);
    ASSERT_TRUE(track.fps.has_value());
    EXPECT_EQ(*track.fps, 24.0f);
    EXPECT_EQ(track.at(1002, "f1002.exr").lens.fNumber, 4.0f);
    try {
        (void)track.at(1003, "shot/f1003.exr");
        ADD_FAILURE() << "a frame the track lacks was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(
            std::string(e.what()).find("no camera for frame 1003 (shot/f1003.exr); the track holds frames "
                                       "1001 to 1002"),
            std::string::npos)
            << e.what();
    }
    EXPECT_THROW((void)track.at(std::nullopt, "still.exr"), InputError);
    // One camera is every frame's.
    const CameraTrack single = parseCameraTrack(R"({"position": [0, 0, 5], "target": [0, 0, 0]})", kName);
    EXPECT_EQ(&single.at(std::nullopt, "a.exr"), &*single.single);
}

TEST(CameraTrack, ErrorsNameTheFrameAndTheKey) {
    const auto trackError = [](const std::string& text) {
        try {
            (void)parseCameraTrack(text, kName);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    const std::string ok = R"("position": [0, 0, 5], "target": [0, 0, 0])";
    EXPECT_NE(
        trackError(R"({"frames": {"7": {)" + ok + R"(, "fov": 3}}})").find("camera key \"frames.7.fov\""),
        std::string::npos);
    EXPECT_NE(trackError(R"({"frames": {"2": {"position": [0, 0], "target": [0, 0, 0]}}})")
                  .find("camera key \"frames.2.position\": expected an array of 3"),
              std::string::npos);
    EXPECT_NE(trackError(R"({"frames": {"x": {)" + ok + "}}}").find("camera key \"frames.x\""),
              std::string::npos);
    EXPECT_NE(trackError(R"({"frames": {}})").find("camera key \"frames\""), std::string::npos);
    EXPECT_NE(trackError(R"({"frames": {"1": {"cameraToWorld": [[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0],
              [0, 0, 0, 1]]}}})")
                  .find("frames.1.cameraToWorld\": the upper 3x3 must be a rotation"),
              std::string::npos);
    EXPECT_NE(trackError(R"({"frames": {"1": {)" + ok + R"(, "shift": [0.1, 0]}}})")
                  .find("frames.1.shift\": needs focalLengthMm"),
              std::string::npos);
    EXPECT_NE(trackError(R"({"frames": {"1": {)" + ok + R"(, "focalLengthMm": 50, "verticalFovDeg": 40}}})")
                  .find("give either verticalFovDeg or focalLengthMm"),
              std::string::npos);
    EXPECT_NE(trackError(R"({"frames": {"1": {)" + ok +
                         R"(, "focalLengthMm": 50, "sensor": {"fit": "diagonal"}}}})")
                  .find("frames.1.sensor.fit"),
              std::string::npos);
    EXPECT_NE(trackError(R"({"fps": -1, "frames": {"1": {)" + ok + "}}}").find("camera key \"fps\""),
              std::string::npos);
}

} // namespace
} // namespace photopic::cli
