#pragma once
// The three stages of a sequence rendered in chunks, on one machine or a farm (docs/farm.md):
//   photopic meter   each frame's metering (frames apart, in parallel)           -> meter CSV
//   photopic expose  the exposure controller over every frame in order (CPU)      -> exposure track CSV
//   photopic image   --exposure-track --preroll: any chunk, the single run's frames
//   photopic farm    writes (and submits) those stages as a Slurm job set

#include "Commands.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace photopic::cli {

/// The output file of `photopic meter` or `expose`, written atomically; an error names the command and the
/// file.
AtomicFileWriter openCommandOutput(std::string_view command, const std::filesystem::path& path);

/// `photopic meter INPUTS -o meter.csv`: the inputs, frames and settings as `photopic image` takes them.
class MeterCommand {
public:
    explicit MeterCommand(const ImageOptions& options)
        : mOptions(options) {}
    int run();

private:
    const ImageOptions& mOptions;
};

struct ExposeOptions {
    std::vector<std::filesystem::path> meterFiles;
    std::filesystem::path output; ///< the exposure track
    float fps = 30.0f;
    SettingsSources settings;
    std::vector<std::int64_t> cuts; ///< frames where exposure snaps to its target (the first always does)
    bool allowGaps = false;         ///< frames missing between the first and the last are not an error
};

/// `photopic expose meter*.csv --fps F -o exposure.csv`.
class ExposeCommand {
public:
    explicit ExposeCommand(const ExposeOptions& options)
        : mOptions(options) {}
    int run();

private:
    const ExposeOptions& mOptions;
};

struct FarmOptions {
    std::filesystem::path input;  ///< one frame-numbered pattern
    std::string frames;           ///< --frames A-B; empty: every frame that exists
    std::filesystem::path output; ///< the output pattern of `photopic image` (out/f%04d.png)
    std::filesystem::path jobDir; ///< where the job set is written
    int chunk = 100;              ///< frames a render (and meter) job takes
    int preroll = -1;             ///< -1: the default (kDefaultFarmPreroll)
    float fps = 30.0f;
    SettingsSources settings;
    std::vector<std::int64_t> cuts;
    std::string photopic;                   ///< the command the jobs run; empty: this program's own path
    std::vector<std::string> sbatchOptions; ///< --sbatch-option, added to every job (-p, --account, ...)
    std::vector<std::string> imageOptions;  ///< --image-option, added to each render's command line
    bool submit = false;
};

/// Frames a farm template renders before each chunk's first when nothing says otherwise (docs/farm.md has
/// the residual against the single run for 0, 8, 16 and 32).
inline constexpr int kDefaultFarmPreroll = 24;

/// `photopic farm PATTERN -o OUT --chunk N --jobs DIR [--submit]`.
class FarmCommand {
public:
    explicit FarmCommand(const FarmOptions& options)
        : mOptions(options) {}
    int run();

private:
    const FarmOptions& mOptions;
};

} // namespace photopic::cli
