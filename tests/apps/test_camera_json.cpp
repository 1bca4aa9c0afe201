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

} // namespace
} // namespace photopic::cli
