// The settings reference: one row per reflected field, with the key, type, default and range the JSON
// reader and writer use, and a meaning for every field.

#include "core/settings/SettingsDescriber.h"
#include "core/settings/SettingsJson.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>
#include <set>

namespace photopic {
namespace {

/// Every leaf of a JSON object as "a.b" -> value (arrays are leaves).
void flatten(const nlohmann::json& j, const std::string& prefix, std::map<std::string, nlohmann::json>& out) {
    for (const auto& [key, value] : j.items()) {
        const std::string path = prefix.empty() ? key : prefix + "." + key;
        if (value.is_object()) {
            flatten(value, path, out);
        } else {
            out[path] = value;
        }
    }
}

TEST(SettingsDescriber, OneRowPerWrittenKeyWithTheWrittenDefault) {
    const std::vector<SettingDoc> docs = describeSettings(Settings{});
    std::map<std::string, nlohmann::json> written;
    flatten(settingsToJsonValue(Settings{})["postEffects"], "", written);
    std::set<std::string> described;
    for (const SettingDoc& d : docs) {
        if (d.alias) {
            EXPECT_TRUE(d.defaultJson.empty()) << d.key;
            continue;
        }
        EXPECT_TRUE(described.insert(d.key).second) << "described twice: " << d.key;
        ASSERT_TRUE(written.contains(d.key)) << d.key << " is described but not written";
        EXPECT_EQ(nlohmann::json::parse(d.defaultJson), written.at(d.key)) << d.key;
    }
    EXPECT_EQ(described.size(), written.size());
}

TEST(SettingsDescriber, EveryFieldHasAMeaning) {
    for (const SettingDoc& d : describeSettings(Settings{})) {
        EXPECT_GE(d.meaning.size(), 8u) << d.key << " has no description in its visit()";
    }
}

TEST(SettingsDescriber, TypesRangesAndEnumNamesComeFromTheReflection) {
    std::map<std::string, SettingDoc> byKey;
    for (const SettingDoc& d : describeSettings(Settings{})) {
        byKey[d.key] = d;
    }
    EXPECT_EQ(byKey.at("bloom.intensity").type, "number");
    EXPECT_EQ(byKey.at("bloom.intensity").allowed, "[0, 10]");
    EXPECT_EQ(byKey.at("bloom.intensity").defaultJson, "0.04");
    EXPECT_EQ(byKey.at("bloom.enabled").type, "bool");
    EXPECT_EQ(byKey.at("bloom.mipCount").type, "integer");
    EXPECT_EQ(byKey.at("tonemapping.mode").type, "enum");
    EXPECT_NE(byKey.at("tonemapping.mode").allowed.find("agx"), std::string::npos);
    EXPECT_EQ(byKey.at("quality").defaultJson, "\"high\"");
    EXPECT_EQ(byKey.at("autoExposure.spot.u").allowed, "[0, 1]");
    EXPECT_TRUE(byKey.at("autoExposure.speed").alias);
    // A value the reader refuses lies outside the listed range.
    Settings s;
    EXPECT_FALSE(readSettingsJson(R"({"postEffects": {"bloom": {"intensity": 10.5}}})", s).empty());
}

TEST(SettingsDescriber, DefaultsFollowTheGivenValues) {
    Settings s;
    s.bloom.intensity = 0.25f;
    for (const SettingDoc& d : describeSettings(s, "root")) {
        if (d.key == "root.bloom.intensity") {
            EXPECT_EQ(d.defaultJson, "0.25");
            return;
        }
    }
    FAIL() << "root.bloom.intensity not described";
}

TEST(SettingsDescriber, MarkdownEscapesCellsAndListsDifferences) {
    const std::vector<SettingDoc> base = {{"a.b", "number", "1.0", "[0, 2]", "x | y", false},
                                          {"a.c", "bool", "true", "true, false", "switch", false}};
    std::vector<SettingDoc> changed = base;
    changed[1].defaultJson = "false";
    const std::string table = settingsMarkdownTable(base);
    EXPECT_NE(table.find("| `a.b` | number | `1.0` | [0, 2] | x \\| y |"), std::string::npos) << table;
    EXPECT_EQ(settingsDifferenceList(base, changed), "- `a.c`: `true` -> `false`\n");
}

} // namespace
} // namespace photopic
