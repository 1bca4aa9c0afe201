// `photopic scene NAME`: renders a built-in scene's frames through the pipeline, with per-frame telemetry.

#include "Commands.h"

#include "core/settings/SettingsJson.h"
#include "gl/Context.h"
#include "gl/TextureIo.h"
#include "io/ImageIO.h"
#include "scenes/Scene.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <tuple>

namespace photopic::cli {

namespace fs = std::filesystem;

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
    for (const auto& [flag, key, value] : {std::tuple{"--canvas", "colour", options.canvasColor},
                                           std::tuple{"--material", "material", options.canvasMaterial},
                                           std::tuple{"--motion", "motion", options.motion}}) {
        if (!value.empty()) {
            if (scene->name() != "canvas") {
                throw InputError(
                    fmt::format("{} is an option of the canvas scene, not of '{}'", flag, scene->name()));
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
    std::error_code ec;
    fs::create_directories(outDir, ec);
    if (ec) {
        throw std::runtime_error(
            fmt::format("cannot create output folder {}: {}", outDir.string(), ec.message()));
    }

    Pipeline pipeline({.settings = resolved, .forceLdr = options.forceLdr, .keepTelemetryHistory = true});
    const std::vector<std::string> sceneColumns = scene->telemetryColumns();
    std::vector<std::vector<double>> sceneValues(std::size_t(options.frames));

    const float dt = 1.0f / options.fps;
    for (int i = 0; i < options.frames; ++i) {
        const FrameTime time{.dt = dt, .frameIndex = std::uint64_t(i)};
        const Texture& color = scene->render(time, pipeline, sceneValues[std::size_t(i)]);
        const Texture& display = pipeline.execute({.color = &color}, time);
        const fs::path frame = outDir / fmt::format("frame_{:04d}.{}", i, options.format);
        if (options.format == "exr") {
            writeExr(frame, readTextureF(pipeline.sceneReferred()));
        } else {
            writePng(frame, readTexture8(display));
        }
    }
    const std::vector<ExposureTelemetry> rows = pipeline.drainTelemetry();
    if (rows.size() != std::size_t(options.frames)) {
        throw std::runtime_error(fmt::format("telemetry: {} of {} frames came back ({} dropped)", rows.size(),
                                             options.frames, pipeline.droppedTelemetry()));
    }
    const std::string csv = telemetryCsv(rows, dt, sceneColumns, sceneValues);
    writeTextFile(outDir / "telemetry.csv", csv);
    std::printf("%s: %d frames at %dx%d, %.3g fps -> %s (frames + telemetry.csv)\n", options.name.c_str(),
                options.frames, size.width, size.height, double(options.fps), outDir.string().c_str());
    return kOk;
}

} // namespace photopic::cli
