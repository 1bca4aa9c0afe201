#pragma once
// JSON form of the settings: {"version": 1, "postEffects": {...}} with the keys common to post-effect
// settings files kept where they exist.

#include "core/Settings.h"
#include "core/ShownText.h" // invalidUtf8Offset, for callers that check command-line text

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace photopic {

inline constexpr int kSettingsVersion = 1;

/// Thrown at set-up boundaries when settings cannot be used; holds every issue found, not just the first.
/// what() reads "invalid settings in SOURCE:" then one line per issue, or for a settings file that is missing
/// or cannot be read, just that sentence naming the file.
class SettingsError : public std::runtime_error {
public:
    SettingsError(std::string source, std::vector<SettingsIssue> issues);
    [[nodiscard]] const std::vector<SettingsIssue>& issues() const { return mIssues; }

private:
    std::vector<SettingsIssue> mIssues;
};

/// What a document's top-level "preset" (a name from presetNames()) does: Apply takes that preset's look
/// first, then the document's other keys over it; Ignore checks the name only, for a caller whose own
/// preset (the command line's) wins.
enum class DocumentPreset { Apply, Ignore };

/// Reads JSON text over `settings` (keys that are absent keep their current values). Returns the issues
/// found; fields with issues are left unchanged. Never throws for any text: JSON the parser rejects (bad
/// syntax, bad UTF-8, a number beyond double range) is a ParseError issue.
std::vector<SettingsIssue> readSettingsJson(std::string_view text, Settings& settings,
                                            DocumentPreset preset = DocumentPreset::Apply);

/// Loads a file over `base` (the defaults unless given); throws SettingsError naming the file and every
/// issue.
Settings loadSettingsFile(const std::filesystem::path& file, Settings base = {},
                          DocumentPreset preset = DocumentPreset::Apply);

/// "unknown preset 'NAME' (known presets: stills, realtime, neutral)": what a bad `--preset` or "preset"
/// says.
std::string unknownPresetMessage(std::string_view name);

/// Full JSON of every field (what `photopic settings --defaults` prints). Save then load is lossless.
std::string settingsToJson(const Settings& settings);
nlohmann::json settingsToJsonValue(const Settings& settings);

/// Applies "path=value" (path below postEffects, e.g. "tonemapping.mode=agx"). The value is parsed as JSON
/// when it is valid JSON, else taken as a string. Throws SettingsError naming the override: as "--set
/// path=value", or as `option` when a shorthand made it (e.g. "--tonemap nope" for tonemapping.mode=nope).
void applySettingsOverride(Settings& settings, std::string_view assignment, std::string_view option = {});

/// Every issue `settings` has (a value out of its range, a NaN), by JSON path: what loading the same values
/// from JSON would report. Empty when the settings can be used.
std::vector<SettingsIssue> validateSettings(const Settings& settings);

/// "postEffects.a.b: message (allowed ...)" lines, one per issue; an unknown key reads "postEffects.a.b:
/// unknown key (known keys: ...)".
std::string formatSettingsIssues(const std::vector<SettingsIssue>& issues);

} // namespace photopic
