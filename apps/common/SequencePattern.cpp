#include "common/SequencePattern.h"

#include <algorithm>
#include <charconv>
#include <stdexcept>
#include <utility>

namespace photopic {

namespace {

constexpr int kMaxDigits = 18; // every 18-digit number fits std::int64_t

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

std::string inQuotes(std::string_view text) {
    return "\"" + std::string(text) + "\"";
}

/// The token at `i` (a `%` or the first of a run of `#` or `@`): its width and length, or nullopt for `%%`.
struct Token {
    int width = 1;
    std::size_t length = 0;
};

std::optional<Token> tokenAt(std::string_view name, std::size_t i) {
    if (name[i] == '#' || name[i] == '@') {
        std::size_t end = i;
        while (end < name.size() && name[end] == name[i]) {
            ++end;
        }
        if (end - i > std::size_t(kMaxDigits)) {
            throw std::invalid_argument(inQuotes(name) + ": more than 18 digits of frame number");
        }
        return Token{.width = int(end - i), .length = end - i};
    }
    // printf: "%d", or "%0Nd" (zero padded to N digits).
    std::size_t end = i + 1;
    int width = 1;
    if (end < name.size() && name[end] == '0') {
        std::size_t digitsEnd = end + 1;
        while (digitsEnd < name.size() && isDigit(name[digitsEnd])) {
            ++digitsEnd;
        }
        const auto [ptr, ec] = std::from_chars(name.data() + end + 1, name.data() + digitsEnd, width);
        if (ec != std::errc() || width < 1 || width > kMaxDigits) {
            throw std::invalid_argument(inQuotes(name) + ": \"%0Nd\" needs N in [1, 18]");
        }
        (void)ptr;
        end = digitsEnd;
    }
    if (end < name.size() && name[end] == 'd') {
        return Token{.width = width, .length = end + 1 - i};
    }
    throw std::invalid_argument(inQuotes(name) +
                                ": a '%' is a frame number only as %d or %0Nd (%% is a '%')");
}

} // namespace

std::string FramePattern::name(std::int64_t frame) const {
    std::string digits = std::to_string(frame);
    if (digits.size() < std::size_t(width)) {
        digits.insert(0, std::size_t(width) - digits.size(), '0');
    }
    return prefix + digits + suffix;
}

std::optional<std::int64_t> FramePattern::match(std::string_view fileName) const {
    if (fileName.size() <= prefix.size() + suffix.size() || !fileName.starts_with(prefix) ||
        !fileName.ends_with(suffix)) {
        return std::nullopt;
    }
    const std::string_view digits =
        fileName.substr(prefix.size(), fileName.size() - prefix.size() - suffix.size());
    if (digits.size() > std::size_t(kMaxDigits) || !std::all_of(digits.begin(), digits.end(), isDigit)) {
        return std::nullopt;
    }
    std::int64_t frame = 0;
    std::from_chars(digits.data(), digits.data() + digits.size(), frame);
    if (name(frame) != fileName) { // "f12.exr" under %04d, or an extra leading zero
        return std::nullopt;
    }
    return frame;
}

std::optional<FramePattern> parseFramePattern(std::string_view fileName) {
    std::optional<FramePattern> pattern;
    std::string literal;
    for (std::size_t i = 0; i < fileName.size();) {
        const char c = fileName[i];
        if (c == '%' && i + 1 < fileName.size() && fileName[i + 1] == '%') {
            literal += '%';
            i += 2;
            continue;
        }
        if (c != '%' && c != '#' && c != '@') {
            literal += c;
            ++i;
            continue;
        }
        const std::optional<Token> token = tokenAt(fileName, i);
        if (pattern) {
            throw std::invalid_argument(inQuotes(fileName) + ": more than one frame number in a name");
        }
        pattern = FramePattern{.prefix = std::exchange(literal, {}), .suffix = {}, .width = token->width};
        i += token->length;
    }
    if (pattern) {
        pattern->suffix = literal;
    }
    return pattern;
}

FrameRange parseFrameRange(std::string_view text) {
    const auto bad = [&] {
        return std::invalid_argument("frame range " + inQuotes(text) +
                                     ": expected FIRST-LAST (1001-1100) or one frame, frames >= 0");
    };
    const std::size_t dash = text.find('-');
    const std::string_view first = text.substr(0, dash);
    const std::string_view last = dash == std::string_view::npos ? first : text.substr(dash + 1);
    FrameRange range;
    for (auto [part, value] : {std::pair{first, &range.first}, std::pair{last, &range.last}}) {
        if (part.empty() || part.size() > std::size_t(kMaxDigits) ||
            !std::all_of(part.begin(), part.end(), isDigit)) {
            throw bad();
        }
        std::from_chars(part.data(), part.data() + part.size(), *value);
    }
    if (range.last < range.first) {
        throw std::invalid_argument("frame range " + inQuotes(text) + ": the last frame is before the first");
    }
    return range;
}

std::vector<SequenceFrame> expandSequence(const std::filesystem::path& pattern,
                                          const std::vector<std::string>& folderNames,
                                          const FrameSelection& selection) {
    const std::optional<FramePattern> name = parseFramePattern(pattern.filename().string());
    if (!name) {
        throw std::invalid_argument(inQuotes(pattern.string()) + " holds no frame number (%04d, ####, @)");
    }
    const std::filesystem::path folder = pattern.parent_path();
    std::vector<std::int64_t> found;
    for (const std::string& n : folderNames) {
        if (const std::optional<std::int64_t> frame = name->match(n)) {
            found.push_back(*frame);
        }
    }
    std::sort(found.begin(), found.end());
    std::vector<SequenceFrame> frames;
    if (selection.range) {
        std::size_t k = 0;
        for (std::int64_t f = selection.range->first; f <= selection.range->last; ++f) {
            while (k < found.size() && found[k] < f) {
                ++k;
            }
            if (k == found.size() || found[k] != f) {
                throw std::invalid_argument("frame " + std::to_string(f) + " of " +
                                            inQuotes(pattern.string()) +
                                            " is missing: " + inQuotes((folder / name->name(f)).string()));
            }
            frames.push_back({folder / name->name(f), f});
        }
        return frames;
    }
    for (const std::int64_t f : found) {
        if (!selection.startFrom || f >= *selection.startFrom) {
            frames.push_back({folder / name->name(f), f});
        }
    }
    if (frames.empty()) {
        throw std::invalid_argument(
            "no file matches " + inQuotes(pattern.string()) +
            (selection.startFrom ? " from frame " + std::to_string(*selection.startFrom) + " on" : ""));
    }
    return frames;
}

} // namespace photopic
