// One headless GL context for every benchmark in the binary (two contexts would each need to be current for
// their own objects), then Google Benchmark's usual main.

#include "gl/Context.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <memory>

int main(int argc, char** argv) {
    std::unique_ptr<photopic::HeadlessContext> context;
    try {
        context = std::make_unique<photopic::HeadlessContext>();
        std::printf("GL: %s (%s)\n", context->info().renderer.c_str(), context->info().platform.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photopic_bench: no OpenGL 4.5 context: %s\n", e.what());
        return 1;
    }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
        return 1;
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
