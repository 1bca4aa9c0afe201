#include "core/settings/SettingsJson.h"

#include "core/settings/JsonVisitors.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

namespace photopic {

using nlohmann::json;

std::string_view settingsIssueCodeName(SettingsIssueCode code) {
    switch (code) {
#define PHOTOPIC_X(name, text)                                                                               \
    case SettingsIssueCode::name:                                                                            \
        return #name;
        PHOTOPIC_SETTINGS_ISSUES(PHOTOPIC_X)
#undef PHOTOPIC_X
    }
    return "Unknown";
}

namespace {

using namespace settings_json;

std::string_view issueText(SettingsIssueCode code) {
    switch (code) {
#define PHOTOPIC_X(name, text)                                                                               \
    case SettingsIssueCode::name:                                                                            \
        return text;
        PHOTOPIC_SETTINGS_ISSUES(PHOTOPIC_X)
#undef PHOTOPIC_X
    }
    return "";
}

std::vector<SettingsIssue> readDocument(const json& doc, Settings& settings) {
    std::vector<SettingsIssue> issues;
    if (!doc.is_object()) {
        issues.push_back({SettingsIssueCode::WrongType, "", "the document must be a JSON object"});
        return issues;
    }
    // "version" may be absent: older post_effects.json files carry none and stay valid as version 1.
    if (const auto v = doc.find("version"); v != doc.end()) {
        if (!v->is_number_integer() || v->get<long long>() != kSettingsVersion) {
            issues.push_back({SettingsIssueCode::BadVersion, "version",
                              fmt::format("version {} is not supported (this build reads version {})",
                                          v->dump(), kSettingsVersion)});
            return issues;
        }
    }
    for (const auto& [key, value] : doc.items()) {
        if (key != "version" && key != "postEffects") {
            issues.push_back(
                {SettingsIssueCode::UnknownKey, key, "unknown key (known keys: version, postEffects)"});
        }
    }
    const auto post = doc.find("postEffects");
    if (post == doc.end()) {
        return issues;
    }
    if (!post->is_object()) {
        issues.push_back({SettingsIssueCode::WrongType, "postEffects",
                          fmt::format("expected an object, got {}", post->type_name())});
        return issues;
    }
    auto found = readObject(*post, "postEffects", settings);
    issues.insert(issues.end(), found.begin(), found.end());
    return issues;
}

} // namespace

SettingsError::SettingsError(std::string source, std::vector<SettingsIssue> issues)
    : std::runtime_error(source + ":\n" + formatSettingsIssues(issues))
    , mIssues(std::move(issues)) {}

std::string formatSettingsIssues(const std::vector<SettingsIssue>& issues) {
    std::string out;
    for (const auto& issue : issues) {
        out += fmt::format("  {}: {}: {}\n", issue.path.empty() ? "(document)" : issue.path,
                           issueText(issue.code), issue.message);
    }
    return out;
}

std::vector<SettingsIssue> readSettingsJson(std::string_view text, Settings& settings) {
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::parse_error& e) {
        return {{SettingsIssueCode::ParseError, "", e.what()}};
    }
    // Read into a copy so a document with issues leaves `settings` exactly as it was.
    Settings candidate = settings;
    auto issues = readDocument(doc, candidate);
    if (issues.empty()) {
        settings = std::move(candidate);
    }
    return issues;
}

Settings loadSettingsFile(const std::filesystem::path& file, Settings base) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        throw SettingsError(file.string(), {{SettingsIssueCode::ParseError, "", "cannot open the file"}});
    }
    std::stringstream ss;
    ss << in.rdbuf();
    auto issues = readSettingsJson(ss.str(), base);
    if (!issues.empty()) {
        throw SettingsError(file.string(), std::move(issues));
    }
    return base;
}

json settingsToJsonValue(const Settings& settings) {
    return json{{"version", kSettingsVersion}, {"postEffects", writeObject(settings)}};
}

std::string settingsToJson(const Settings& settings) {
    return settingsToJsonValue(settings).dump(2) + "\n";
}

namespace settings_json {

bool parseAssignment(std::string_view assignment, json& patch) {
    const auto eq = assignment.find('=');
    if (eq == std::string_view::npos || eq == 0) {
        return false;
    }
    const std::string valueText(assignment.substr(eq + 1));
    patch = json::parse(valueText, nullptr, /*allow_exceptions=*/false);
    if (patch.is_discarded()) {
        patch = valueText; // bare words such as agx are strings
    }
    std::vector<std::string> parts;
    std::string_view rest = assignment.substr(0, eq);
    while (!rest.empty()) {
        const auto dot = rest.find('.');
        parts.emplace_back(rest.substr(0, dot));
        rest = dot == std::string_view::npos ? std::string_view{} : rest.substr(dot + 1);
    }
    for (auto it = parts.rbegin(); it != parts.rend(); ++it) {
        patch = json{{*it, patch}};
    }
    return true;
}

} // namespace settings_json

void applySettingsOverride(Settings& settings, std::string_view assignment) {
    const std::string source = fmt::format("--set {}", assignment);
    // Build {"postEffects": {"a": {"b": value}}} and read it like a file, so errors carry the same paths.
    json patch;
    if (!parseAssignment(assignment, patch)) {
        throw SettingsError(source, {{SettingsIssueCode::BadOverride, std::string(assignment),
                                      "expected path=value, e.g. tonemapping.mode=agx"}});
    }
    Settings candidate = settings;
    auto issues = readDocument(json{{"postEffects", patch}}, candidate);
    if (!issues.empty()) {
        throw SettingsError(source, std::move(issues));
    }
    settings = std::move(candidate);
}

std::vector<SettingsIssue> validateSettings(const Settings& settings) {
    // One set of rules: the JSON reader's type and range checks, applied to the values as written.
    Settings scratch;
    return readSettingsJson(settingsToJson(settings), scratch);
}

} // namespace photopic
