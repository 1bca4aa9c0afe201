#pragma once
// `photopic settings --defaults / --check FILE / --markdown`: the default settings, a settings file checked,
// or the reference of every setting.

#include "Command.h"

#include <filesystem>
#include <string>

namespace photopic::cli {

class SettingsCommand final : public Command {
public:
    explicit SettingsCommand(CLI::App& parent);
    [[nodiscard]] bool usesGl() const override { return false; }
    int run() override;

private:
    /// --defaults: every field of the defaults with the preset's look (none: empty).
    int printDefaults() const;
    /// --check FILE: with --preset, the file over that preset's look, as --preset reads it.
    int check() const;
    /// --markdown: the reference of every setting.
    int printMarkdown() const;

    bool mDefaults = false;
    bool mMarkdown = false;
    std::filesystem::path mCheckFile;
    std::string mPreset;
};

} // namespace photopic::cli
