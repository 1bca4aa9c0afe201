#include "OrbitDemo.h"

#include "Commands.h"
#include "DemoFiles.h"
#include "Interrupt.h"
#include "Outputs.h"
#include "Progress.h"
#include "TabletopDemo.h"
#include "TelemetryCsv.h"

#include "common/Raster.h"
#include "gl/Context.h"
#include "gl/TextureIo.h"
#include "io/ImageIO.h"
#include "scenes/orbit/OrbitScene.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

namespace photopic::cli {

namespace fs = std::filesystem;

namespace {

/// Six written frames spread over the run, read back from their PNGs.
Image8 contactSheet(const fs::path& folder, std::size_t written, int every,
                    const std::vector<TelemetrySample>& samples, const std::vector<float>& sunVisibility) {
    std::vector<std::pair<std::string, Image8>> tiles;
    constexpr std::size_t kTiles = 6;
    for (std::size_t k = 0; k < kTiles; ++k) {
        const std::size_t w = written <= 1 ? 0 : k * (written - 1) / (kTiles - 1);
        const std::size_t i = std::min(w * std::size_t(every), samples.size() - 1);
        const TelemetrySample& s = samples[i];
        tiles.emplace_back(fmt::format("t={:.1f}s sun {:.0f}% {:+.2f} EV", s.timeS, 100.0f * sunVisibility[i],
                                       s.appliedLog2),
                           readPng8(demoFramePath(folder, w)));
    }
    return makeContactSheet(tiles, 3, 320);
}

} // namespace

namespace {

/// What the frame loop leaves for the summary files.
struct OrbitRun {
    std::vector<TelemetrySample> samples;
    std::vector<float> sunVisibility; ///< at the ship, 0..1, one per sample
    std::size_t written = 0;          ///< frame PNGs
    int frames = 0;
};

/// Renders every frame through the pipeline, writes every `every`th as PNG and the telemetry CSV.
OrbitRun renderOrbit(const OrbitDemoOptions& options, RunOutputs& outputs) {
    HeadlessContext context(commandContext());
    OrbitScene scene;
    Settings settings = scene.defaultSettings();
    if (!options.preset.empty()) {
        settings.applyLook(presetLook(options.preset));
    }
    Pipeline pipeline({.settings = settings, .keepTelemetryHistory = true});
    scene.resize({options.width, options.height});

    const float dt = 1.0f / options.fps;
    OrbitRun run;
    run.frames = std::max(1, int(std::lround(options.seconds * options.fps)));
    const int every = std::max(1, options.frameEvery);
    const fs::path telemetryPath = options.output / "telemetry.csv";
    TelemetryCsv telemetry(telemetryPath, dt, scene.telemetryColumns());
    run.samples.reserve(std::size_t(run.frames));
    run.sunVisibility.reserve(std::size_t(run.frames));
    // The scene's columns: script_s, sun_visibility.
    const auto addSample = [&](const ExposureTelemetry& t, const std::vector<double>& values) {
        run.samples.push_back({.timeS = float(t.frame) * dt,
                               .measuredLuma = t.frameLuminance,
                               .targetLog2 = t.targetLog2,
                               .appliedLog2 = t.appliedLog2});
        run.sunVisibility.push_back(values.size() > 1 ? float(values[1]) : 1.0f);
    };
    Progress progress("demo --scene orbit", std::size_t(run.frames));
    for (int i = 0; i < run.frames; ++i) {
        throwIfInterrupted();
        const FrameTime time{.dt = dt, .frameIndex = std::uint64_t(i)};
        std::vector<double> values;
        const FrameInputs frame = scene.render(time, pipeline, values);
        const Texture& display = pipeline.execute(frame, time);
        if (i % every == 0) {
            writePng(demoFramePath(options.output, run.written++), readTexture8(display));
            outputs.wroteSequenceItem();
        }
        telemetry.sceneValues(std::uint64_t(i), std::move(values));
        telemetry.take(pipeline, std::uint64_t(i), i + 1 == run.frames, addSample);
        progress.advance();
    }
    telemetry.commit(std::uint64_t(run.frames), pipeline.droppedTelemetry());
    outputs.wrote(telemetryPath);
    return run;
}

void printSummary(const OrbitDemoOptions& options, const OrbitRun& run, const std::string& video) {
    std::printf("orbit: %d frames at %dx%d, %.3g fps, auto exposure -> %s\n", run.frames, options.width,
                options.height, double(options.fps), options.output.string().c_str());
    std::printf("  files: %zu frame PNGs, telemetry.csv, exposure_plot.png, contact_sheet.png, %s\n",
                run.written, video.c_str());
    if (!run.samples.empty()) {
        const auto [low, high] = std::minmax_element(
            run.samples.begin(), run.samples.end(),
            [](const TelemetrySample& a, const TelemetrySample& b) { return a.appliedLog2 < b.appliedLog2; });
        std::printf("  exposure: %+.2f EV (t=%.1f s) .. %+.2f EV (t=%.1f s)\n", double(low->appliedLog2),
                    double(low->timeS), double(high->appliedLog2), double(high->timeS));
    }
}

} // namespace

int runOrbitDemo(const OrbitDemoOptions& options) {
    const auto begin = std::chrono::steady_clock::now();
    // Every output is checked before the first frame; a run that fails takes back what it wrote.
    RunOutputs outputs;
    const DemoFiles files = prepareDemoFiles(outputs, options.output, options.width, options.height,
                                             options.fps, options.seconds);

    const OrbitRun run = renderOrbit(options, outputs);
    const auto rendered = std::chrono::steady_clock::now();
    writePng(files.plot,
             plotExposureTelemetry(
                 run.samples, {"sun visible at the ship (0..1)", {220, 180, 30, 255}, {}, run.sunVisibility},
                 960, 420, "Orbit: into the planet's shadow and out into the sun, auto exposure"));
    outputs.wrote(files.plot);
    if (!run.samples.empty() && run.written > 0) {
        writePng(files.sheet, contactSheet(options.output, run.written, std::max(1, options.frameEvery),
                                           run.samples, run.sunVisibility));
        outputs.wrote(files.sheet);
    }
    const std::string video = encodeDemoVideo(
        outputs, files, double(options.fps) / double(std::max(1, options.frameEvery)), options.video);
    outputs.commit();
    const auto end = std::chrono::steady_clock::now();
    if (!statusLines()) {
        return kOk; // -q: errors only
    }
    printSummary(options, run, video);
    std::printf("  time: %.1f s rendering, %.1f s in all\n",
                std::chrono::duration<double>(rendered - begin).count(),
                std::chrono::duration<double>(end - begin).count());
    return kOk;
}

} // namespace photopic::cli
