// `photopic scene NAME`: renders a built-in scene's frames through the pipeline, with per-frame telemetry.

#include "Commands.h"
#include "Outputs.h"
#include "TelemetryCsv.h"

#include "core/settings/SettingsJson.h"
#include "gl/Context.h"
#include "gl/TextureIo.h"
#include "io/ImageIO.h"
#include "scenes/Scene.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <tuple>

namespace photopic::cli {

namespace fs = std::filesystem;

namespace {

/// VmRSS from /proc/self/status, kB; -1 where there is none (not Linux).
long residentKilobytes() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.starts_with("VmRSS:")) {
            return std::strtol(line.c_str() + 6, nullptr, 10);
        }
    }
    return -1;
}

} // namespace

Extent parseSize(const std::string& text, int minSide) {
    const std::optional<Extent> size = parseExtent(text, minSide);
    if (!size) {
        throw InputError(
            fmt::format("size '{}' is not WIDTHxHEIGHT with each side in [{}, 16384]", text, minSide));
    }
    return *size;
}

int runScene(const SceneOptions& options) {
    const Extent size = parseSize(options.size);
    if (options.frames < 1) {
        throw InputError(fmt::format("--frames {} must be at least 1", options.frames));
    }
    HeadlessContext context;
    std::unique_ptr<Scene> scene;
    try {
        scene = makeScene(options.name);
    } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
    }

    // The canvas scene's file flags are shorthands for its settings, applied before the --set overrides.
    std::vector<std::string> overrides;
    for (const auto& [flag, key, value] : {std::tuple{"--canvas", "colour", options.canvasColour},
                                           std::tuple{"--material", "material", options.canvasMaterial},
                                           std::tuple{"--motion", "motion", options.motion}}) {
        if (!value.empty()) {
            if (scene->name() != "canvas") {
                throw InputError(
                    fmt::format("{} is an option of the canvas scene, not of '{}'", flag, scene->name()));
            }
            // A JSON string must be UTF-8; a file name need not be. Say so rather than let dump() throw.
            if (const auto bad = invalidUtf8Offset(value)) {
                throw InputError(fmt::format("{}: the file name is not valid UTF-8 (byte {})", flag, *bad));
            }
            overrides.push_back(fmt::format("canvas.{}={}", key, nlohmann::json(value).dump()));
        }
    }
    overrides.insert(overrides.end(), options.settings.overrides.begin(), options.settings.overrides.end());
    const SplitOverrides split = splitSceneOverrides(scene->name(), overrides);
    applySceneOverrides(*scene, split.scene);
    // Post settings: the scene's defaults, then --settings, the shorthands and every --set that is not the
    // scene's.
    SettingsSources post = options.settings;
    post.overrides = split.post;
    const Settings resolved = resolveSettings(post, scene->defaultSettings());
    // The scene reads its input files here, before any output exists: a bad one is bad input (exit 2).
    try {
        scene->resize(size);
    } catch (const SceneInputError& e) {
        throw InputError(e.what());
    }

    const fs::path outDir =
        options.output.empty() ? fs::path("out") / ("scene-" + options.name) : options.output;
    // Every output is checked before the first frame; a run that fails takes back what it wrote.
    RunOutputs outputs;
    outputs.makeFolder(outDir);
    const auto framePath = [&](std::size_t index) {
        return outDir / fmt::format("frame_{:04d}.{}", index, options.format);
    };
    RunOutputs::requireFile(framePath(0));
    outputs.sequence(framePath);
    const float dt = 1.0f / options.fps;
    const fs::path telemetryPath = outDir / "telemetry.csv";
    TelemetryCsv telemetry(telemetryPath, dt, scene->telemetryColumns());

    Pipeline pipeline({.settings = resolved, .forceLdr = options.forceLdr, .keepTelemetryHistory = true});
    const int every = std::max(1, options.every);
    for (int i = 0; i < options.frames; ++i) {
        const FrameTime time{.dt = dt, .frameIndex = std::uint64_t(i)};
        std::vector<double> values;
        const Texture& color = scene->render(time, pipeline, values);
        const Texture& display = pipeline.execute({.color = &color}, time);
        if (i % every == 0) {
            const fs::path frame = framePath(std::size_t(i / every));
            if (options.format == "exr") {
                writeExr(frame, readTextureF(pipeline.sceneReferred()));
            } else {
                writePng(frame, readTexture8(display));
            }
            outputs.wroteSequenceItem();
        }
        telemetry.sceneValues(std::uint64_t(i), std::move(values));
        telemetry.take(pipeline, std::uint64_t(i), i + 1 == options.frames);
        if (options.reportRss && (i == 0 || i + 1 == options.frames)) {
            std::printf("rss after frame %d: %ld kB\n", i + 1, residentKilobytes());
        }
    }
    telemetry.commit(std::uint64_t(options.frames), pipeline.droppedTelemetry());
    outputs.wrote(telemetryPath);
    outputs.commit();
    std::printf("%s: %d frames at %dx%d, %.3g fps -> %s (frames + telemetry.csv)\n", options.name.c_str(),
                options.frames, size.width, size.height, double(options.fps), outDir.string().c_str());
    return kOk;
}

} // namespace photopic::cli
