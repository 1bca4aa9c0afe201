#pragma once
// Scene settings use the same reflection as the post settings (core/settings/Reflect.h): a struct with
// visit(V&).

#include "core/JsonText.h"
#include "core/settings/JsonVisitors.h"
#include "core/settings/SettingsDescriber.h"

#include <string>
#include <string_view>
#include <vector>

namespace photopic {

/// Applies "key=value" to `settings`, whose JSON path root is `sceneName`; returns the issues (nothing
/// changes when there are any).
template <class S>
std::vector<SettingsIssue> applySceneOverride(S& settings, std::string_view sceneName,
                                              std::string_view assignment) {
    nlohmann::json patch;
    try {
        if (!settings_json::parseAssignment(assignment, patch)) {
            return {{SettingsIssueCode::BadOverride, std::string(sceneName) + "." + shownText(assignment),
                     "expected " + std::string(sceneName) + ".key=value"}};
        }
    } catch (const JsonTextError& e) {
        return {
            {SettingsIssueCode::ParseError, std::string(sceneName) + "." + shownText(assignment), e.what()}};
    }
    S candidate = settings;
    auto issues = settings_json::readObject(patch, std::string(sceneName), candidate);
    if (issues.empty()) {
        settings = std::move(candidate);
    }
    return issues;
}

/// The reference rows of a scene's settings struct (keys "NAME.key", defaults of a default-made struct): what
/// a SceneInfo's describeSettings points at, so the reference needs no scene instance (no GL context).
template <class S>
std::vector<SettingDoc> describeSceneSettings(std::string_view sceneName) {
    return describeSettings(S{}, sceneName);
}

template <class S>
std::string sceneSettingsJson(const S& settings) {
    return settings_json::writeObject(settings).dump(2);
}

} // namespace photopic
