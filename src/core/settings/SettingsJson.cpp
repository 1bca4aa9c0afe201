#include "core/settings/SettingsJson.h"

#include "core/JsonText.h"
#include "core/ShownText.h"
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

/// The document's "preset", laid over `settings` when `use` says so. False when it is not a preset's name.
bool readPreset(const json& doc, Settings& settings, DocumentPreset use, std::vector<SettingsIssue>& issues) {
    const auto p = doc.find("preset");
    if (p == doc.end()) {
        return true;
    }
    if (!p->is_string()) {
        issues.push_back(
            {SettingsIssueCode::WrongType, "preset",
             fmt::format("expected a preset name ({}), got {}", joinNames(presetNames()), shown(*p))});
        return false;
    }
    const std::optional<Settings> look = Settings::preset(p->get<std::string>());
    if (!look) {
        issues.push_back({SettingsIssueCode::BadEnum, "preset", unknownPresetMessage(p->get<std::string>())});
        return false;
    }
    if (use == DocumentPreset::Apply) {
        settings.applyLook(*look);
    }
    return true;
}

std::vector<SettingsIssue> readDocument(const json& doc, Settings& settings,
                                        DocumentPreset preset = DocumentPreset::Apply) {
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
                                          shown(*v), kSettingsVersion)});
            return issues;
        }
    }
    for (const auto& [key, value] : doc.items()) {
        if (key != "version" && key != "preset" && key != "postEffects") {
            // A settings group written at the top ({"bloom": ...}) is the likeliest slip: say where it goes.
            const bool group = writeObject(Settings{}).contains(key);
            issues.push_back({SettingsIssueCode::UnknownKey, shownText(key),
                              group ? fmt::format("known keys: version, preset, postEffects; \"{}\" belongs "
                                                  "inside postEffects: {{\"postEffects\": {{\"{}\": ...}}}}",
                                                  key, key)
                                    : std::string("known keys: version, preset, postEffects")});
        }
    }
    // The preset first, so that the document's own keys land on top of it.
    if (!readPreset(doc, settings, preset, issues)) {
        return issues;
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

/// A file that could not be read has no settings to be invalid: its message stands alone.
bool unreadable(const std::vector<SettingsIssue>& issues) {
    return issues.size() == 1 && (issues[0].code == SettingsIssueCode::MissingFile ||
                                  issues[0].code == SettingsIssueCode::UnreadableFile);
}

std::string describeSettingsError(const std::string& source, const std::vector<SettingsIssue>& issues) {
    if (unreadable(issues)) {
        return issues[0].message + "\n";
    }
    return "invalid settings in " + source + ":\n" + formatSettingsIssues(issues);
}

} // namespace

SettingsError::SettingsError(std::string source, std::vector<SettingsIssue> issues)
    : std::runtime_error(describeSettingsError(source, issues))
    , mIssues(std::move(issues)) {}

std::string formatSettingsIssues(const std::vector<SettingsIssue>& issues) {
    // A document can hold any number of mistakes; the first ones say what is wrong, the count the rest.
    constexpr std::size_t kMaxListed = 20;
    std::string out;
    for (std::size_t i = 0; i < issues.size(); ++i) {
        if (i == kMaxListed) {
            out += fmt::format("  ... and {} more\n", issues.size() - kMaxListed);
            break;
        }
        const SettingsIssue& issue = issues[i];
        const std::string path = issue.path.empty() ? "(document)" : issue.path;
        // An unknown key's message is the keys that would have been read there: "unknown key" once.
        if (issue.code == SettingsIssueCode::UnknownKey) {
            out += fmt::format("  {}: {} ({})\n", path, issueText(issue.code), issue.message);
        } else {
            out += fmt::format("  {}: {}: {}\n", path, issueText(issue.code), issue.message);
        }
    }
    return out;
}

std::string unknownPresetMessage(std::string_view name) {
    return fmt::format("unknown preset '{}' (known presets: {})", shownText(name), joinNames(presetNames()));
}

std::vector<SettingsIssue> readSettingsJson(std::string_view text, Settings& settings,
                                            DocumentPreset preset) {
    // parseJsonText turns every parse failure (syntax, nesting, a duplicate key, 1e400) into one error.
    try {
        const json doc = parseJsonText(text);
        // Read into a copy so a document with issues leaves `settings` exactly as it was.
        Settings candidate = settings;
        auto issues = readDocument(doc, candidate, preset);
        if (issues.empty()) {
            settings = std::move(candidate);
        }
        return issues;
    } catch (const JsonTextError& e) {
        return {{SettingsIssueCode::ParseError, "", e.what()}};
    } catch (const json::exception& e) {
        return {{SettingsIssueCode::ParseError, "", e.what()}};
    }
}

