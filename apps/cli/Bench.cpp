// What the bench's files share (Bench.h): the median, the JSON report's writer.

#include "Bench.h"

#include "io/ImageIO.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace photopic::cli {

namespace fs = std::filesystem;

double median(std::vector<double> values) {
    if (values.empty()) {
        return 0;
    }
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/// Through the io library's atomic writer: flushed to disk and renamed into place, so a reader never sees
/// half a table.
void writeJsonAtomically(const fs::path& path, const nlohmann::json& doc) {
    // A file name need not be UTF-8 (the input's is in the document): its stray bytes become U+FFFD.
    writeTextFile(path, doc.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

} // namespace photopic::cli
