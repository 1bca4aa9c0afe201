// Where `photopic image` writes (PlannedOutputs.h), and the checks every output passes before any work.
#include "PlannedOutputs.h"

#include "common/SequencePattern.h"
#include "io/DisplayImageIO.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <stdexcept>

namespace photopic::cli {

namespace fs = std::filesystem;

std::string lowerExtension(const fs::path& p) {
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// A JPEG holds 8 bits per channel: a 16-bit display image bound for one is refused rather than narrowed
// without a word.
void requireBitDepthFits(const std::vector<fs::path>& outputs, int bitDepth, std::string_view source) {
    for (const fs::path& out : outputs) {
        const std::optional<DisplayFileFormat> format = displayFileFormatFor(out);
        if (format && !holdsBitDepth(*format, bitDepth)) {
            throw InputError(fmt::format("output {}: {} holds 8 bits per channel only, but {} is {}: write "
                                         ".png or .tif for 16 bits, or use 8",
                                         out.string(), displayFileFormatName(*format), source, bitDepth));
        }
    }
}

namespace {

/// The same file, whether or not it exists yet (links and relative paths resolved).
bool sameFile(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    if (fs::equivalent(a, b, ec)) {
        return true;
    }
    const fs::path ca = fs::weakly_canonical(a, ec);
    return !ec && ca == fs::weakly_canonical(b, ec) && !ec;
}

/// Refuses outputs that would destroy an input or each other: an output that is one of the inputs, and two
/// inputs whose results would land on the same file.
void requireDistinctOutputs(const std::vector<fs::path>& inputs, const std::vector<fs::path>& outputs) {
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        for (const fs::path& in : inputs) {
            if (sameFile(outputs[i], in)) {
                throw InputError(fmt::format("output {} is also an input; it would be overwritten: choose "
                                             "another output",
                                             outputs[i].string()));
            }
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (sameFile(outputs[i], outputs[j])) {
                throw InputError(fmt::format("inputs {} and {} would both be written to {}: give them "
                                             "different names or process them separately",
                                             inputs[j].string(), inputs[i].string(), outputs[i].string()));
            }
        }
    }
}

/// `-o -`, a device or a pipe: one image, as PNG (or EXR into a pipe named .exr), written as it is encoded.
fs::path streamOutput(const ImageOptions& options, std::size_t inputCount) {
    const fs::path& out = options.output;
    if (inputCount > 1) {
        throw InputError(
            fmt::format("output {} is a stream (standard output, a device or a pipe) and holds one "
                        "image, not {}: name a folder (-o out/) or a pattern (-o out/f%04d.png)",
                        out.string(), inputCount));
    }
    if (options.format != "png" && lowerExtension(out) != "." + options.format) {
        throw InputError(fmt::format("output {}: a stream carries the display image as PNG; --format {} "
                                     "needs a file or folder",
                                     out.string(), options.format));
    }
    return out;
}

void requireExtension(const fs::path& out) {
    const std::string ext = lowerExtension(out);
    if (!displayFileFormatFor(out) && ext != ".exr") {
        throw InputError(
            fmt::format("output {}: unsupported extension '{}' (use .png, .tif, .tiff, .jpg or .jpeg for the "
                        "display image, or .exr for the scene-referred image)",
                        out.string(), ext));
    }
}

/// The frame-number pattern of an output's file name (out/f%04d.png), if it holds one. A name with a '%' that
/// is no frame number ("50%.png") is an ordinary name, as it was before patterns.
std::optional<FramePattern> outputPattern(const fs::path& out) {
    try {
        return parseFramePattern(out.filename().string());
    } catch (const std::invalid_argument&) {
        return std::nullopt;
    }
}

/// `-n`: every output must be new.
void requireNew(const std::vector<fs::path>& paths) {
    for (const fs::path& path : paths) {
        std::error_code ec;
        if (fs::exists(fs::symlink_status(path, ec))) {
            throw InputError(fmt::format("output {} exists already (-n: never overwrite); remove it, choose "
                                         "another output, or leave out -n",
                                         path.string()));
        }
    }
}

} // namespace

std::vector<fs::path> plannedOutputs(const ImageOptions& options, const std::vector<InputFile>& files,
                                     RunOutputs& outputs) {
    const fs::path& out = options.output;
    if (isStreamOutput(out)) {
        return {streamOutput(options, files.size())};
    }
    std::vector<fs::path> inputs;
    for (const InputFile& f : files) {
        inputs.push_back(f.path);
    }
    std::vector<fs::path> paths;
    fs::path folder; // made before the outputs are checked; empty: none
    if (const std::optional<FramePattern> pattern = outputPattern(out)) {
        requireExtension(out);
        for (const std::int64_t n : outputFrameNumbers(files)) {
            paths.push_back(out.parent_path() / pattern->name(n));
        }
        folder = out.parent_path();
    } else if (inputs.size() > 1 && !fs::is_directory(out) &&
               (displayFileFormatFor(out) || lowerExtension(out) == ".exr")) {
        // A name like out.png is one image; a folder of that name, made silently, is not what it asked for.
        throw InputError(fmt::format("output {} names one image file, and there are {} inputs: name a folder "
                                     "(-o out/) or a pattern (-o out/f%04d.png)",
                                     out.string(), inputs.size()));
    } else if (inputs.size() > 1 || fs::is_directory(out) || lowerExtension(out).empty()) {
        for (const fs::path& in : inputs) {
            paths.push_back(out / (in.stem().string() + "." + options.format));
        }
        folder = out;
    } else {
        requireExtension(out);
        paths.push_back(out);
    }
    requireDistinctOutputs(inputs, paths);
    if (options.noOverwrite) {
        requireNew(paths);
    }
    if (!folder.empty()) {
        outputs.makeFolder(folder);
    }
    for (const fs::path& path : paths) {
        RunOutputs::requireFile(path);
    }
    return paths;
}

void requireNewSideOutputs(const ImageOptions& options, const std::vector<fs::path>& inputs) {
    std::vector<fs::path> paths;
    if (!options.telemetry.empty()) {
        paths.push_back(options.telemetry);
    }
    for (const fs::path& in : inputs) {
        if (!options.writeAux.empty()) {
            paths.push_back(options.writeAux / (in.stem().string() + ".aux.exr"));
        }
    }
    requireNew(paths);
}

} // namespace photopic::cli
