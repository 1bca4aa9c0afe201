#pragma once
// The cells of one line of a comma-separated file, as views into the line (no quoting: the project's CSV
// files hold numbers and plain names).

#include <string_view>
#include <vector>

namespace photopic {

/// The cells of `line` split at every comma, untrimmed; an empty line is one empty cell.
inline std::vector<std::string_view> splitCsvLine(std::string_view line) {
    std::vector<std::string_view> cells;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = line.find(',', start);
        cells.push_back(line.substr(start, comma == std::string_view::npos ? comma : comma - start));
        if (comma == std::string_view::npos) {
            return cells;
        }
        start = comma + 1;
    }
}

} // namespace photopic
