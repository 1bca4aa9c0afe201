#pragma once
// The bench's per-pass table: the timings of the measured frames (PassSamples), printed with the bytes each
// pass moves and its bandwidth against the reference copy's (printPassTable).

#include "Bench.h"
#include "CopyReference.h"

#include "gl/GpuTimers.h"

#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

namespace photopic::cli {

/// Per-pass timings over the measured frames, passes in the order they first ran.
struct PassSamples {
    std::vector<std::string> order;
    std::map<std::string, std::vector<double>> times; ///< GPU ms per frame
    std::map<std::string, std::vector<double>> walls; ///< wall ms per frame, where measured (--sync)
    std::map<std::string, double> bytes;              ///< bytes moved per frame
    std::vector<double> totals, wallTotals;           ///< per-frame sums

    void add(const std::vector<std::vector<PassTiming>>& frames) {
        for (const auto& passes : frames) {
            double total = 0, wallTotal = 0;
            for (const PassTiming& p : passes) {
                if (!times.contains(p.name)) {
                    order.push_back(p.name);
                }
                times[p.name].push_back(p.gpuMs);
                if (p.wallMs >= 0) {
                    walls[p.name].push_back(p.wallMs);
                    wallTotal += p.wallMs;
                }
                bytes[p.name] = p.bytesMoved;
                total += p.gpuMs;
            }
            totals.push_back(total);
            wallTotals.push_back(wallTotal);
        }
    }
};

struct PassTable {
    nlohmann::json passes;
    double totalBytes = 0, totalMs = 0, totalWallMs = 0;
};

/// The per-pass table on stdout: median GPU time, bytes moved, bandwidth and its fraction of the same run's
/// copy (and wall time with --sync).
PassTable printPassTable(const BenchOptions& options, PassSamples& samples, const CopyReference& copy);

} // namespace photopic::cli
