// Settings: typed structs <-> JSON, errors by JSON path and code, --set overrides, lossless save/load.

#include "core/settings/SettingsJson.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

namespace photopic {
namespace {

bool hasIssue(const std::vector<SettingsIssue>& issues, SettingsIssueCode code, const std::string& path) {
    for (const auto& i : issues) {
        if (i.code == code && i.path == path) {
            return true;
        }
    }
    return false;
}

TEST(Settings, DefaultsRoundTripLosslessly) {
    const Settings defaults;
    const std::string text = settingsToJson(defaults);
    Settings loaded;
    loaded.tonemapping.exposure = 3; // must be overwritten by the file
    EXPECT_TRUE(readSettingsJson(text, loaded).empty());
    EXPECT_EQ(settingsToJson(loaded), text);
    EXPECT_EQ(loaded.tonemapping.exposure, defaults.tonemapping.exposure);
}

TEST(Settings, NonDefaultValuesRoundTripBitExactly) {
    Settings s;
    s.tonemapping.mode = ToneMapper::Agx;
    s.tonemapping.agxLook = AgxLook::Golden;
    s.tonemapping.exposure = 0.1f + 1e-7f; // not representable in short decimal: must survive bit-exactly
    s.tonemapping.whitePoint = 11.2f;
    s.output.dither = false;
    Settings back;
    ASSERT_TRUE(readSettingsJson(settingsToJson(s), back).empty());
    EXPECT_EQ(back.tonemapping.mode, ToneMapper::Agx);
    EXPECT_EQ(back.tonemapping.agxLook, AgxLook::Golden);
    EXPECT_EQ(back.tonemapping.exposure, s.tonemapping.exposure);
    EXPECT_EQ(back.tonemapping.whitePoint, 11.2f);
    EXPECT_FALSE(back.output.dither);
    EXPECT_EQ(settingsToJson(back), settingsToJson(s));
}

TEST(Settings, DocumentHasVersionAndPostEffects) {
    const auto j = nlohmann::json::parse(settingsToJson(Settings{}));
    EXPECT_EQ(j.at("version"), 1);
    EXPECT_TRUE(j.at("postEffects").at("tonemapping").contains("mode"));
    EXPECT_TRUE(j.at("postEffects").at("output").contains("dither"));
}

TEST(Settings, PartialDocumentKeepsOtherDefaults) {
    Settings s;
    ASSERT_TRUE(
        readSettingsJson(R"({"version": 1, "postEffects": {"tonemapping": {"mode": "hable"}}})", s).empty());
    EXPECT_EQ(s.tonemapping.mode, ToneMapper::Hable);
    EXPECT_EQ(s.tonemapping.exposure, 0.0f);
    EXPECT_TRUE(s.output.dither);
}

TEST(Settings, LegacyDocumentWithoutVersionLoads) {
    Settings s;
    const auto issues =
        readSettingsJson(R"({"postEffects": {"tonemapping": {"mode": "aces", "exposure": 1.0}}})", s);
    EXPECT_TRUE(issues.empty()) << formatSettingsIssues(issues);
    EXPECT_EQ(s.tonemapping.mode, ToneMapper::Aces);
}

TEST(Settings, UnknownKeyNamedByPath) {
    Settings s;
    const auto issues =
        readSettingsJson(R"({"version": 1, "postEffects": {"output": {"dithering": true}}})", s);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].code, SettingsIssueCode::UnknownKey);
    EXPECT_EQ(issues[0].path, "postEffects.output.dithering");
    EXPECT_NE(issues[0].message.find("dither"), std::string::npos); // lists the known keys
    // The formatted line says "unknown key" once, after the path, then the keys that would have been read.
    const std::string line = formatSettingsIssues(issues);
    EXPECT_EQ(line.find("unknown key"), line.rfind("unknown key")) << line;
    EXPECT_NE(line.find("postEffects.output.dithering: unknown key (known keys: "), std::string::npos)
        << line;
}