Settings loadSettingsFile(const std::filesystem::path& file, Settings base, DocumentPreset preset) {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) {
        throw SettingsError(file.string(), {{SettingsIssueCode::MissingFile, "",
                                             fmt::format("settings file {} does not exist", file.string())}});
    }
    // Checked before opening: opening a named pipe for reading waits for a writer, possibly forever.
    if (!std::filesystem::is_regular_file(file, ec)) {
        throw SettingsError(
            file.string(),
            {{SettingsIssueCode::UnreadableFile, "",
              fmt::format("settings file {} is not a regular file (a folder, a pipe or a device)",
                          file.string())}});
    }
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        throw SettingsError(
            file.string(), {{SettingsIssueCode::UnreadableFile, "",
                             fmt::format("settings file {} cannot be read (no permission)", file.string())}});
    }
    std::stringstream ss;
    ss << in.rdbuf();
    auto issues = readSettingsJson(ss.str(), base, preset);
    if (!issues.empty()) {
        throw SettingsError(file.string(), std::move(issues));
    }
    return base;
}

json settingsToJsonValue(const Settings& settings) {
    return json{{"version", kSettingsVersion}, {"postEffects", writeObject(settings)}};
}

std::string settingsToJson(const Settings& settings) {
    // A string field set through the API may hold bytes that are not UTF-8: write U+FFFD rather than throw.
    return settingsToJsonValue(settings).dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

namespace settings_json {

bool parseAssignment(std::string_view assignment, json& patch) {
    const auto eq = assignment.find('=');
    if (eq == std::string_view::npos || eq == 0) {
        return false;
    }
    std::vector<std::string> parts;
    std::string_view rest = assignment.substr(0, eq);
    while (!rest.empty()) {
        const auto dot = rest.find('.');
        parts.emplace_back(rest.substr(0, dot));
        rest = dot == std::string_view::npos ? std::string_view{} : rest.substr(dot + 1);
        if (parts.size() > kMaxOverrideParts) {
            throw JsonTextError(JsonTextError::Kind::TooDeep,
                                fmt::format("the key has more than {} parts", kMaxOverrideParts));
        }
    }
    const std::string valueText(assignment.substr(eq + 1));
    try {
        patch = parseJsonText(valueText);
    } catch (const JsonTextError& e) {
        // Bare words such as agx are strings; text that is JSON but breaks a limit (1e400, an array nested
        // too deep, a key twice) or an array or object that does not parse is an error, not a string.
        const bool container = valueText.starts_with('[') || valueText.starts_with('{');
        if (e.kind != JsonTextError::Kind::Syntax || container) {
            throw;
        }
        patch = valueText;
    }
    for (auto it = parts.rbegin(); it != parts.rend(); ++it) {
        patch = json{{*it, patch}};
    }
    return true;
}

} // namespace settings_json

void applySettingsOverride(Settings& settings, std::string_view assignment, std::string_view option) {
    // Command-line text is raw bytes: say so when it is not UTF-8 (JSON strings must be), and print it with
    // \xNN in place of the bad bytes so the message itself stays valid text.
    const std::string source =
        option.empty() ? fmt::format("--set {}", shownText(assignment)) : shownText(option);
    if (const auto bad = invalidUtf8Offset(assignment)) {
        throw SettingsError(source, {{SettingsIssueCode::InvalidUtf8, "",
                                      fmt::format("at byte {} (0x{:02x}); settings text must be UTF-8", *bad,
                                                  static_cast<unsigned char>(assignment[*bad]))}});
    }
    try {
        // Build {"postEffects": {"a": {"b": value}}} and read it like a file, so errors carry the same paths.
        json patch;
        if (!parseAssignment(assignment, patch)) {
            throw SettingsError(source, {{SettingsIssueCode::BadOverride, shownText(assignment),
                                          "expected path=value, e.g. tonemapping.mode=agx"}});
        }
        Settings candidate = settings;
        auto issues = readDocument(json{{"postEffects", patch}}, candidate);
        if (!issues.empty()) {
            throw SettingsError(source, std::move(issues));
        }
        settings = std::move(candidate);
    } catch (const JsonTextError& e) {
        throw SettingsError(source, {{SettingsIssueCode::ParseError, "", e.what()}});
    } catch (const json::exception& e) {
        throw SettingsError(source, {{SettingsIssueCode::ParseError, "", e.what()}});
    }
}

std::vector<SettingsIssue> validateSettings(const Settings& settings) {
    // One set of rules: the JSON reader's type and range checks, applied to the values as written.
    Settings scratch;
    return readSettingsJson(settingsToJson(settings), scratch);
}

} // namespace photopic
