#pragma once
// The three stages of a sequence rendered in chunks, on one machine or a farm (docs/farm.md):
//   photopic meter   each frame's metering (frames apart, in parallel)           -> meter CSV
//   photopic expose  the exposure controller over every frame in order (CPU)      -> exposure track CSV
//   photopic image   --exposure-track --preroll: any chunk, the single run's frames
//   photopic farm    writes (and submits) those stages as a Slurm job set

#include "Commands.h"
#include "ExposeCommand.h"
#include "FarmCommand.h"
#include "MeterCommand.h"

#include <filesystem>
#include <string_view>

namespace photopic::cli {

/// The output file of `photopic meter` or `expose`, written atomically; an error names the command and the
/// file.
AtomicFileWriter openCommandOutput(std::string_view command, const std::filesystem::path& path);

} // namespace photopic::cli
