// photopic-view's key map: each toggle key changes exactly its setting and back, and --press parses.

#include "ViewerKeys.h"

#include "core/settings/SettingsJson.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <set>
#include <stdexcept>

namespace photopic::viewer {
namespace {

/// The keys (JSON paths) whose values differ between two settings.
std::set<std::string> changedKeys(const Settings& a, const Settings& b) {
    std::set<std::string> out;
    const nlohmann::json ja = settingsToJsonValue(a)["postEffects"];
    const nlohmann::json jb = settingsToJsonValue(b)["postEffects"];
    for (const auto& [group, values] : ja.items()) {
        if (!values.is_object()) {
            if (values != jb[group]) {
                out.insert(group);
            }
            continue;
        }
        for (const auto& [key, value] : values.items()) {
            if (value != jb[group][key]) {
                out.insert(group + "." + key);
            }
        }
    }
    return out;
}

struct Expected {
    const char* key;
    std::set<std::string> changes; ///< from the defaults
};

TEST(ViewerKeys, EachToggleChangesItsSettingAndASecondPressRestoresIt) {
    const Expected expected[] = {
        {"1", {"ssao.enabled"}},
        {"2", {"contactShadows.enabled"}},
        {"3", {"volumetricLight.enabled"}},
        {"4", {"dof.enabled"}},
        {"5", {"motionBlur.enabled"}},
        {"6", {"colorGrading.enabled"}},
        {"7", {"lensFlare.enabled"}},
        {"8", {"aa.mode"}},
        {"9", {"aa.mode"}},
        {"B", {"bloom.enabled"}},
        {"R", {"ssr.enabled"}},
        {"O", {"outline.enabled"}},
        {"V", {"vignette.enabled"}},
        {"T", {"aa.mode"}},
        {"X", {"autoExposure.enabled"}},
        {"0", {"tonemapping.mode"}},
    };
    for (const Expected& e : expected) {
        const Settings defaults;
        Settings s;
        const auto message = applyToggleKey(e.key, s);
        ASSERT_TRUE(message.has_value()) << e.key;
        EXPECT_EQ(changedKeys(defaults, s), e.changes) << e.key;
        EXPECT_NE(message->find(std::string("(") + e.key + ")"), std::string::npos) << *message;
        EXPECT_TRUE(validateSettings(s).empty()) << e.key;
        if (std::string(e.key) != "0") {
            applyToggleKey(e.key, s);
            EXPECT_TRUE(changedKeys(defaults, s).empty()) << e.key << " pressed twice";
        }
    }
}

TEST(ViewerKeys, AntiAliasingKeysSelectTheirModeAndClearTheOlderSwitches) {
    Settings s;
    s.fxaa.enabled = true; // the older switch selects FXAA
    applyToggleKey("t", s);
    EXPECT_EQ(s.antiAliasing(), AntiAliasing::Taa);
    EXPECT_FALSE(s.fxaa.enabled);
    applyToggleKey("9", s);
    EXPECT_EQ(s.antiAliasing(), AntiAliasing::Smaa);
    applyToggleKey("9", s);
    EXPECT_EQ(s.antiAliasing(), AntiAliasing::None);
}

TEST(ViewerKeys, ZeroCyclesThroughEveryToneCurve) {
    Settings s;
    const ToneMapper first = s.tonemapping.mode;
    std::set<int> seen;
    for (std::size_t i = 0; i < toneMapperNames().size(); ++i) {
        seen.insert(int(s.tonemapping.mode));
        applyToggleKey("0", s);
    }
    EXPECT_EQ(seen.size(), toneMapperNames().size());
    EXPECT_EQ(s.tonemapping.mode, first);
}

TEST(ViewerKeys, UnboundKeysChangeNothing) {
    for (const char* key : {"F12", "Q", "", "BB", "F1"}) {
        Settings s;
        EXPECT_FALSE(applyToggleKey(key, s).has_value()) << key;
        EXPECT_TRUE(changedKeys(Settings{}, s).empty()) << key;
    }
}

TEST(ViewerKeys, TheHelpListsEveryToggleKey) {
    std::set<std::string> listed;
    for (const KeyBinding& k : viewerKeys()) {
        listed.emplace(k.key);
    }
    for (const char* key :
         {"1", "2", "3", "4", "5", "6", "7", "8", "9", "0", "B", "R", "O", "V", "T", "X", "F12"}) {
        EXPECT_TRUE(listed.contains(key)) << key;
    }
}

TEST(ViewerKeys, ScriptedEventsParse) {
    EXPECT_EQ(parseScriptedEvent("b").key, "B");
    EXPECT_EQ(parseScriptedEvent("f12").key, "F12");
    const ScriptedEvent drag = parseScriptedEvent("drag:40:-12.5");
    EXPECT_EQ(drag.kind, ScriptedEvent::Kind::Drag);
    EXPECT_EQ(drag.x, 40.0);
    EXPECT_EQ(drag.y, -12.5);
    const ScriptedEvent wheel = parseScriptedEvent("wheel:-2");
    EXPECT_EQ(wheel.kind, ScriptedEvent::Kind::Wheel);
    EXPECT_EQ(wheel.x, -2.0);
    for (const char* bad : {"Q", "drag:1", "drag:a:b", "wheel:", "wheel:nan", "drag:1e9:0", ""}) {
        EXPECT_THROW(parseScriptedEvent(bad), std::invalid_argument) << bad;
    }
}

} // namespace
} // namespace photopic::viewer
