// volumetricLight.* settings (defaults, the older files' keys, ranges by JSON path) and the CPU side of the
// pass: the sun's screen position, its fade as it leaves the screen, and the reference scattering against
// the analytic mean of a uniform sky.

#include "core/VolumetricLight.h"
#include "core/settings/SettingsJson.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

namespace photopic {
namespace {

std::vector<SettingsIssue> readVolumetric(const std::string& body, Settings& s) {
    return readSettingsJson(R"({"postEffects": {"volumetricLight": )" + body + "}}", s);
}

TEST(VolumetricLightSettings, DefaultsAreOffWithTheDocumentedValues) {
    const nlohmann::json v = settingsToJsonValue(Settings{})["postEffects"]["volumetricLight"];
    EXPECT_FALSE(v["enabled"].get<bool>());
    EXPECT_DOUBLE_EQ(v["intensity"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(v["density"].get<double>(), 1.0);
    EXPECT_NEAR(v["decay"].get<double>(), 0.97, 1e-7);
    EXPECT_DOUBLE_EQ(v["weight"].get<double>(), 1.0);
    EXPECT_NEAR(v["exposure"].get<double>(), 0.005, 1e-9);
    EXPECT_EQ(v["samples"].get<int>(), 0); // the quality preset's: 64 at high
    EXPECT_EQ(Settings{}.volumetricLight.sampleCount(), 64);
    EXPECT_EQ(v["mode"].get<std::string>(), "auto");
    EXPECT_EQ(v["resolution"].get<std::string>(), "half");
    EXPECT_NEAR(v["scattering"].get<double>(), 0.02, 1e-7);
    EXPECT_NEAR(v["anisotropy"].get<double>(), 0.6, 1e-7);
    EXPECT_DOUBLE_EQ(v["maxDistance"].get<double>(), 100.0);
}

TEST(VolumetricLightSettings, TheOlderFilesKeysLoad) {
    Settings s;
    ASSERT_TRUE(
        readVolumetric(R"({"enabled": true, "intensity": 2.0, "density": 0.8, "decay": 0.95})", s).empty());
    EXPECT_TRUE(s.volumetricLight.enabled);
    EXPECT_FLOAT_EQ(s.volumetricLight.intensity, 2.0f);
    EXPECT_FLOAT_EQ(s.volumetricLight.density, 0.8f);
    EXPECT_FLOAT_EQ(s.volumetricLight.decay, 0.95f);
    Settings loaded;
    ASSERT_TRUE(readSettingsJson(settingsToJson(s), loaded).empty());
    EXPECT_EQ(settingsToJson(loaded), settingsToJson(s)); // save then load is lossless
    applySettingsOverride(s, "volumetricLight.samples=128");
    EXPECT_EQ(s.volumetricLight.samples, 128);
    applySettingsOverride(s, "debug.view=volumetric-light");
    EXPECT_EQ(s.debug.view, DebugView::VolumetricLight);
    EXPECT_THROW(applySettingsOverride(s, "volumetricLight.decay=1.5"), SettingsError);
}

TEST(VolumetricLightSettings, ErrorsAreNamedByJsonPath) {
    Settings s;
    const struct {
        const char* body;
        const char* path;
        SettingsIssueCode code;
    } cases[] = {
        {R"({"intensity": -1})", "postEffects.volumetricLight.intensity", SettingsIssueCode::OutOfRange},
        {R"({"density": 3})", "postEffects.volumetricLight.density", SettingsIssueCode::OutOfRange},
        {R"({"decay": 1.01})", "postEffects.volumetricLight.decay", SettingsIssueCode::OutOfRange},
        {R"({"weight": 17})", "postEffects.volumetricLight.weight", SettingsIssueCode::OutOfRange},
        {R"({"exposure": 2})", "postEffects.volumetricLight.exposure", SettingsIssueCode::OutOfRange},
        {R"({"samples": 2})", "postEffects.volumetricLight.samples", SettingsIssueCode::Constraint},
        {R"({"samples": 257})", "postEffects.volumetricLight.samples", SettingsIssueCode::OutOfRange},
        {R"({"samples": 8.5})", "postEffects.volumetricLight.samples", SettingsIssueCode::WrongType},
        {R"({"decay": "slow"})", "postEffects.volumetricLight.decay", SettingsIssueCode::WrongType},
        {R"({"enabled": 1})", "postEffects.volumetricLight.enabled", SettingsIssueCode::WrongType},
        {R"({"numSamples": 64})", "postEffects.volumetricLight.numSamples", SettingsIssueCode::UnknownKey},
        {R"({"mode": "raymarch"})", "postEffects.volumetricLight.mode", SettingsIssueCode::BadEnum},
        {R"({"resolution": "full"})", "postEffects.volumetricLight.resolution", SettingsIssueCode::BadEnum},
        {R"({"scattering": -0.1})", "postEffects.volumetricLight.scattering", SettingsIssueCode::OutOfRange},
        {R"({"anisotropy": 1})", "postEffects.volumetricLight.anisotropy", SettingsIssueCode::OutOfRange},
        {R"({"maxDistance": 0})", "postEffects.volumetricLight.maxDistance", SettingsIssueCode::OutOfRange},
    };
    for (const auto& c : cases) {
        const std::vector<SettingsIssue> issues = readVolumetric(c.body, s);
        ASSERT_EQ(issues.size(), 1u) << c.body;
        EXPECT_EQ(issues[0].code, c.code) << c.body;
        EXPECT_EQ(issues[0].path, c.path) << c.body;
    }
    s.volumetricLight.density = -0.5f; // set through the API: validation names it
    const std::vector<SettingsIssue> issues = validateSettings(s);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].path, "postEffects.volumetricLight.density");
}

Camera cameraLookingAlong(glm::vec3 forward) {
    Camera c;
    c.view = glm::lookAt(glm::vec3(1.0f, 2.0f, 3.0f), glm::vec3(1.0f, 2.0f, 3.0f) + forward,
                         glm::vec3(0.0f, 1.0f, 0.0f));
    c.projection = perspectiveProjection(0.785398f, 16.0f / 9.0f, 0.1f, 100.0f);
    return c;
}

TEST(VolumetricLight, TheSunProjectsWhereTheCameraLooks) {
    const glm::vec3 sun = glm::normalize(glm::vec3(-0.3f, 0.4f, -0.9f));
    const SunOnScreen centred = sunOnScreen(cameraLookingAlong(sun), sun * 5.0f); // any length
    EXPECT_TRUE(centred.inFront);
    EXPECT_NEAR(centred.uv.x, 0.5f, 1e-5f);
    EXPECT_NEAR(centred.uv.y, 0.5f, 1e-5f);
    EXPECT_FLOAT_EQ(centred.fade, 1.0f);
    const SunOnScreen behind = sunOnScreen(cameraLookingAlong(-sun), sun);
    EXPECT_FALSE(behind.inFront);
    EXPECT_EQ(behind.fade, 0.0f);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(sunOnScreen(cameraLookingAlong(sun), glm::vec3(0.0f)).fade, 0.0f);
    EXPECT_EQ(sunOnScreen(cameraLookingAlong(sun), glm::vec3(nan, 0.0f, 1.0f)).fade, 0.0f);
}

TEST(VolumetricLight, TheFadeFallsSmoothlyToZeroAsTheSunLeavesTheScreen) {
    EXPECT_EQ(sunScreenFade({0.5f, 0.5f}), 1.0f);
    EXPECT_EQ(sunScreenFade({kVolumetricSunFadeInside, 0.5f}), 1.0f);
    EXPECT_EQ(sunScreenFade({0.5f, 1.0f - kVolumetricSunFadeInside}), 1.0f);
    const float middle = 0.5f * (kVolumetricSunFadeOutside - kVolumetricSunFadeInside);
    EXPECT_NEAR(sunScreenFade({-middle, 0.5f}), 0.5f, 1e-6f);
    EXPECT_NEAR(sunScreenFade({0.5f, 1.0f + middle}), 0.5f, 1e-6f);
    EXPECT_EQ(sunScreenFade({-kVolumetricSunFadeOutside, 0.5f}), 0.0f);
    EXPECT_EQ(sunScreenFade({0.5f, -2.0f}), 0.0f);
    float last = 1.0f;
    for (int i = 1; i <= 40; ++i) {
        const float f = sunScreenFade({0.9f + 0.005f * float(i), 0.5f});
        EXPECT_LE(f, last) << i;
        last = f;
    }
}

// A uniform sky of radiance c with the sun on screen: every pixel's samples reach the sun within the image,
// so the light is c x scale x the mean of decay^(64 t) over t in [0, 1]: (1 - decay^64) / (-64 ln decay).
TEST(VolumetricLight, TheReferenceOfAUniformSkyIsTheAnalyticMean) {
    const int w = 48, h = 27;
    ImageF color(w, h, 2.0f), depth(w, h, std::numeric_limits<float>::infinity());
    const VolumetricLightSettings s;
    const SunOnScreen sun{.uv = {0.4f, 0.6f}, .inFront = true, .fade = 1.0f};
    const ImageF light = volumetricLightReference(color, depth, sun, s, 512);
    const double mean = (1.0 - std::pow(double(s.decay), 64.0)) / (-64.0 * std::log(double(s.decay)));
    const double expected = 2.0 * double(s.intensity * s.weight * s.exposure) * mean;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            ASSERT_NEAR(light.at(x, y)[0], expected, 1e-3 * expected) << x << ", " << y;
        }
    }
    // Occluders block: with every pixel a surface there is no source at all.
    ImageF surfaces(w, h, 4.0f);
    const ImageF none = volumetricLightReference(color, surfaces, sun, s, 64);
    for (float v : none.rgba) {
        ASSERT_TRUE(v == 0.0f || v == 1.0f); // RGB 0, alpha 1
    }
}

} // namespace
} // namespace photopic
