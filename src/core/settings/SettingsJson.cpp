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

std::string escapeInvalidUtf8(std::string_view text) {
    std::string out;
    while (const auto bad = invalidUtf8Offset(text)) {
        out += text.substr(0, *bad);
        out += fmt::format("\\x{:02x}", static_cast<unsigned char>(text[*bad]));
        text.remove_prefix(*bad + 1);
    }
    return out + std::string(text);
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
            issues.push_back({SettingsIssueCode::UnknownKey, key,
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
    std::string out;
    for (const auto& issue : issues) {
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

std::optional<std::size_t> invalidUtf8Offset(std::string_view text) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    std::size_t i = 0;
    while (i < text.size()) {
        const unsigned char lead = byte(i);
        std::size_t length = 0;
        unsigned char low = 0x80; // bounds of the second byte (they exclude overlong forms and surrogates)
        unsigned char high = 0xbf;
        if (lead < 0x80) {
            ++i;
            continue;
        } else if (lead >= 0xc2 && lead <= 0xdf) {
            length = 2;
        } else if (lead >= 0xe0 && lead <= 0xef) {
            length = 3;
            low = lead == 0xe0 ? 0xa0 : 0x80;
            high = lead == 0xed ? 0x9f : 0xbf;
        } else if (lead >= 0xf0 && lead <= 0xf4) {
            length = 4;
            low = lead == 0xf0 ? 0x90 : 0x80;
            high = lead == 0xf4 ? 0x8f : 0xbf;
        } else {
            return i;
        }
        if (i + length > text.size() || byte(i + 1) < low || byte(i + 1) > high) {
            return i;
        }
        for (std::size_t k = 2; k < length; ++k) {
            if (byte(i + k) < 0x80 || byte(i + k) > 0xbf) {
                return i;
            }
        }
        i += length;
    }
    return std::nullopt;
}

std::string unknownPresetMessage(std::string_view name) {
    return fmt::format("unknown preset '{}' (known presets: {})", name, joinNames(presetNames()));
}

std::vector<SettingsIssue> readSettingsJson(std::string_view text, Settings& settings,
                                            DocumentPreset preset) {
    // nlohmann's exceptions all derive from json::exception: a parse error, but also out_of_range.406 for a
    // number beyond double range (1e400). One catch of the base keeps every one of them inside the issues.
    try {
        const json doc = json::parse(text);
        // Read into a copy so a document with issues leaves `settings` exactly as it was.
        Settings candidate = settings;
        auto issues = readDocument(doc, candidate, preset);
        if (issues.empty()) {
            settings = std::move(candidate);
        }
        return issues;
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
    std::ifstream in(file, std::ios::binary);
    if (!in || std::filesystem::is_directory(file, ec)) {
        throw SettingsError(
            file.string(),
            {{SettingsIssueCode::UnreadableFile, "",
              fmt::format("settings file {} cannot be read (a folder, or no permission)", file.string())}});
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

void applySettingsOverride(Settings& settings, std::string_view assignment, std::string_view option) {
    // Command-line text is raw bytes: say so when it is not UTF-8 (JSON strings must be), and print it with
    // \xNN in place of the bad bytes so the message itself stays valid text.
    const std::string source =
        option.empty() ? fmt::format("--set {}", escapeInvalidUtf8(assignment)) : escapeInvalidUtf8(option);
    if (const auto bad = invalidUtf8Offset(assignment)) {
        throw SettingsError(source, {{SettingsIssueCode::InvalidUtf8, "",
                                      fmt::format("at byte {} (0x{:02x}); settings text must be UTF-8", *bad,
                                                  static_cast<unsigned char>(assignment[*bad]))}});
    }
    try {
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
