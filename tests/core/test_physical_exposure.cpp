// Physical exposure (exposure.mode = physical) and the lens's shutter helpers.

#include "core/Color.h"
#include "core/DepthOfField.h"
#include "core/ExposureController.h"
#include "core/PhysicalExposure.h"
#include "core/Settings.h"
#include "core/settings/SettingsJson.h"

#include <gtest/gtest.h>

#include <cmath>

namespace photopic {
namespace {

Lens sunny16() {
    Lens lens;
    lens.fNumber = 16.0f;
    lens.exposureTimeS = 0.01f;
    lens.iso = 100.0f;
    return lens;
}

TEST(PhysicalExposure, Ev100OfACameraSetting) {
    // f/16, 1/100 s, ISO 100: log2(256 / 0.01) = 14.64.
    EXPECT_NEAR(cameraEv100(sunny16(), 1.0f / 30.0f), 14.644f, 1e-3f);
    Lens iso = sunny16();
    iso.iso = 400.0f; // two stops more sensitive
    EXPECT_NEAR(cameraEv100(iso, 1.0f / 30.0f), 12.644f, 1e-3f);
}

TEST(PhysicalExposure, HalvingTheShutterHalvesTheExposure) {
    Lens lens = sunny16();
    const float full = std::exp2(cameraExposureLog2(lens, 1.0f / 30.0f));
    lens.exposureTimeS = 0.005f;
    const float half = std::exp2(cameraExposureLog2(lens, 1.0f / 30.0f));
    EXPECT_NEAR(half / full, 0.5f, 1e-4f);
    // The shutter angle when no exposure time is set: 180 degrees of a 1/30 s frame is 1/60 s.
    Lens angle;
    angle.shutterAngleDeg = 180.0f;
    EXPECT_NEAR(shutterTime(angle, 1.0f / 30.0f), 1.0f / 60.0f, 1e-7f);
    EXPECT_NEAR(shutterFraction(angle, 1.0f / 30.0f), 0.5f, 1e-6f);
    angle.shutterAngleDeg = 90.0f;
    EXPECT_NEAR(std::exp2(cameraExposureLog2(angle, 1.0f / 30.0f)) /
                    std::exp2(cameraExposureLog2(Lens{}, 1.0f / 30.0f)),
                0.5f, 1e-4f);
    // The saturation-based scale: 1 / (1.2 * 2^EV100).
    EXPECT_NEAR(std::exp2(cameraExposureLog2(sunny16(), 0.0f)), exposureFromEv100(14.644f), 1e-8f);
}

TEST(PhysicalExposure, AutoExposureIsACompensationAroundTheCamera) {
    AutoExposureSettings ae;
    ae.enabled = true;
    ae.minEV = -1.0f;
    ae.maxEV = 1.0f;
    const Lens lens = sunny16();
    const float camera = cameraExposureLog2(lens, 1.0f / 30.0f);
    const PhysicalExposureInputs in = physicalExposure(ae, 0.5f, lens, 1.0f / 30.0f);
    EXPECT_NEAR(in.manualEV, 0.5f + camera, 1e-5f);
    // A scene the camera exposes exactly to the key: no correction.
    const float luminance = ae.keyValue / std::exp2(camera);
    ExposureController controller(in.autoExposure);
    const ExposureState& s = controller.update(luminance, 1.0f / 30.0f, in.manualEV);
    EXPECT_NEAR(s.appliedLog2, 0.0f, 1e-3f);
    EXPECT_NEAR(std::log2(s.exposure), 0.5f + camera, 1e-3f);
    // Eight times brighter: the correction stops at minEV.
    ExposureController bright(in.autoExposure);
    EXPECT_NEAR(bright.update(8.0f * luminance, 1.0f / 30.0f, in.manualEV).appliedLog2, -1.0f, 1e-3f);
}

TEST(PhysicalExposure, ModeIsASettingWithNamedErrors) {
    Settings s;
    EXPECT_TRUE(readSettingsJson(R"({"postEffects": {"exposure": {"mode": "physical"}}})", s).empty());
    EXPECT_EQ(s.exposure.mode, ExposureMode::Physical);
    const auto issues = readSettingsJson(R"({"postEffects": {"exposure": {"mode": "film"}}})", s);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_NE(issues[0].path.find("exposure.mode"), std::string::npos);
}

} // namespace
} // namespace photopic
