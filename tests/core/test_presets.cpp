// Named presets: each is a valid look, a settings document's "preset" is applied before its own keys, and a
// bad name is an issue that lists the presets.

#include "core/settings/SettingsJson.h"

#include <gtest/gtest.h>

#include <string>

namespace photopic {
namespace {

TEST(Presets, EveryNameGivesValidSettings) {
    ASSERT_EQ(presetNames().size(), 3u);
    for (const std::string_view name : presetNames()) {
        const std::optional<Settings> s = Settings::preset(name);
        ASSERT_TRUE(s.has_value()) << name;
        EXPECT_TRUE(validateSettings(*s).empty()) << name;
    }
    EXPECT_FALSE(Settings::preset("Stills").has_value()); // names are exact, as enum names are
    EXPECT_FALSE(Settings::preset("").has_value());
}

TEST(Presets, RealtimeIsTheDefaultsAndStillsOnlyChangesBloomAndTheCurve) {
    EXPECT_EQ(settingsToJson(Settings::realtime()), settingsToJson(Settings{}));
    Settings stills = Settings::stills();
    EXPECT_EQ(stills.bloom.mode, BloomMode::Threshold);
    EXPECT_GT(stills.bloom.threshold, 1.0f); // only what lies well past display white blooms
    EXPECT_EQ(stills.tonemapping.mode, ToneMapper::Agx);
    EXPECT_EQ(stills.tonemapping.agxLook, AgxLook::Base);
    stills.bloom = BloomSettings{};
    stills.tonemapping.mode = Settings{}.tonemapping.mode;
    stills.tonemapping.agxLook = Settings{}.tonemapping.agxLook;
    EXPECT_EQ(settingsToJson(stills), settingsToJson(Settings{}));
}

TEST(Presets, TheToneCurveIsPartOfALook) {
    Settings s = Settings::stills();
    s.tonemapping.exposure = 1.5f;
    s.applyLook(Settings::realtime());
    EXPECT_EQ(s.tonemapping.mode, Settings{}.tonemapping.mode);
    EXPECT_EQ(s.tonemapping.exposure, 1.5f); // exposure is not
}

TEST(Presets, NeutralTurnsEveryLookEffectOff) {
    const Settings n = Settings::neutral();
    EXPECT_FALSE(n.bloom.enabled);
    EXPECT_FALSE(n.lensFlare.enabled);
    EXPECT_FALSE(n.vignette.enabled);
    EXPECT_FALSE(n.grain.enabled);
    EXPECT_FALSE(n.dazzle.enabled);
    EXPECT_FALSE(n.colorGrading.enabled);
}

TEST(Presets, ApplyLookKeepsWhatIsNotTheLook) {
    Settings s;
    s.autoExposure.enabled = true;
    s.tonemapping.exposure = 1.5f;
    s.grain.enabled = true;
    s.applyLook(Settings::neutral());
    EXPECT_TRUE(s.autoExposure.enabled);
    EXPECT_EQ(s.tonemapping.exposure, 1.5f);
    EXPECT_FALSE(s.grain.enabled);
    EXPECT_FALSE(s.bloom.enabled);
}

TEST(Presets, DocumentPresetComesFirstAndItsKeysOnTop) {
    Settings s;
    const auto issues =
        readSettingsJson(R"({"preset": "stills", "postEffects": {"bloom": {"intensity": 0.5}}})", s);
    ASSERT_TRUE(issues.empty());
    EXPECT_EQ(s.bloom.mode, BloomMode::Threshold);
    EXPECT_EQ(s.bloom.threshold, BloomSettings::stills().threshold);
    EXPECT_EQ(s.bloom.intensity, 0.5f);
}

TEST(Presets, IgnoredDocumentPresetIsStillChecked) {
    Settings s = Settings::neutral();
    ASSERT_TRUE(readSettingsJson(R"({"preset": "stills"})", s, DocumentPreset::Ignore).empty());
    EXPECT_FALSE(s.bloom.enabled); // the caller's look stays
    const auto issues = readSettingsJson(R"({"preset": "sunset"})", s, DocumentPreset::Ignore);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].code, SettingsIssueCode::BadEnum);
}

TEST(Presets, UnknownOrMistypedPresetIsAnIssueListingThePresets) {
    Settings s;
    s.tonemapping.exposure = 2.0f;
    auto issues =
        readSettingsJson(R"({"preset": "sunset", "postEffects": {"tonemapping": {"exposure": 0}}})", s);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].code, SettingsIssueCode::BadEnum);
    EXPECT_EQ(issues[0].path, "preset");
    EXPECT_NE(issues[0].message.find("sunset"), std::string::npos);
    EXPECT_NE(issues[0].message.find("stills, realtime, neutral"), std::string::npos);
    EXPECT_EQ(s.tonemapping.exposure, 2.0f); // a document with issues changes nothing
    issues = readSettingsJson(R"({"preset": 1})", s);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].code, SettingsIssueCode::WrongType);
    EXPECT_EQ(issues[0].path, "preset");
}

} // namespace
} // namespace photopic
