// The full pipeline at 1920x1080 on the synthetic HDR frame, timed with GPU timer queries (the sum of every
// pass's GPU time per frame, manual time), after a warm-up; the output is checked so a broken pipeline cannot
// post a fast time.

#include "core/Image.h"
#include "gl/TextureIo.h"
#include "pipeline/Pipeline.h"
#include "scenes/SyntheticHdr.h"

#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>

namespace {

using namespace photopic;

void runPipeline(benchmark::State& state, Quality quality) {
    Settings settings;
    settings.quality = quality;
    Pipeline pipeline({.settings = settings});
    const ImageF image = makeSyntheticHdr(1920, 1080);
    const Texture input = makeTexture(image, "bench input");
    std::uint64_t frame = 0;
    for (int i = 0; i < 3; ++i) {
        pipeline.execute({.color = &input}, {.frameIndex = frame++});
        pipeline.timers().drain();
    }
    std::map<std::string, double> passMs;
    int frames = 0;
    const Texture* output = nullptr;
    for (auto _ : state) {
        output = &pipeline.execute({.color = &input}, {.frameIndex = frame++});
        double total = 0;
        for (const auto& passes : pipeline.timers().drain()) {
            for (const PassTiming& p : passes) {
                total += p.gpuMs;
                passMs[p.name] += p.gpuMs;
            }
            ++frames;
        }
        state.SetIterationTime(total * 1e-3);
    }
    // The output must be a plausible image: not black, not white, every pixel opaque.
    const Image8 out = readTexture8(*output);
    double sum = 0;
    for (std::size_t i = 0; i < out.rgba.size(); i += 4) {
        sum += out.rgba[i + 1];
        if (out.rgba[i + 3] != 255) {
            state.SkipWithError("output has a non-opaque pixel");
            return;
        }
    }
    const double mean = sum / double(out.rgba.size() / 4);
    if (mean < 10.0 || mean > 245.0) {
        state.SkipWithError("output is implausibly dark or bright");
        return;
    }
    for (const auto& [name, ms] : passMs) {
        state.counters[name + " ms"] = frames ? ms / frames : 0.0;
    }
}

void BM_Pipeline1080pHigh(benchmark::State& state) {
    runPipeline(state, Quality::High);
}
void BM_Pipeline1080pLow(benchmark::State& state) {
    runPipeline(state, Quality::Low);
}

// llvmpipe renders a 1080p frame in tens to hundreds of milliseconds: a fixed count keeps the run short.
BENCHMARK(BM_Pipeline1080pHigh)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(20);
BENCHMARK(BM_Pipeline1080pLow)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(20);

} // namespace
