#pragma once
// The options several commands take, registered the same way on each: the settings sources, OpenColorIO,
// --max-pixels, the display encoding, an EXR's channels and a sequence's inputs.

#include "Commands.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace photopic::cli {

/// An output path that reads as an option ("-o -y" would make a folder named "-y") is refused; "-" alone is
/// standard output, and "./-y" names such a file on purpose.
extern const CLI::Validator kOutputPath;

/// The file types a frame can be written as: the display image's formats, then EXR (scene-referred).
extern const std::vector<std::string> kFrameFormats;

/// "a, b, c": an enum's names as its option's help lists them, from the same list the settings reader checks.
template <class Names>
std::string joined(const Names& names) {
    std::string out;
    for (const auto& name : names) {
        out += (out.empty() ? "" : ", ") + std::string(name);
    }
    return out;
}

/// --preset's help: the presets and what each is for, then where a command's own default comes from.
std::string presetHelp(std::string_view commandDefault);

/// --preset, --settings, --tonemap, --exposure, --debug and --set.
void addSettingsOptions(CLI::App* cmd, SettingsSources& s, std::string_view presetDefault);
/// --ocio-display, --ocio-view and --ocio-config.
void addOcioOptions(CLI::App* cmd, OcioOptions& o);
void addMaxPixelsOption(CLI::App* cmd, std::int64_t& maxPixels);
/// --bit-depth and --jpeg-quality, as `photopic image` and `photopic scene` both take them.
void addDisplayEncodingOptions(CLI::App* cmd, std::optional<int>& bitDepth, int& jpegQuality);
/// --aovs, --layer and --aov: which channels of an EXR feed what (docs/interop.md).
void addChannelOptions(CLI::App* cmd, std::string& preset, std::string& layer,
                       std::vector<std::string>& aovs);
/// The inputs of a sequence: files or patterns, --frames, --start-number (as `photopic image` takes them).
void addSequenceInputs(CLI::App* cmd, ImageOptions& o);

} // namespace photopic::cli
