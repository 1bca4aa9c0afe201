// `photopic demo`: the tabletop walk through the GPU pipeline, exposure driven by `subject` metering (the
// pipeline's probe under the player token). The eye's lag, made visible.

#include "TabletopDemo.h"

#include "Commands.h"
#include "DemoFiles.h"
#include "Interrupt.h"
#include "Outputs.h"
#include "Progress.h"
#include "TelemetryCsv.h"

#include "common/Raster.h"
#include "core/Log.h"
#include "gl/Context.h"
#include "gl/TextureIo.h"
#include "io/ImageIO.h"
#include "scenes/tabletop/TabletopScene.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

namespace photopic::cli {

namespace fs = std::filesystem;

Image8 plotExposureTelemetry(const std::vector<TelemetrySample>& samples, PlotSeries extra, int width,
                             int height, const std::string& title) {
    PlotSeries luma{"measured luma (log2)", {120, 120, 120, 255}, {}, {}};
    PlotSeries target{"target EV", {30, 110, 220, 255}, {}, {}};
    PlotSeries applied{"applied EV", {220, 60, 30, 255}, {}, {}};
    for (const TelemetrySample& s : samples) {
        luma.x.push_back(s.timeS);
        luma.y.push_back(s.measuredLuma > 0.0f ? std::log2(s.measuredLuma)
                                               : std::numeric_limits<float>::quiet_NaN());
        target.y.push_back(s.targetLog2);
        applied.y.push_back(s.appliedLog2);
    }
    target.x = luma.x;
    applied.x = luma.x;
    extra.x = luma.x;
    return plotLines({luma, target, applied, extra}, width, height, title, "time (s)");
}

std::vector<std::size_t> keyFrameIndices(const std::vector<Transition>& transitions, std::size_t frameCount) {
    std::vector<std::size_t> frames;
    for (const Transition& t : transitions) {
        frames.push_back(t.crossingIndex > 0 ? t.crossingIndex - 1 : 0);
        frames.push_back(t.startIndex);
        if (t.settled) {
            frames.push_back(t.settledIndex);
        }
    }
    std::erase_if(frames, [&](std::size_t f) { return f >= frameCount; });
    std::sort(frames.begin(), frames.end());
    frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
    return frames;
}

namespace {

/// Mean of the display image's sRGB-encoded RGB (0..255): how bright the frame looks.
double meanDisplay(const Image8& image) {
    double sum = 0.0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        sum += double(image.rgba[i]) + double(image.rgba[i + 1]) + double(image.rgba[i + 2]);
    }
    return image.rgba.empty() ? 0.0 : sum / (3.0 * double(image.rgba.size() / 4));
}

/// The contact sheet's tiles: each key frame, or with --every N the written frame at or before it (only
/// those are on disk; frames are never kept in memory), read back from its PNG.
Image8 contactSheet(const fs::path& folder, const std::vector<std::size_t>& keyFrames, int every,
                    const std::vector<TelemetrySample>& samples) {
    std::vector<std::size_t> shown;
    for (std::size_t f : keyFrames) {
        const std::size_t written = f - f % std::size_t(every);
        if (shown.empty() || shown.back() != written) {
            shown.push_back(written);
        }
    }
    std::vector<std::pair<std::string, Image8>> tiles;
    for (std::size_t f : shown) {
        tiles.emplace_back(fmt::format("t={:.2f}s {:+.2f} EV (target {:+.2f})", samples[f].timeS,
                                       samples[f].appliedLog2, samples[f].targetLog2),
                           readPng8(demoFramePath(folder, f / std::size_t(every))));
    }
    return makeContactSheet(tiles, 3, 320);
}

/// What the walk's frames leave for the plot, the contact sheet and the summary: per frame only what they
/// need (24 bytes and a brightness); the frames themselves go to disk.
struct WalkRecord {
    std::vector<TelemetrySample> samples;
    std::vector<double> brightness; ///< mean sRGB of each frame's display image
    AutoExposureSettings autoExposure;
    int frames = 0;
    int every = 1;
};

/// Renders the walk through the pipeline (subject metering on the GPU), writing its frame PNGs and
/// telemetry.csv into `outputs`.
WalkRecord renderWalk(const TabletopWalkOptions& options, const std::optional<Settings>& look,
                      RunOutputs& outputs, Progress& progress) {
    HeadlessContext context(commandContext());
    TabletopScene scene;
    Settings settings = scene.defaultSettings(); // subject metering, the eye-lag defaults
    if (look) {
        settings.applyLook(*look);
    }
    WalkRecord record;
    record.autoExposure = settings.autoExposure;
    Pipeline pipeline({.settings = settings, .keepTelemetryHistory = true});
    scene.resize({options.width, options.height});

    const float dt = 1.0f / options.fps;
    const int frames = record.frames = std::max(1, int(std::lround(options.seconds * options.fps)));
    const int every = record.every = std::max(1, options.frameEvery);
    const fs::path telemetryPath = options.output / "telemetry.csv";
    TelemetryCsv telemetry(telemetryPath, dt, scene.telemetryColumns());
    record.samples.reserve(std::size_t(frames));
    record.brightness.reserve(std::size_t(frames));
    // The scene's columns: subject, world_x, world_y, screen_u, screen_v, outdoors.
    const auto addSample = [&](const ExposureTelemetry& t, const std::vector<double>& values) {
        record.samples.push_back({float(t.frame) * dt, t.frameLuminance, t.targetLog2, t.appliedLog2,
                                  values.size() > 5 ? float(values[5]) : 0.0f});
    };
    for (int i = 0; i < frames; ++i) {
        throwIfInterrupted();
        const FrameTime time{.dt = dt, .frameIndex = std::uint64_t(i)};
        std::vector<double> values;
        // The scene registers its tokens with the pipeline; exposure follows the player on the GPU.
        const FrameInputs frame = scene.render(time, pipeline, values);
        const Image8 display = readTexture8(pipeline.execute(frame, time));
        if (i % every == 0) {
            writePng(demoFramePath(options.output, std::size_t(i / every)), display);
            outputs.wroteSequenceItem();
            logDebug("frame {} -> {}", i, demoFramePath(options.output, std::size_t(i / every)).string());
        }
        record.brightness.push_back(meanDisplay(display));
        telemetry.sceneValues(std::uint64_t(i), std::move(values));
        telemetry.take(pipeline, std::uint64_t(i), i + 1 == frames, addSample);
        progress.advance();
    }
    telemetry.commit(std::uint64_t(frames), pipeline.droppedTelemetry());
    outputs.wrote(telemetryPath);
    return record;
}

/// The exposure plot and the contact sheet of the transitions' key frames.
void writeWalkImages(const TabletopWalkOptions& options, const DemoFiles& files, const WalkRecord& record,
                     const std::vector<Transition>& transitions, RunOutputs& outputs) {
    PlotSeries outdoors{"outdoors (0..1)", {40, 160, 60, 255}, {}, {}};
    for (const TelemetrySample& s : record.samples) {
        outdoors.y.push_back(s.outdoors);
    }
    writePng(files.plot,
             plotExposureTelemetry(record.samples, std::move(outdoors), 960, 420,
                                   "Tabletop walk: light under the token and the eye's exposure"));
    outputs.wrote(files.plot);
    const std::vector<std::size_t> keyFrames = keyFrameIndices(transitions, record.samples.size());
    if (!keyFrames.empty()) {
        writePng(files.sheet, contactSheet(options.output, keyFrames, record.every, record.samples));
        outputs.wrote(files.sheet);
    }
}

/// What was written, each transition's summary and the times.
void printWalkSummary(const TabletopWalkOptions& options, const WalkRecord& record,
                      const std::vector<Transition>& transitions, const std::string& video, double renderS,
                      double totalS) {
    std::printf("tabletop walk: %d frames at %dx%d, %.3g fps, subject metering on the GPU -> %s\n",
                record.frames, options.width, options.height, double(options.fps),
                options.output.string().c_str());
    std::printf("  files: %d frame PNGs, telemetry.csv, exposure_plot.png, contact_sheet.png, %s\n",
                (record.frames + record.every - 1) / record.every, video.c_str());
    for (const Transition& t : transitions) {
        std::printf("  %s\n", describeTransition(t).c_str());
        if (t.settled) {
            std::printf("    frame brightness (mean sRGB): %.1f at the start -> %.1f settled\n",
                        record.brightness[t.startIndex], record.brightness[t.settledIndex]);
        }
    }
    if (transitions.empty()) {
        std::printf("  no indoor/outdoor crossing in %.3g s\n", double(options.seconds));
    }
    std::printf("  time: %.1f s rendering, %.1f s in all\n", renderS, totalS);
}

} // namespace

