#include "InputSequence.h"

#include "core/Log.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>

namespace photopic::cli {

namespace fs = std::filesystem;

/// Natural order of file names, as a person numbers frames: runs of digits compare by value, so f9 comes
/// before f10 (a plain string sort would run f10 first and the adaptation would see frames out of order).
bool naturalLess(const fs::path& a, const fs::path& b) {
    const std::string x = a.string();
    const std::string y = b.string();
    std::size_t i = 0, j = 0;
    while (i < x.size() && j < y.size()) {
        const bool dx = std::isdigit(static_cast<unsigned char>(x[i])) != 0;
        const bool dy = std::isdigit(static_cast<unsigned char>(y[j])) != 0;
        if (dx && dy) {
            std::size_t ei = i, ej = j;
            while (ei < x.size() && std::isdigit(static_cast<unsigned char>(x[ei])) != 0) {
                ++ei;
            }
            while (ej < y.size() && std::isdigit(static_cast<unsigned char>(y[ej])) != 0) {
                ++ej;
            }
            // Compare by value without overflow: leading zeros off, then length, then digits.
            std::size_t si = i, sj = j;
            while (si + 1 < ei && x[si] == '0') {
                ++si;
            }
            while (sj + 1 < ej && y[sj] == '0') {
                ++sj;
            }
            if (ei - si != ej - sj) {
                return ei - si < ej - sj;
            }
            const int c = x.compare(si, ei - si, y, sj, ej - sj);
            if (c != 0) {
                return c < 0;
            }
            i = ei;
            j = ej;
            continue;
        }
        if (x[i] != y[j]) {
            return x[i] < y[j];
        }
        ++i;
        ++j;
    }
    return x.size() - i < y.size() - j || (x.size() - i == y.size() - j && x < y);
}

namespace {

std::vector<std::string> folderNames(const fs::path& folder) {
    std::vector<std::string> names;
    std::error_code ec;
    for (fs::directory_iterator it(folder.empty() ? fs::path(".") : folder, ec), end; !ec && it != end;
         it.increment(ec)) {
        names.push_back(it->path().filename().string());
    }
    return names;
}

/// --frames and --start-number as a selection of a pattern's frames.
FrameSelection frameSelection(const ImageOptions& options) {
    FrameSelection selection{.range = std::nullopt, .startFrom = options.startNumber};
    if (!options.frames.empty()) {
        try {
            selection.range = parseFrameRange(options.frames);
        } catch (const std::invalid_argument& e) {
            throw InputError(fmt::format("--frames: {}", e.what()));
        }
    }
    return selection;
}

/// Without --frames a pattern takes the frames that exist, so a frame missing in the middle would shift the
/// adaptation in time without a word: say so (a range makes it an error).
void warnAboutGaps(const fs::path& pattern, const std::vector<SequenceFrame>& frames) {
    const FrameGaps gaps = frameGaps(frames, [](const SequenceFrame& f) { return f.frame; });
    if (gaps.firstMissing) {
        logWarning(
            "{}: {} frame(s) missing between {} and {}, the first {}; the sequence runs on without them "
            "(--frames A-B refuses a gap)",
            pattern.string(), gaps.missing, frames.front().frame, frames.back().frame, *gaps.firstMissing);
    }
}

} // namespace

std::vector<InputFile> expandInputs(const ImageOptions& options) {
    const FrameSelection selection = frameSelection(options);
    std::vector<InputFile> files;
    bool anyPattern = false;
    for (const fs::path& in : options.inputs) {
        std::error_code ec;
        std::optional<FramePattern> pattern;
        try {
            // A file that exists is that file; only a file name holds a frame number, never a folder.
            pattern = fs::exists(in, ec) ? std::nullopt : parseFramePattern(in.filename().string());
            if (!pattern) {
                files.push_back({in, std::nullopt});
                continue;
            }
            anyPattern = true;
            std::vector<SequenceFrame> frames = expandSequence(in, folderNames(in.parent_path()), selection);
            warnAboutGaps(in, frames);
            for (SequenceFrame& f : frames) {
                files.push_back({std::move(f.path), f.frame});
            }
        } catch (const std::invalid_argument& e) { // the messages name the pattern or the missing file
            throw InputError(e.what());
        }
    }
    if (!anyPattern && (selection.range || selection.startFrom)) {
        throw InputError("--frames and --start-number pick frames of a pattern input (f%04d.exr, "
                         "f.####.exr, f@.exr); these inputs are files");
    }
    std::stable_sort(files.begin(), files.end(),
                     [](const InputFile& a, const InputFile& b) { return naturalLess(a.path, b.path); });
    return files;
}

namespace {

/// The last run of digits in a file name's stem ("frame_0012b" -> 12), if it has one that fits.
std::optional<std::int64_t> numberInName(const fs::path& path) {
    const std::string stem = path.stem().string();
    const auto last =
        std::find_if(stem.rbegin(), stem.rend(), [](unsigned char c) { return std::isdigit(c); });
    if (last == stem.rend()) {
        return std::nullopt;
    }
    const auto first = std::find_if(last, stem.rend(), [](unsigned char c) { return !std::isdigit(c); });
    const std::string digits(first.base(), last.base());
    if (digits.size() > 18) {
        return std::nullopt;
    }
    return std::stoll(digits);
}

} // namespace

std::map<fs::path, std::int64_t> inputFrameNumbers(const std::vector<InputFile>& inputs) {
    std::map<fs::path, std::int64_t> numbers;
    for (const InputFile& in : inputs) {
        if (const std::optional<std::int64_t> n = in.frame ? in.frame : numberInName(in.path))
            numbers.emplace(in.path, *n);
    }
    return numbers;
}

std::vector<std::int64_t> outputFrameNumbers(const std::vector<InputFile>& inputs) {
    std::vector<std::int64_t> numbers;
    for (const InputFile& in : inputs) {
        const std::optional<std::int64_t> n = in.frame ? in.frame : numberInName(in.path);
        if (!n || std::find(numbers.begin(), numbers.end(), *n) != numbers.end()) {
            numbers.clear();
            for (std::size_t i = 0; i < inputs.size(); ++i) {
                numbers.push_back(std::int64_t(i));
            }
            return numbers;
        }
        numbers.push_back(*n);
    }
    return numbers;
}

namespace {

/// Every frame that exists of the inputs' one frame-numbered pattern; nullopt when the inputs are not one
/// pattern.
std::optional<std::vector<SequenceFrame>> wholeSequence(const ImageOptions& options) {
    std::optional<FramePattern> pattern;
    std::error_code ec;
    if (options.inputs.size() != 1 || fs::exists(options.inputs[0], ec)) {
        return std::nullopt;
    }
    try {
        pattern = parseFramePattern(options.inputs[0].filename().string());
        if (!pattern) {
            return std::nullopt;
        }
        const fs::path& in = options.inputs[0];
        return expandSequence(in, folderNames(in.parent_path()), FrameSelection{});
    } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
    }
}

} // namespace

std::optional<std::int64_t> sequenceStart(const ImageOptions& options) {
    const std::optional<std::vector<SequenceFrame>> all = wholeSequence(options);
    if (!all || all->empty()) {
        return std::nullopt;
    }
    return all->front().frame;
}

std::vector<InputFile> prerollInputs(const ImageOptions& options, const std::vector<InputFile>& chunk,
                                     int count) {
    if (count <= 0 || chunk.empty()) {
        return {};
    }
    std::optional<std::vector<SequenceFrame>> all = wholeSequence(options);
    if (!all || !chunk.front().frame) {
        throw InputError(
            "--preroll renders the frames before the first of a pattern input's frames: give one "
            "frame-numbered pattern (f%04d.exr) with --frames A-B");
    }
    std::vector<InputFile> before;
    for (SequenceFrame& f : *all) {
        if (f.frame < *chunk.front().frame) {
            before.push_back({std::move(f.path), f.frame});
        }
    }
    if (before.size() > std::size_t(count)) {
        before.erase(before.begin(), before.end() - count);
    }
    return before;
}

} // namespace photopic::cli
