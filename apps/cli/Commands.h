#pragma once
// The photopic CLI's commands. Each returns the process exit code: 0 ok, 2 bad usage or input, 1 other
// failure.

#include "core/Settings.h"

#include <filesystem>
#include <string>
#include <vector>

namespace photopic::cli {

enum ExitCode : int { kOk = 0, kFailure = 1, kBadInput = 2 };

/// Bad usage or bad input (a file that cannot be read, settings that do not validate): exit 2.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Settings from defaults, then --settings FILE, then the shorthand flags, then each --set in order.
struct SettingsSources {
    std::filesystem::path file;
    std::string tonemap;
    std::optional<float> exposure;
    std::vector<std::string> overrides;
};
Settings resolveSettings(const SettingsSources& sources);

struct ImageOptions {
    std::vector<std::filesystem::path> inputs;
    std::filesystem::path output;
    std::string format = "png"; ///< for folder outputs: png or exr
    SettingsSources settings;
    bool forceLdr = false;
    float fps = 30.0f;
};

/// GL and capability report; with settings, also the quality tier and the path frames would take.
int runInfo(bool forceLdr, const SettingsSources& settings);
int runImage(const ImageOptions& options);
int runSettingsDefaults();
int runSettingsCheck(const std::filesystem::path& file);
int runDemo(const std::filesystem::path& dataDir, const std::filesystem::path& outDir);

} // namespace photopic::cli
