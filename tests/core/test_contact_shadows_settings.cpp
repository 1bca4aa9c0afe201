// contactShadows.* settings: defaults, ranges by JSON path, the object-id mask list, and save-load.

#include "core/settings/SettingsJson.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace photopic {
namespace {

std::vector<SettingsIssue> readContact(const std::string& body, Settings& s) {
    return readSettingsJson(R"({"postEffects": {"contactShadows": )" + body + "}}", s);
}

TEST(ContactShadowsSettings, DefaultsAreOffWithTheDocumentedValues) {
    const nlohmann::json cs = settingsToJsonValue(Settings{})["postEffects"]["contactShadows"];
    EXPECT_FALSE(cs["enabled"].get<bool>());
    EXPECT_DOUBLE_EQ(cs["distance"].get<double>(), 0.18);
    EXPECT_DOUBLE_EQ(cs["thickness"].get<double>(), 0.003);
    EXPECT_DOUBLE_EQ(cs["strength"].get<double>(), 1.1);
    EXPECT_EQ(cs["quality"].get<std::string>(), "high");
    EXPECT_EQ(cs["steps"].get<int>(), 0); // the preset's: 22 at high
    EXPECT_EQ(Settings{}.contactShadows.stepCount(), 22);
    EXPECT_TRUE(cs["mask"].is_array());
    EXPECT_TRUE(cs["mask"].empty());
}

TEST(ContactShadowsSettings, RangesAreCheckedByJsonPath) {
    Settings s;
    const struct {
        const char* body;
        const char* path;
        SettingsIssueCode code;
    } cases[] = {
        {R"({"distance": 0})", "postEffects.contactShadows.distance", SettingsIssueCode::OutOfRange},
        {R"({"thickness": -0.1})", "postEffects.contactShadows.thickness", SettingsIssueCode::OutOfRange},
        {R"({"strength": 5})", "postEffects.contactShadows.strength", SettingsIssueCode::OutOfRange},
        {R"({"steps": -1})", "postEffects.contactShadows.steps", SettingsIssueCode::OutOfRange},
        {R"({"steps": 2.5})", "postEffects.contactShadows.steps", SettingsIssueCode::WrongType},
        {R"({"mask": 3})", "postEffects.contactShadows.mask", SettingsIssueCode::WrongType},
        {R"({"mask": [1, "two"]})", "postEffects.contactShadows.mask[1]", SettingsIssueCode::WrongType},
        {R"({"mask": [1, 0]})", "postEffects.contactShadows.mask[1]", SettingsIssueCode::OutOfRange},
        {R"({"mask": [-4]})", "postEffects.contactShadows.mask[0]", SettingsIssueCode::OutOfRange},
        {R"({"mask": [4294967296]})", "postEffects.contactShadows.mask[0]", SettingsIssueCode::OutOfRange},
        {R"({"mask": [1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17]})", "postEffects.contactShadows.mask",
         SettingsIssueCode::Constraint},
        {R"({"csDist": 0.2})", "postEffects.contactShadows.csDist", SettingsIssueCode::UnknownKey},
    };
    for (const auto& c : cases) {
        const Settings before = s;
        const std::vector<SettingsIssue> issues = readContact(c.body, s);
        ASSERT_EQ(issues.size(), 1u) << c.body;
        EXPECT_EQ(issues[0].code, c.code) << c.body;
        EXPECT_EQ(issues[0].path, c.path) << c.body;
        EXPECT_EQ(s.contactShadows.mask, before.contactShadows.mask) << c.body; // untouched on error
    }
}

TEST(ContactShadowsSettings, MaskReadsWritesAndOverrides) {
    Settings s;
    ASSERT_TRUE(readContact(R"({"enabled": true, "mask": [4, 4294967295, 1], "steps": 64})", s).empty());
    EXPECT_TRUE(s.contactShadows.enabled);
    EXPECT_EQ(s.contactShadows.mask, (IdList{4, 4294967295u, 1}));
    EXPECT_EQ(s.contactShadows.steps, 64);

    Settings loaded;
    ASSERT_TRUE(readSettingsJson(settingsToJson(s), loaded).empty());
    EXPECT_EQ(loaded.contactShadows.mask, s.contactShadows.mask);
    EXPECT_EQ(settingsToJson(loaded), settingsToJson(s)); // save then load is lossless

    applySettingsOverride(s, "contactShadows.mask=[7,8]");
    EXPECT_EQ(s.contactShadows.mask, (IdList{7, 8}));
    applySettingsOverride(s, "contactShadows.mask=[]");
    EXPECT_TRUE(s.contactShadows.mask.empty());
    EXPECT_THROW(applySettingsOverride(s, "contactShadows.mask=[0]"), SettingsError);
    EXPECT_TRUE(validateSettings(s).empty());
    s.contactShadows.strength = 9.0f; // set through the API: validation names it
    const std::vector<SettingsIssue> issues = validateSettings(s);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].path, "postEffects.contactShadows.strength");
}

TEST(ContactShadowsSettings, DebugViewsAreNamed) {
    Settings s;
    ASSERT_TRUE(
        readSettingsJson(R"({"postEffects": {"debug": {"view": "contact-shadows-steps"}}})", s).empty());
    EXPECT_EQ(s.debug.view, DebugView::ContactShadowSteps);
    applySettingsOverride(s, "debug.view=contact-shadows");
    EXPECT_EQ(s.debug.view, DebugView::ContactShadows);
}

} // namespace
} // namespace photopic
