#pragma once
// Where `photopic image` writes, every path checked before any work (plannedOutputs).

#include "Commands.h"
#include "InputSequence.h"
#include "Outputs.h"

#include <filesystem>
#include <string>
#include <vector>

namespace photopic::cli {

/// The extension of `p`, lower case, with its dot (".png"); empty for none.
[[nodiscard]] std::string lowerExtension(const std::filesystem::path& p);

/// Where `photopic image` writes each input's result, every path checked before any work. The rules of -o:
/// "-", a device or a pipe is a stream; a name with a frame number (out/f%04d.png) is a pattern; an extension
/// means a file; a trailing '/', an existing folder, no extension or several inputs mean a folder. Several
/// inputs and the name of an image file (out.png, not an existing folder) are refused.
std::vector<std::filesystem::path> plannedOutputs(const ImageOptions& options,
                                                  const std::vector<InputFile>& files, RunOutputs& outputs);

/// `-n`: the telemetry CSV and the --write-aux files of `inputs` must be new too.
void requireNewSideOutputs(const ImageOptions& options, const std::vector<std::filesystem::path>& inputs);

} // namespace photopic::cli
