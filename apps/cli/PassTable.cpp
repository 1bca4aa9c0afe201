// The bench's per-pass table (PassTable.h).
#include "PassTable.h"

#include <cstdio>

namespace photopic::cli {

PassTable printPassTable(const BenchOptions& options, PassSamples& samples, const CopyReference& copy) {
    std::printf("%-36s %12s %12s %10s %8s%s\n", "pass", "median ms", "MB moved", "GB/s", "of copy",
                options.sync ? "      wall ms" : "");
    const double copyGbps = copy.gbPerSecond();
    const auto fractionOf = [copyGbps](double gbps) { return copyGbps > 0 ? gbps / copyGbps : 0.0; };
    PassTable table{.passes = nlohmann::json::array()};
    double& totalBytes = table.totalBytes;
    for (const auto& name : samples.order) {
        const double ms = median(samples.times[name]);
        const double b = samples.bytes[name];
        const double gbps = ms > 0 ? b / (ms * 1e6) : 0.0;
        totalBytes += b;
        nlohmann::json row = {{"name", name},
                              {"medianGpuMs", ms},
                              {"bytesMoved", b},
                              {"gbPerSecond", gbps},
                              {"fractionOfCopy", fractionOf(gbps)},
                              {"samples", samples.times[name].size()}};
        std::printf("%-36s %12.3f %12.2f %10.2f %7.0f%%", name.c_str(), ms, b / 1e6, gbps,
                    100.0 * fractionOf(gbps));
        if (options.sync) {
            const double wall = median(samples.walls[name]);
            std::printf(" %12.3f", wall);
            row["medianWallMs"] = wall;
        }
        std::printf("\n");
        table.passes.push_back(row);
    }
    const double totalMs = table.totalMs = median(samples.totals);
    const double totalWallMs = table.totalWallMs = median(samples.wallTotals);
    const double totalGbps = totalMs > 0 ? totalBytes / (totalMs * 1e6) : 0.0;
    std::printf("%-36s %12.3f %12.2f %10.2f %7.0f%%", "total (median of frame sums)", totalMs,
                totalBytes / 1e6, totalGbps, 100.0 * fractionOf(totalGbps));
    if (options.sync) {
        std::printf(" %12.3f", totalWallMs);
    }
    std::printf("\n");
    return table;
}

} // namespace photopic::cli
