// Text people supply, parsed and shown: parseJsonText's nesting limit, duplicate keys and number range;
// shownText and shownJson bound and escape whatever they are given; the settings readers built on them
// refuse values nested or sized to exhaust a printer with a short message, never a crash.

#include "core/JsonText.h"
#include "core/ShownText.h"
#include "core/settings/SettingsJson.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace photopic {

namespace {

using nlohmann::json;

std::string nested(std::size_t depth) {
    return std::string(depth, '[') + std::string(depth, ']');
}

std::string parseError(std::string_view text, const JsonTextLimits& limits = {}) {
    try {
        (void)parseJsonText(text, limits);
    } catch (const JsonTextError& e) {
        return e.what();
    }
    return "";
}

TEST(JsonText, NestingUpToTheLimitParsesAndOneMoreLevelIsRefused) {
    EXPECT_EQ(parseJsonText(nested(64)).dump(), nested(64));
    // The path is a JSON pointer, cut like any shown text.
    const std::string oneTooMany = parseError(nested(65));
    EXPECT_TRUE(oneTooMany.starts_with("nested deeper than 64 levels at /0/0/0/0/")) << oneTooMany;
    EXPECT_TRUE(oneTooMany.ends_with("/0/...")) << oneTooMany;
    EXPECT_LT(oneTooMany.size(), 200u);
    EXPECT_NE(parseError(nested(70000)).find("nested deeper than 64 levels"), std::string::npos);
    EXPECT_LT(parseError(nested(70000)).size(), 200u);
    EXPECT_EQ(parseError(R"({"a": [1, {"b": [[2]]}]})", {.maxDepth = 3}),
              "nested deeper than 3 levels at /a/1/b");
}

TEST(JsonText, ADuplicateKeyIsNamedWithItsPath) {
    EXPECT_EQ(parseError(R"({"postEffects": {"bloom": {"intensity": 1, "intensity": 2}}})"),
              R"(duplicate key "intensity" at /postEffects/bloom)");
    EXPECT_EQ(parseError(R"({"a": 1, "a": 1})"), R"(duplicate key "a" at /)");
    // The same key in sibling objects is no duplicate; glTF's reader may allow duplicates.
    EXPECT_NO_THROW((void)parseJsonText(R"([{"a": 1}, {"a": 2}])"));
    EXPECT_NO_THROW((void)parseJsonText(R"({"a": 1, "a": 2})", {.rejectDuplicateKeys = false}));
}

TEST(JsonText, ANumberBeyondDoubleRangeSaysSo) {
    try {
        (void)parseJsonText("1e400");
        FAIL() << "1e400 parsed";
    } catch (const JsonTextError& e) {
        EXPECT_EQ(e.kind, JsonTextError::Kind::NumberOutOfRange);
        EXPECT_NE(std::string(e.what()).find("beyond the range of a double"), std::string::npos) << e.what();
    }
    EXPECT_EQ(parseError("[1,"), "parse error at line 1, column 4: syntax error while parsing value - "
                                 "unexpected end of input; expected '[', '{', or a literal");
}

TEST(ShownText, ControlBytesAndBadUtf8AreEscapedAndLongTextIsCut) {
    EXPECT_EQ(shownText("agx"), "agx");
    EXPECT_EQ(shownText("\x1b[31mred"), "\\x1b[31mred");
    EXPECT_EQ(shownText("a\nb\x7f"), "a\\x0ab\\x7f");
    EXPECT_EQ(shownText("caf\xc3\xa9 \xbe"), "caf\xc3\xa9 \\xbe");
    EXPECT_EQ(shownText("C:\\x"), "C:\\\\x");
    const std::string cut = shownText(std::string(10'000'000, 'x'));
    EXPECT_EQ(cut, std::string(kShownMaxBytes, 'x') + "... (10000000 bytes)");
}

TEST(ShownJson, DeepAndHugeValuesAreShownBounded) {
    EXPECT_EQ(shownJson(json::parse(R"({"a":[1,2.5,"x"]})")), R"({"a":[1,2.5,"x"]})");
    // Built without the parser's limit: 100,000 levels are shown as a few, with no recursion through them.
    json deep = json::array();
    for (int i = 0; i < 100000; ++i) {
        deep = json::array({std::move(deep)});
    }
    EXPECT_EQ(shownJson(deep), "[[[[[[[[[...]]]]]]]]]");
    json wide = json::array();
    for (int i = 0; i < 1'000'000; ++i) {
        wide.push_back(i);
    }
    const std::string shown = shownJson(wide);
    EXPECT_LE(shown.size(), kShownMaxBytes + 3);
    EXPECT_TRUE(shown.starts_with("[0,1,2,3,")) << shown;
    EXPECT_TRUE(shown.ends_with("...")) << shown;
    EXPECT_EQ(shownJson(json("\x1b")), R"("\u001b")");
}

TEST(SettingsText, AValueNestedOrSizedToExhaustThePrinterIsAShortIssue) {
    Settings settings;
    const auto deep =
        readSettingsJson(R"({"version": 1, "postEffects": {"bloom": )" + nested(70000) + "}}", settings);
    ASSERT_EQ(deep.size(), 1u);
    EXPECT_EQ(deep[0].code, SettingsIssueCode::ParseError);
    EXPECT_NE(deep[0].message.find("nested deeper than 64 levels"), std::string::npos);

    std::string wide = R"({"version": 1, "postEffects": {"bloom": [0)";
    for (int i = 0; i < 1'000'000; ++i) {
        wide += ",0";
    }
    wide += "]}}";
    const auto huge = readSettingsJson(wide, settings);
    ASSERT_EQ(huge.size(), 1u);
    EXPECT_EQ(huge[0].code, SettingsIssueCode::WrongType);
    EXPECT_LT(huge[0].message.size(), 200u) << huge[0].message.substr(0, 300);

    const auto twice = readSettingsJson(R"({"version": 1, "version": 1})", settings);
    ASSERT_EQ(twice.size(), 1u);
    EXPECT_EQ(twice[0].message, R"(duplicate key "version" at /)");
}

std::string overrideError(const std::string& assignment) {
    Settings settings;
    try {
        applySettingsOverride(settings, assignment);
    } catch (const SettingsError& e) {
        return e.what();
    }
    return "";
}

TEST(SettingsText, OverridesKeepTheirLimitsAndSayWhatIsWrong) {
    EXPECT_NE(overrideError("bloom.intensity=1e400").find("beyond the range of a double"), std::string::npos);
    EXPECT_EQ(overrideError("bloom.intensity=1e400").find("got string"), std::string::npos);
    const std::string deep = overrideError("bloom=" + nested(70000));
    EXPECT_NE(deep.find("nested deeper than 64 levels"), std::string::npos);
    EXPECT_LT(deep.size(), 600u);
    EXPECT_NE(overrideError("bloom=[1,").find("syntax error"), std::string::npos);
    std::string parts = "a";
    for (int i = 0; i < 100000; ++i) {
        parts += ".a";
    }
    const std::string tooManyParts = overrideError(parts + "=1");
    EXPECT_NE(tooManyParts.find("more than 16 parts"), std::string::npos);
    EXPECT_LT(tooManyParts.size(), 600u);
    // Bare words stay strings: the tone curve's name needs no quotes.
    Settings settings;
    applySettingsOverride(settings, "tonemapping.mode=agx");
    EXPECT_EQ(settings.tonemapping.mode, ToneMapper::Agx);
}

TEST(SettingsText, AThousandIssuesListTwentyAndCountTheRest) {
    std::string doc = R"({"version": 1, "postEffects": {)";
    for (int i = 0; i < 1000; ++i) {
        doc += (i ? ",\"k" : "\"k") + std::to_string(i) + "\": 1";
    }
    doc += "}}";
    Settings settings;
    const auto issues = readSettingsJson(doc, settings);
    ASSERT_EQ(issues.size(), 1000u);
    const std::string text = formatSettingsIssues(issues);
    EXPECT_NE(text.find("... and 980 more"), std::string::npos);
}

} // namespace

} // namespace photopic
