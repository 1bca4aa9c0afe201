// `photopic settings --defaults / --check / --markdown` (SettingsCommand.h).
#include "SettingsCommand.h"

#include "CommandOptions.h"
#include "SettingsReference.h"

#include "core/settings/SettingsJson.h"

#include <cstdio>

namespace photopic::cli {

SettingsCommand::SettingsCommand(CLI::App& parent)
    : Command(parent.add_subcommand(
          "settings", "print the default settings, check a settings file or print the settings reference")) {
    CLI::App& cmd = app();
    auto* defaultsFlag = cmd.add_flag("--defaults", mDefaults, "print the full default JSON");
    auto* checkOption = cmd.add_option("--check", mCheckFile, "validate FILE and list every issue");
    auto* markdownFlag =
        cmd.add_flag("--markdown", mMarkdown,
                     "print the reference of every setting (key, type, default, range, meaning) as Markdown: "
                     "docs/settings.md");
    defaultsFlag->excludes(checkOption);
    markdownFlag->excludes(defaultsFlag, checkOption);
    cmd.add_option("--preset", mPreset,
                   "with --defaults: the defaults with this look (" + joined(presetNames()) +
                       "); with --check: the file over this look, as --preset reads it");
    cmd.require_option(1, 2);
    cmd.footer("Examples:\n"
               "  photopic settings --defaults > mine.json\n"
               "  photopic settings --defaults --preset stills   what photopic image starts from\n"
               "  photopic settings --check mine.json\n"
               "  photopic settings --markdown > docs/settings.md");
}

int SettingsCommand::run() {
    if (mMarkdown) {
        return printMarkdown();
    }
    if (!mDefaults && mCheckFile.empty()) {
        throw InputError("settings: --defaults, --check FILE or --markdown is required");
    }
    return mDefaults ? printDefaults() : check();
}

int SettingsCommand::printMarkdown() const {
    if (!mPreset.empty()) {
        throw InputError("settings: --markdown lists every preset; --preset does not apply");
    }
    std::fputs(settingsReferenceMarkdown().c_str(), stdout);
    return kOk;
}

int SettingsCommand::printDefaults() const {
    std::fputs(settingsToJson(mPreset.empty() ? Settings{} : presetLook(mPreset)).c_str(), stdout);
    return kOk;
}

int SettingsCommand::check() const {
    // Throws SettingsError listing every issue (an unknown "preset" among them) -> exit 2.
    SettingsSources sources;
    sources.preset = mPreset;
    sources.file = mCheckFile;
    const Settings settings = resolveSettings(sources);
    (void)settings;
    std::printf("%s: valid\n", mCheckFile.string().c_str());
    return kOk;
}

} // namespace photopic::cli
