#pragma once
// `photopic farm PATTERN -o OUT --chunk N --jobs DIR [--submit]`: a sequence's meter, expose and render
// stages written as a Slurm job set (SequenceCommands.h has the stages), submitted with --submit.

#include "Command.h"
#include "Commands.h"

#include <filesystem>
#include <string>
#include <vector>

namespace photopic::cli {

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

class FarmCommand final : public Command {
public:
    explicit FarmCommand(CLI::App& parent);
    [[nodiscard]] bool usesGl() const override { return false; }
    int run() override;

private:
    FarmOptions mOptions;
};

} // namespace photopic::cli
