// GPU time of auto exposure at 1920x1080: metering (one read of the image: histogram, min/max, partial log
// sums; plus the reduction) and the one-invocation adaptation pass, measured with GPU timestamp queries
// (gl/GpuTimers.h). Warm-up frames first; every run checks the metered luminance of a known image (half the
// pixels at 0.05, half at 0.8: geometric mean 0.2).

#include "core/Log.h"
#include "gl/GpuTimers.h"
#include "gl/TextureIo.h"
#include "passes/Bindings.h"
#include "passes/exposure/ExposurePass.h"
#include "passes/metering/MeteringPass.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

namespace {

using namespace photopic;

constexpr int kWidth = 1920;
constexpr int kHeight = 1080;
constexpr int kWarmUpFrames = 3;
constexpr float kExpectedLuminance = 0.2f; // sqrt(0.05 * 0.8)

ImageF knownImage() {
    ImageF image(kWidth, kHeight, 1.0f);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const float v = (x + y) % 2 == 0 ? 0.05f : 0.8f;
            float* p = image.at(x, y);
            p[0] = p[1] = p[2] = v;
        }
    }
    return image;
}

/// The GPU time of every pass of the frames the timers hold (blocks: benchmark only).
double drainedMs(GpuTimers& timers) {
    double ms = 0.0;
    for (const auto& passes : timers.drain()) {
        for (const auto& p : passes) {
            ms += p.gpuMs;
        }
    }
    return ms;
}

void autoExposure(benchmark::State& state, MeteringMode mode) {
    const Texture input = makeTexture(knownImage(), "bench input");
    AutoExposureSettings settings;
    settings.enabled = true;
    settings.metering = mode;
    MeteringPass metering;
    metering.resize(input.extent());
    ExposurePass exposure;
    const GpuExposureState initial;
    Buffer stateBuffer({.size = sizeof(initial),
                        .flags = GL_DYNAMIC_STORAGE_BIT,
                        .data = &initial,
                        .debugName = "bench state"});
    GpuTimers timers;
    const MeteringPass::Weights weights =
        mode == MeteringMode::Histogram ? MeteringPass::Weights::None : MeteringPass::Weights::Average;
    const auto frame = [&](GpuTimers* t) {
        const auto out = metering.execute({.scene = &input,
                                           .settings = &settings,
                                           .histogram = mode == MeteringMode::Histogram,
                                           .weights = weights,
                                           .timers = t});
        exposure.execute({.histogram = out.histogram,
                          .metering = out.metering,
                          .exposureState = &stateBuffer,
                          .settings = &settings,
                          .metered = true,
                          .histogramBuilt = mode == MeteringMode::Histogram,
                          .dt = 1.0f / 60.0f,
                          .timers = t});
    };
    for (int i = 0; i < kWarmUpFrames; ++i) {
        frame(nullptr);
    }
    glFinish();

    double totalMs = 0.0;
    for (auto _ : state) {
        timers.beginFrame();
        frame(&timers);
        timers.endFrame();
        const double ms = drainedMs(timers);
        totalMs += ms;
        state.SetIterationTime(ms * 1e-3);
    }
    GpuExposureState result;
    glGetNamedBufferSubData(stateBuffer.id(), 0, sizeof(result), &result);
    // Histogram metering reads bin centres: within a bin width (28 / 254 EV) of the true mean.
    const float tolerance = mode == MeteringMode::Histogram ? 0.11f : 1e-3f;
    if (!(std::abs(std::log2(result.frameLuminance / kExpectedLuminance)) <= tolerance)) {
        state.SkipWithError("metered luminance of the known image is wrong");
    }
    state.counters["gpu_ms"] = benchmark::Counter(totalMs / double(state.iterations()));
    state.counters["metered"] = result.frameLuminance;
    state.counters["Mpix/s"] =
        benchmark::Counter(double(kWidth) * kHeight * double(state.iterations()) / 1e6 / (totalMs * 1e-3));
}

} // namespace

BENCHMARK_CAPTURE(autoExposure, average_1080p, photopic::MeteringMode::Average)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(20);
BENCHMARK_CAPTURE(autoExposure, histogram_1080p, photopic::MeteringMode::Histogram)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(20);
