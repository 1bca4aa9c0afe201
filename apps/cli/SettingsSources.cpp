// The settings every command resolves (SettingsSources): a base, a preset's look, the settings file, then the
// command line's shorthands and --set overrides, in that order.
#include "Commands.h"

#include "core/settings/SettingsJson.h"

#include <fmt/format.h>

#include <optional>
#include <utility>

namespace photopic::cli {

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

} // namespace photopic::cli
