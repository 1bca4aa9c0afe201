// `photopic settings --defaults / --check` and the settings every command resolves: a base, a preset's look,
// the settings file, then the command line's shorthands and --set overrides, in that order.
#include "Commands.h"

#include "core/settings/SettingsJson.h"

#include <fmt/format.h>

#include <cstdio>
#include <optional>
#include <utility>

namespace photopic::cli {

namespace fs = std::filesystem;

Settings presetLook(const std::string& name) {
    std::optional<Settings> look = Settings::preset(name);
    if (!look) {
        throw InputError("--preset: " + unknownPresetMessage(name));
    }
    return *look;
}

Settings resolveSettings(const SettingsSources& sources, Settings base) {
    Settings settings = std::move(base);
    if (!sources.preset.empty()) {
        settings.applyLook(presetLook(sources.preset));
    }
    if (!sources.file.empty()) {
        // The command line's preset wins over the file's; the file's other keys still land on top of it.
        settings = loadSettingsFile(sources.file, std::move(settings),
                                    sources.preset.empty() ? DocumentPreset::Apply : DocumentPreset::Ignore);
    }
    // The shorthands' errors name the option the user typed, not the --set it stands for.
    if (!sources.tonemap.empty()) {
        applySettingsOverride(settings, "tonemapping.mode=" + sources.tonemap,
                              "--tonemap " + sources.tonemap);
    }
    if (sources.exposure) {
        applySettingsOverride(settings, fmt::format("tonemapping.exposure={}", *sources.exposure),
                              fmt::format("--exposure {}", *sources.exposure));
    }
    if (!sources.debugView.empty()) {
        applySettingsOverride(settings, "debug.view=" + sources.debugView, "--debug " + sources.debugView);
    }
    for (const auto& o : sources.overrides) {
        applySettingsOverride(settings, o);
    }
    return settings;
}

int runSettingsDefaults(const std::string& preset) {
    std::fputs(settingsToJson(preset.empty() ? Settings{} : presetLook(preset)).c_str(), stdout);
    return kOk;
}

int runSettingsCheck(const fs::path& file, const std::string& preset) {
    // Throws SettingsError listing every issue (an unknown "preset" among them) -> exit 2.
    SettingsSources sources;
    sources.preset = preset;
    sources.file = file;
    const Settings settings = resolveSettings(sources);
    (void)settings;
    std::printf("%s: valid\n", file.string().c_str());
    return kOk;
}

} // namespace photopic::cli
