// The frames a `photopic image` run processes (RunFrames.h).
#include "RunFrames.h"

#include <optional>

namespace photopic::cli {

RunFrames runFrames(const ImageOptions& options, const std::vector<InputFile>& written) {
    std::vector<InputFile> all = prerollInputs(options, written, options.preroll);
    RunFrames run;
    run.prerolled = all.size();
    all.insert(all.end(), written.begin(), written.end());
    for (const InputFile& f : all) {
        run.inputs.push_back(f.path);
    }
    run.numbers = outputFrameNumbers(all);
    run.frameNumbers = inputFrameNumbers(all);
    if (const std::optional<std::int64_t> start = sequenceStart(options); start && all.front().frame) {
        run.firstIndex = std::uint64_t(*all.front().frame - *start);
    }
    return run;
}

void trimPrerollAtCut(RunFrames& run, const ExposureTrack& track) {
    std::size_t from = 0;
    for (std::size_t k = 1; k <= run.prerolled && k < run.numbers.size(); ++k) {
        if (track.find(run.numbers[k])->cut) {
            from = k;
        }
    }
    run.inputs.erase(run.inputs.begin(), run.inputs.begin() + std::ptrdiff_t(from));
    run.numbers.erase(run.numbers.begin(), run.numbers.begin() + std::ptrdiff_t(from));
    run.prerolled -= from;
    run.firstIndex += from;
}

} // namespace photopic::cli