TEST(Settings, GroupAtTheTopIsPointedInsidePostEffects) {
    Settings s;
    const auto issues = readSettingsJson(R"({"bloom": {"intensity": 2}, "bogus": 1})", s);
    ASSERT_EQ(issues.size(), 2u) << formatSettingsIssues(issues);
    EXPECT_EQ(issues[0].path, "bloom");
    EXPECT_NE(issues[0].message.find(R"({"postEffects": {"bloom": ...}})"), std::string::npos)
        << issues[0].message;
    EXPECT_EQ(issues[1].path, "bogus");
    EXPECT_EQ(issues[1].message.find("postEffects:"), std::string::npos) << issues[1].message; // no hint
}

TEST(Settings, MissingFileIsNamedAsMissing) {
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / "photopic_no_such_settings.json";
    std::filesystem::remove(file);
    try {
        (void)loadSettingsFile(file);
        FAIL() << "no SettingsError";
    } catch (const SettingsError& e) {
        ASSERT_EQ(e.issues().size(), 1u);
        EXPECT_EQ(e.issues()[0].code, SettingsIssueCode::MissingFile);
        const std::string what = e.what();
        EXPECT_NE(what.find(file.string()), std::string::npos) << what;
        EXPECT_NE(what.find("does not exist"), std::string::npos) << what;
        EXPECT_EQ(what.find("JSON"), std::string::npos) << what; // not reported as a parse error
    }
}

TEST(Settings, FolderIsNotReadAsSettings) {
    try {
        (void)loadSettingsFile(std::filesystem::temp_directory_path());
        FAIL() << "no SettingsError";
    } catch (const SettingsError& e) {
        ASSERT_EQ(e.issues().size(), 1u);
        EXPECT_EQ(e.issues()[0].code, SettingsIssueCode::UnreadableFile);
    }
}

TEST(Settings, WrongTypeNamedByPath) {
    Settings s;
    const auto issues =
        readSettingsJson(R"({"version": 1, "postEffects": {"tonemapping": {"exposure": "bright"}}})", s);
    EXPECT_TRUE(hasIssue(issues, SettingsIssueCode::WrongType, "postEffects.tonemapping.exposure"));
}

TEST(Settings, OutOfRangeNamesRange) {
    Settings s;
    const auto issues = readSettingsJson(R"({"postEffects": {"tonemapping": {"exposure": 25}}})", s);
    ASSERT_TRUE(hasIssue(issues, SettingsIssueCode::OutOfRange, "postEffects.tonemapping.exposure"));
    EXPECT_NE(formatSettingsIssues(issues).find("[-20, 20]"), std::string::npos);
}

TEST(Settings, OutputBitDepthIsEightOrSixteen) {
    Settings s;
    EXPECT_EQ(s.output.bitDepth, 8);
    EXPECT_TRUE(readSettingsJson(R"({"postEffects": {"output": {"bitDepth": 16}}})", s).empty());
    EXPECT_EQ(s.output.bitDepth, 16);
    EXPECT_TRUE(hasIssue(readSettingsJson(R"({"postEffects": {"output": {"bitDepth": 12}}})", s),
                         SettingsIssueCode::Constraint, "postEffects.output.bitDepth"));
    EXPECT_TRUE(hasIssue(readSettingsJson(R"({"postEffects": {"output": {"bitDepth": 32}}})", s),
                         SettingsIssueCode::OutOfRange, "postEffects.output.bitDepth"));
}

TEST(Settings, BadEnumListsAllowedNames) {
    Settings s;
    const auto issues = readSettingsJson(R"({"postEffects": {"tonemapping": {"mode": "filmic"}}})", s);
    ASSERT_TRUE(hasIssue(issues, SettingsIssueCode::BadEnum, "postEffects.tonemapping.mode"));
    const auto text = formatSettingsIssues(issues);
    for (auto name : toneMapperNames()) {
        EXPECT_NE(text.find(std::string(name)), std::string::npos) << name;
    }
}

TEST(Settings, EveryIssueIsReportedNotJustTheFirst) {
    Settings s;
    const auto issues = readSettingsJson(
        R"({"postEffects": {"tonemapping": {"mode": 3, "exposure": 99}, "output": {"dither": "yes"}, "blum": {}}})",
        s);
    EXPECT_TRUE(hasIssue(issues, SettingsIssueCode::WrongType, "postEffects.tonemapping.mode"));
    EXPECT_TRUE(hasIssue(issues, SettingsIssueCode::OutOfRange, "postEffects.tonemapping.exposure"));
    EXPECT_TRUE(hasIssue(issues, SettingsIssueCode::WrongType, "postEffects.output.dither"));
    EXPECT_TRUE(hasIssue(issues, SettingsIssueCode::UnknownKey, "postEffects.blum"));
}

