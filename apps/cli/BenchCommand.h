#pragma once
// `photopic bench`: per-pass GPU timings of the pipeline over N frames (PipelineBench.h); `--scene canvas`:
// the canvas scene's tiled against full-screen shading (CanvasBench.cpp).

#include "Bench.h"
#include "Command.h"

namespace photopic::cli {

class BenchCommand final : public Command {
public:
    explicit BenchCommand(CLI::App& parent);
    int run() override;

private:
    /// --scene's checks, then the canvas benchmark.
    int runCanvas() const;

    BenchOptions mOptions;
};

} // namespace photopic::cli
