#pragma once
// `photopic meter INPUTS -o meter.csv`: each frame's metering, one CSV row per frame, for `photopic expose`
// (SequenceCommands.h has the stages). The inputs, frames and settings as `photopic image` takes them.

#include "Command.h"
#include "Commands.h"
#include "InputSequence.h"

#include <cstdint>
#include <map>
#include <vector>

namespace photopic::cli {

class MeterCommand final : public Command {
public:
    explicit MeterCommand(CLI::App& parent);
    int run() override;

private:
    /// Each input's reading into `file`, 64 rows at a time; throws when a frame's reading did not come back.
    void meterFrames(const std::vector<InputFile>& files, const Settings& settings,
                     AtomicFileWriter& file) const;
    /// The readings the pipeline has collected, as rows of `file`; returns how many.
    static std::uint64_t writeRows(Pipeline& pipeline, const AutoExposureSettings& ae,
                                   std::map<std::uint64_t, float>& cameraLog2, AtomicFileWriter& file);

    ImageOptions mOptions;
};

} // namespace photopic::cli
