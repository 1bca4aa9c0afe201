#include "core/settings/AutoExposureSettings.h"

#include "core/settings/SettingsJson.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

namespace photopic {
namespace {

std::vector<SettingsIssue> readAutoExposure(const std::string& body, Settings& settings) {
    return readSettingsJson(R"({"version": 1, "postEffects": {"autoExposure": )" + body + "}}", settings);
}

/// Reads `body` into default settings and expects exactly one issue with this code and path.
void expectIssue(const std::string& body, SettingsIssueCode code, const std::string& path) {
    Settings settings;
    const auto issues = readAutoExposure(body, settings);
    ASSERT_EQ(issues.size(), 1u) << body << "\n" << formatSettingsIssues(issues);
    EXPECT_EQ(issues[0].code, code) << formatSettingsIssues(issues);
    EXPECT_EQ(issues[0].path, path);
    // A document with issues leaves the settings as they were.
    EXPECT_EQ(settingsToJson(settings), settingsToJson(Settings{}));
}

TEST(AutoExposureSettings, DefaultsFollowTheOwnerDecisions) {
    const AutoExposureSettings s;
    EXPECT_FALSE(s.enabled);
    EXPECT_EQ(s.metering, MeteringMode::Average);
    EXPECT_EQ(s.adaptation, AdaptationMode::Exponential);
    EXPECT_EQ(s.keyValue, 0.18f);
    EXPECT_EQ(s.compensationEV, 0.0f);
    EXPECT_EQ(s.minEV, -2.0f);
    EXPECT_EQ(s.maxEV, 2.0f);
    EXPECT_EQ(s.tauBrighten, 1.0f);
    EXPECT_EQ(s.tauDarken, 0.3f);
    EXPECT_EQ(s.speedUp, 3.0f);
    EXPECT_EQ(s.speedDown, 1.0f);
    EXPECT_EQ(s.transitionEV, 1.5f);
    EXPECT_EQ(s.deadbandEV, 0.02f);
    EXPECT_EQ(s.maxDt, 0.1f);
    EXPECT_LE(s.histogramLog2Min, -10.0f);
    EXPECT_GE(s.histogramLog2Max, 10.0f);
    EXPECT_EQ(s.lowPercent, 10.0f);
    EXPECT_EQ(s.highPercent, 90.0f);
    EXPECT_EQ(s.spot.taps, 9);
    EXPECT_TRUE(s.compensationCurve.empty());
    EXPECT_TRUE(s.mask.path.empty());
    EXPECT_EQ(meteringModeNames().size(), 6u);
    EXPECT_EQ(meteringModeNames()[std::size_t(MeteringMode::Subject)], "subject");
    EXPECT_EQ(adaptationModeNames()[2], "hybrid");
}

TEST(AutoExposureSettings, DefaultsAndEditsRoundTripThroughJson) {
    const Settings defaults;
    const std::string text = settingsToJson(defaults);
    const auto doc = nlohmann::json::parse(text);
    ASSERT_TRUE(doc["postEffects"].contains("autoExposure"));
    const auto& ae = doc["postEffects"]["autoExposure"];
    EXPECT_EQ(ae["metering"], "average");
    EXPECT_EQ(ae["adaptation"], "exponential");
    EXPECT_EQ(ae["spot"]["taps"], 9);
    // Aliases are read, never written.
    EXPECT_FALSE(ae.contains("speed"));
    EXPECT_FALSE(ae.contains("min"));
    EXPECT_FALSE(ae.contains("max"));

    Settings edited;
    auto& e = edited.autoExposure;
    e.enabled = true;
    e.metering = MeteringMode::Spot;
    e.adaptation = AdaptationMode::Hybrid;
    e.compensationEV = -0.5f;
    e.compensationCurve = {{-6.0f, 1.0f}, {0.0f, 0.0f}, {8.0f, -1.5f}};
    e.tauDarken = 0.25f;
    e.spot = {0.3f, 0.7f, 0.05f, 13};
    e.mask.path = "masks/centre.png";
    Settings back;
    EXPECT_TRUE(readSettingsJson(settingsToJson(edited), back).empty());
    EXPECT_EQ(settingsToJson(back), settingsToJson(edited));
    EXPECT_EQ(back.autoExposure.compensationCurve, e.compensationCurve);
    EXPECT_EQ(back.autoExposure.spot.taps, 13);
    EXPECT_EQ(back.autoExposure.mask.path, "masks/centre.png");

    // And the defaults read back over edited settings restore them.
    EXPECT_TRUE(readSettingsJson(text, back).empty());
    EXPECT_EQ(settingsToJson(back), text);
}

TEST(AutoExposureSettings, OutOfRangeNamesTheJsonPath) {
    expectIssue(R"({"tauDarken": 100})", SettingsIssueCode::OutOfRange, "postEffects.autoExposure.tauDarken");
    expectIssue(R"({"tauDarken": 0})", SettingsIssueCode::OutOfRange, "postEffects.autoExposure.tauDarken");
    expectIssue(R"({"spot": {"radius": 2}})", SettingsIssueCode::OutOfRange,
                "postEffects.autoExposure.spot.radius");
    expectIssue(R"({"spot": {"taps": 14}})", SettingsIssueCode::OutOfRange,
                "postEffects.autoExposure.spot.taps");
    expectIssue(R"({"tauDarken": "fast"})", SettingsIssueCode::WrongType,
                "postEffects.autoExposure.tauDarken");
    expectIssue(R"({"speedUpp": 3})", SettingsIssueCode::UnknownKey, "postEffects.autoExposure.speedUpp");
}

TEST(AutoExposureSettings, BadEnumName) {
    expectIssue(R"({"metering": "matrix"})", SettingsIssueCode::BadEnum, "postEffects.autoExposure.metering");
    expectIssue(R"({"adaptation": "linear"})", SettingsIssueCode::BadEnum,
                "postEffects.autoExposure.adaptation");
}

TEST(AutoExposureSettings, ConstraintsBetweenFields) {
    expectIssue(R"({"compensationCurve": [[0, 0], [-1, 1]]})", SettingsIssueCode::Constraint,
                "postEffects.autoExposure.compensationCurve");
    expectIssue(R"({"compensationCurve": [[0, 0], [0, 1]]})", SettingsIssueCode::Constraint,
                "postEffects.autoExposure.compensationCurve");
    std::string seventeen = "[";
    for (int i = 0; i < 17; ++i) {
        seventeen += (i ? ", [" : "[") + std::to_string(i) + ", 0]";
    }
    expectIssue(R"({"compensationCurve": )" + seventeen + "]}", SettingsIssueCode::Constraint,
                "postEffects.autoExposure.compensationCurve");
    expectIssue(R"({"minEV": 1, "maxEV": -1})", SettingsIssueCode::Constraint,
                "postEffects.autoExposure.minEV");
    expectIssue(R"({"histogramLog2Min": 4, "histogramLog2Max": 4})", SettingsIssueCode::Constraint,
                "postEffects.autoExposure.histogramLog2Min");
    expectIssue(R"({"lowPercent": 90, "highPercent": 10})", SettingsIssueCode::Constraint,
                "postEffects.autoExposure.lowPercent");
    expectIssue(R"({"spot": {"taps": 7}})", SettingsIssueCode::Constraint,
                "postEffects.autoExposure.spot.taps");

    // y may take any shape once x increases strictly.
    Settings ok;
    EXPECT_TRUE(readAutoExposure(R"({"compensationCurve": [[-4, 1], [0, -1], [4, 1]]})", ok).empty());
    EXPECT_EQ(ok.autoExposure.compensationCurve.size(), 3u);
}

TEST(AutoExposureSettings, LegacyKeysStayReadable) {
    Settings settings;
    // An older post_effects.json entry, verbatim, in a document without "version".
    const auto issues =
        readSettingsJson(R"({"postEffects": {"autoExposure": )"
                         R"({"enabled": true, "speed": 1.5, "min": 0.1, "max": 10.0, "keyValue": 0.18})"
                         R"(}})",
                         settings);
    ASSERT_TRUE(issues.empty()) << formatSettingsIssues(issues);
    const auto& ae = settings.autoExposure;
    EXPECT_TRUE(ae.enabled);
    EXPECT_EQ(ae.speedUp, 1.5f);
    EXPECT_EQ(ae.speedDown, 1.5f);
    EXPECT_FLOAT_EQ(ae.minEV, std::log2(0.1f));
    EXPECT_FLOAT_EQ(ae.maxEV, std::log2(10.0f));
    EXPECT_EQ(ae.keyValue, 0.18f);
    // A file holding both the old key and the new one keeps the new one.
    Settings both;
    EXPECT_TRUE(readAutoExposure(R"({"min": 0.5, "minEV": -1.5})", both).empty());
    EXPECT_EQ(both.autoExposure.minEV, -1.5f);
    // The old multipliers are checked too.
    expectIssue(R"({"min": 0})", SettingsIssueCode::OutOfRange, "postEffects.autoExposure.min");
    expectIssue(R"({"min": 4, "max": 2})", SettingsIssueCode::Constraint, "postEffects.autoExposure.minEV");
}

TEST(AutoExposureSettings, CommandLineOverrides) {
    Settings settings;
    applySettingsOverride(settings, "autoExposure.metering=histogram");
    applySettingsOverride(settings, "autoExposure.spot.taps=5");
    applySettingsOverride(settings, "autoExposure.compensationCurve=[[-2,0.5],[2,-0.5]]");
    EXPECT_EQ(settings.autoExposure.metering, MeteringMode::Histogram);
    EXPECT_EQ(settings.autoExposure.spot.taps, 5);
    EXPECT_EQ(settings.autoExposure.compensationCurve.size(), 2u);
    try {
        applySettingsOverride(settings, "autoExposure.spot.taps=6");
        FAIL() << "taps = 6 must be refused";
    } catch (const SettingsError& e) {
        ASSERT_EQ(e.issues().size(), 1u);
        EXPECT_EQ(e.issues()[0].code, SettingsIssueCode::Constraint);
        EXPECT_EQ(e.issues()[0].path, "postEffects.autoExposure.spot.taps");
    }
    EXPECT_EQ(settings.autoExposure.spot.taps, 5);
}

} // namespace
} // namespace photopic
