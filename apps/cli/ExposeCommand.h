#pragma once
// `photopic expose meter*.csv --fps F -o exposure.csv`: the exposure controller over every metered frame in
// order, one row per frame, for `photopic image --exposure-track` (SequenceCommands.h has the stages).

#include "Command.h"
#include "Commands.h"

#include "common/ExposureTrack.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace photopic::cli {

struct ExposeOptions {
    std::vector<std::filesystem::path> meterFiles;
    std::filesystem::path output; ///< the exposure track
    float fps = 30.0f;
    SettingsSources settings;
    std::vector<std::int64_t> cuts; ///< frames where exposure snaps to its target (the first always does)
    bool allowGaps = false;         ///< frames missing between the first and the last are not an error
};

class ExposeCommand final : public Command {
public:
    explicit ExposeCommand(CLI::App& parent);
    [[nodiscard]] bool usesGl() const override { return false; }
    int run() override;

private:
    /// The meter files merged into one, checked to have been metered as `settings` meter.
    [[nodiscard]] MeterFile mergedMeterFiles(const Settings& settings) const;
    /// Gaps (unless --allow-gaps) and cuts that are no metered frame are errors.
    void checkFrames(const std::vector<MeterRecord>& records) const;

    ExposeOptions mOptions;
};

} // namespace photopic::cli
