// Per-effect quality presets: each costly effect's `quality` key picks its count from one table, an
// explicit count overrides it, the names are shared, and the defaults are the high preset's counts.

#include "core/settings/SettingsJson.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <string>

namespace photopic {
namespace {

struct PresetCase {
    const char* effect; ///< the settings' section
    const char* count;  ///< its count key (0: the preset's)
    std::array<int, 4> counts;
    int (*resolved)(const Settings&);
};

const PresetCase kCases[] = {
    {"contactShadows",
     "steps",
     {8, 14, 22, 40},
     [](const Settings& s) { return s.contactShadows.stepCount(); }},
    {"ssr", "maxSteps", {48, 96, 200, 400}, [](const Settings& s) { return s.ssr.stepCount(); }},
    {"volumetricLight",
     "samples",
     {16, 32, 64, 128},
     [](const Settings& s) { return s.volumetricLight.sampleCount(); }},
    {"motionBlur",
     "sampleCount",
     {7, 11, 15, 25},
     [](const Settings& s) { return s.motionBlur.gatherCount(); }},
};

TEST(EffectPresets, DefaultsAreTheHighPresetsCounts) {
    const nlohmann::json post = settingsToJsonValue(Settings{})["postEffects"];
    for (const PresetCase& c : kCases) {
        EXPECT_EQ(post[c.effect]["quality"].get<std::string>(), "high") << c.effect;
        EXPECT_EQ(post[c.effect][c.count].get<int>(), 0) << c.effect;
        EXPECT_EQ(c.resolved(Settings{}), c.counts[2]) << c.effect;
    }
    // The counts the effects ran with before they had presets.
    Settings s;
    EXPECT_EQ(s.contactShadows.stepCount(), 22);
    EXPECT_EQ(s.ssr.stepCount(), 200);
    EXPECT_EQ(s.volumetricLight.sampleCount(), 64);
    EXPECT_EQ(s.motionBlur.gatherCount(), 15);
}

TEST(EffectPresets, EachPresetPicksItsCountAndAnExplicitCountWins) {
    const auto names = effectQualityNames();
    for (const PresetCase& c : kCases) {
        for (std::size_t q = 0; q < names.size(); ++q) {
            Settings s;
            applySettingsOverride(s, std::string(c.effect) + ".quality=" + std::string(names[q]));
            EXPECT_EQ(c.resolved(s), c.counts[q]) << c.effect << " " << names[q];
            applySettingsOverride(s, std::string(c.effect) + "." + c.count + "=9");
            EXPECT_EQ(c.resolved(s), 9) << c.effect << " " << names[q];
            Settings loaded; // the preset and the override survive a save and a load
            ASSERT_TRUE(readSettingsJson(settingsToJson(s), loaded).empty()) << c.effect;
            EXPECT_EQ(settingsToJson(loaded), settingsToJson(s)) << c.effect;
            applySettingsOverride(s, std::string(c.effect) + "." + c.count + "=0");
            EXPECT_EQ(c.resolved(s), c.counts[q]) << c.effect << " " << names[q];
        }
    }
    // SSR's presets also choose the trace's resolution, unless `ssr.resolution` names one.
    const bool halfAt[] = {true, true, false, false};
    for (std::size_t q = 0; q < names.size(); ++q) {
        Settings s;
        applySettingsOverride(s, "ssr.quality=" + std::string(names[q]));
        EXPECT_EQ(s.ssr.halfResolution(), halfAt[q]) << names[q];
        applySettingsOverride(s, "ssr.resolution=full");
        EXPECT_FALSE(s.ssr.halfResolution()) << names[q];
        applySettingsOverride(s, "ssr.resolution=half");
        EXPECT_TRUE(s.ssr.halfResolution()) << names[q];
    }
    EXPECT_EQ(settingsToJsonValue(Settings{})["postEffects"]["ssr"]["resolution"].get<std::string>(), "preset");
    EXPECT_FALSE(Settings{}.ssr.halfResolution()); // the default, high: full resolution as before presets

    // The presets grow with the name, so low is the cheapest.
    for (const PresetCase& c : kCases) {
        for (std::size_t q = 1; q < c.counts.size(); ++q) {
            EXPECT_LT(c.counts[q - 1], c.counts[q]) << c.effect;
        }
    }
}

TEST(EffectPresets, BadValuesAreNamedAndChangeNothing) {
    const struct {
        const char* body;
        const char* path;
        SettingsIssueCode code;
    } cases[] = {
        {R"({"contactShadows": {"quality": "extreme"}})", "postEffects.contactShadows.quality",
         SettingsIssueCode::BadEnum},
        {R"({"contactShadows": {"steps": -1}})", "postEffects.contactShadows.steps",
         SettingsIssueCode::OutOfRange},
        {R"({"ssr": {"quality": "max"}})", "postEffects.ssr.quality", SettingsIssueCode::BadEnum},
        {R"({"ssr": {"maxSteps": 1001}})", "postEffects.ssr.maxSteps", SettingsIssueCode::OutOfRange},
        {R"({"volumetricLight": {"samples": 3}})", "postEffects.volumetricLight.samples",
         SettingsIssueCode::Constraint},
        {R"({"motionBlur": {"sampleCount": 2}})", "postEffects.motionBlur.sampleCount",
         SettingsIssueCode::Constraint},
        {R"({"motionBlur": {"quality": 2}})", "postEffects.motionBlur.quality", SettingsIssueCode::WrongType},
    };
    for (const auto& c : cases) {
        Settings s;
        const std::string before = settingsToJson(s);
        const std::vector<SettingsIssue> issues =
            readSettingsJson(std::string(R"({"postEffects": )") + c.body + "}", s);
        ASSERT_EQ(issues.size(), 1u) << c.body;
        EXPECT_EQ(issues[0].code, c.code) << c.body;
        EXPECT_EQ(issues[0].path, c.path) << c.body;
        EXPECT_EQ(settingsToJson(s), before) << c.body; // nothing applied
    }
}

} // namespace
} // namespace photopic
