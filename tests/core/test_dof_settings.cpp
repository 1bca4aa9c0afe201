// Depth of field's settings and its CPU CoC model (the constants the CoC pass takes).

#include "core/DepthOfField.h"
#include "core/Settings.h"
#include "core/settings/SettingsJson.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace photopic {
namespace {

TEST(DofSettings, KeysLoadAndBadValuesNameTheirPath) {
    Settings s;
    EXPECT_TRUE(readSettingsJson(R"({"postEffects": {"dof": {"enabled": true, "mode": "artistic",
        "kernel": "hexagon", "quality": "high", "maxCocRadius": 24, "focalDistance": 3, "focalRange": 2,
        "bokehRadius": 6}}})",
                                 s)
                    .empty());
    EXPECT_TRUE(s.dof.enabled);
    EXPECT_EQ(s.dof.mode, DofMode::Artistic);
    EXPECT_EQ(s.dof.kernel, DofKernel::Hexagon);
    EXPECT_EQ(s.dof.quality, DofQuality::High);
    EXPECT_EQ(s.dof.maxCocRadius, 24.0f);
    const auto issues = readSettingsJson(R"({"postEffects": {"dof": {"maxCocRadius": 100}}})", s);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].path, "postEffects.dof.maxCocRadius");
    EXPECT_EQ(s.dof.maxCocRadius, 24.0f); // unchanged
}

TEST(DepthOfFieldModel, ThinLensRadiusInPixels) {
    Lens lens;
    lens.focalLengthMm = 50.0f;
    lens.sensorHeightMm = 24.0f;
    lens.fNumber = 2.0f;
    lens.focusDistance = 2.0f;
    DofSettings s;
    s.maxCocRadius = 64.0f;
    const CocModel m = cocModel(s, lens, 1080);
    // c = (f / N) f |z - F| / (z (F - f)) on the sensor; radius in pixels = c / 2 / h * H.
    const auto expected = [](double z) {
        const double f = 0.05, n = 2.0, focus = 2.0;
        return (f / n) * f * (z - focus) / (z * (focus - f)) / 2.0 / 0.024 * 1080.0;
    };
    EXPECT_NEAR(m.radius(2.0f), 0.0f, 1e-4f);
    EXPECT_NEAR(m.radius(4.0f), expected(4.0), 1e-3);
    EXPECT_NEAR(m.radius(1.5f), expected(1.5), 1e-3);
    EXPECT_LT(m.radius(1.5f), 0.0f); // near: negative
    EXPECT_NEAR(m.radius(std::numeric_limits<float>::infinity()),
                1080.0 * 0.05 * 0.05 / (2 * 2 * 1.95 * 0.024), 1e-3);
    EXPECT_EQ(m.radius(std::numeric_limits<float>::quiet_NaN()), 0.0f);
    EXPECT_EQ(m.radius(0.06f), -64.0f); // clamped
}

TEST(DepthOfFieldModel, ArtisticRadius) {
    DofSettings s;
    s.mode = DofMode::Artistic;
    const CocModel m = cocModel(s, Lens{}, 1080);
    EXPECT_EQ(m.radius(10.0f), 0.0f);
    EXPECT_NEAR(m.radius(12.5f), 2.0f, 1e-6f);
    EXPECT_EQ(m.radius(100.0f), 4.0f);
    EXPECT_EQ(m.radius(1.0f), -4.0f);
    EXPECT_EQ(m.radius(std::numeric_limits<float>::infinity()), 4.0f);
}

} // namespace
} // namespace photopic