TEST(Settings, DocumentWithIssuesChangesNothing) {
    Settings s;
    s.tonemapping.mode = ToneMapper::Lottes;
    const auto issues =
        readSettingsJson(R"({"postEffects": {"tonemapping": {"mode": "agx", "exposure": 99}}})", s);
    EXPECT_FALSE(issues.empty());
    EXPECT_EQ(s.tonemapping.mode, ToneMapper::Lottes);
}

TEST(Settings, BadVersionAndParseErrors) {
    Settings s;
    auto issues = readSettingsJson(R"({"version": 2, "postEffects": {}})", s);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].code, SettingsIssueCode::BadVersion);
    issues = readSettingsJson(R"({"version": 1, "postEffects": {)", s);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].code, SettingsIssueCode::ParseError);
    issues = readSettingsJson("[1, 2]", s);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].code, SettingsIssueCode::WrongType);
    issues = readSettingsJson(R"({"postEffect": {}})", s);
    EXPECT_TRUE(hasIssue(issues, SettingsIssueCode::UnknownKey, "postEffect"));
}

TEST(Settings, OverridesParseJsonValuesAndBareWords) {
    Settings s;
    applySettingsOverride(s, "tonemapping.mode=agx");
    applySettingsOverride(s, "tonemapping.exposure=-1.5");
    applySettingsOverride(s, "output.dither=false");
    applySettingsOverride(s, "tonemapping.agxLook=\"punchy\"");
    EXPECT_EQ(s.tonemapping.mode, ToneMapper::Agx);
    EXPECT_EQ(s.tonemapping.exposure, -1.5f);
    EXPECT_FALSE(s.output.dither);
    EXPECT_EQ(s.tonemapping.agxLook, AgxLook::Punchy);
}

TEST(Settings, BadOverridesThrowWithPathAndCode) {
    Settings s;
    const auto codeOf = [&](const char* assignment) {
        try {
            applySettingsOverride(s, assignment);
        } catch (const SettingsError& e) {
            EXPECT_FALSE(e.issues().empty());
            return e.issues().front();
        }
        ADD_FAILURE() << assignment << " did not throw";
        return SettingsIssue{};
    };
    EXPECT_EQ(codeOf("tonemapping.mode").code, SettingsIssueCode::BadOverride);
    EXPECT_EQ(codeOf("=3").code, SettingsIssueCode::BadOverride);
    const auto unknown = codeOf("tonemapping.gamma=2.2");
    EXPECT_EQ(unknown.code, SettingsIssueCode::UnknownKey);
    EXPECT_EQ(unknown.path, "postEffects.tonemapping.gamma");
    EXPECT_EQ(codeOf("tonemapping.exposure=1e9").code, SettingsIssueCode::OutOfRange);
    EXPECT_EQ(codeOf("tonemapping=3").code, SettingsIssueCode::WrongType);
    EXPECT_EQ(s.tonemapping.mode, ToneMapper::AcesFitted); // nothing applied
}

TEST(Settings, IssueCodesHaveNames) {
    EXPECT_EQ(settingsIssueCodeName(SettingsIssueCode::UnknownKey), "UnknownKey");
    EXPECT_EQ(settingsIssueCodeName(SettingsIssueCode::OutOfRange), "OutOfRange");
}

} // namespace
} // namespace photopic

namespace photopic {

TEST(SettingsJson, NumbersAreWrittenAsTheShortestTextThatReadsBack) {
    Settings s;
    s.bloom.intensity = 0.02f;
    s.autoExposure.tauDarken = 0.3f;
    const std::string text = settingsToJson(s);
    EXPECT_NE(text.find("\"intensity\": 0.02,"), std::string::npos) << text;
    EXPECT_EQ(text.find("0.019999999552965164"), std::string::npos);
    EXPECT_NE(text.find("\"tauDarken\": 0.3"), std::string::npos);
    Settings back;
    EXPECT_TRUE(readSettingsJson(text, back).empty());
    EXPECT_EQ(back.bloom.intensity, 0.02f); // the same float
    EXPECT_EQ(back.autoExposure.tauDarken, 0.3f);
}

} // namespace photopic