int runTabletopWalk(const TabletopWalkOptions& options) {
    const auto begin = std::chrono::steady_clock::now();
    const std::optional<Settings> look =
        options.preset.empty() ? std::nullopt : std::optional<Settings>(presetLook(options.preset));
    // Every output is checked before the first frame; a run that fails takes back what it wrote.
    RunOutputs outputs;
    const DemoFiles files = prepareDemoFiles(outputs, options.output, options.width, options.height,
                                             options.fps, options.seconds);
    const int frames = std::max(1, int(std::lround(options.seconds * options.fps)));
    Progress progress("demo", std::size_t(frames));
    const WalkRecord record = renderWalk(options, look, outputs, progress);
    const auto rendered = std::chrono::steady_clock::now();
    const std::vector<Transition> transitions = analyzeTransitions(record.samples, record.autoExposure);
    writeWalkImages(options, files, record, transitions, outputs);
    if (options.video) {
        progress.note(fmt::format("encoding {} with ffmpeg", files.video.filename().string()));
    }
    const std::string video =
        encodeDemoVideo(outputs, files, double(options.fps) / double(record.every), options.video);
    if (options.video) {
        progress.clear();
    }
    outputs.commit();
    const auto end = std::chrono::steady_clock::now();
    if (!statusLines()) {
        return kOk; // -q: errors only
    }
    printWalkSummary(options, record, transitions, video,
                     std::chrono::duration<double>(rendered - begin).count(),
                     std::chrono::duration<double>(end - begin).count());
    return kOk;
}

} // namespace photopic::cli
