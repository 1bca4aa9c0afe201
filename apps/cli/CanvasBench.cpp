// `photopic bench --scene canvas` (Bench.h runCanvasBench): the canvas scene's tiled shading against its
// full-screen shading (scenes/canvas/CanvasRenderer.h).

#include "Bench.h"

#include "Progress.h"

#include "core/Motion.h"
#include "core/settings/SettingsJson.h"
#include "gl/Context.h"
#include "gl/GpuTimers.h"
#include "gl/TextureIo.h"
#include "io/ImageIO.h"
#include "scenes/SceneSettings.h"
#include "scenes/canvas/CanvasScene.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace photopic::cli {

namespace {

/// `--set canvas.key=value` into the canvas scene's settings; any other key is an error (this bench shades
/// the canvas and runs no post-processing).
CanvasSceneSettings canvasBenchSettings(const SettingsSources& sources) {
    if (!sources.file.empty() || !sources.preset.empty() || !sources.tonemap.empty() || sources.exposure ||
        !sources.debugView.empty()) {
        throw InputError(
            "bench --scene canvas times the canvas shading only: post-processing settings do not "
            "apply (use --set canvas.KEY=VALUE)");
    }
    CanvasSceneSettings s;
    s.occupancy = 0.3f; // the benchmark case: 30% of the tiles hold material
    std::vector<SettingsIssue> issues;
    for (const auto& o : sources.overrides) {
        constexpr std::string_view kPrefix = "canvas.";
        if (!std::string_view(o).starts_with(kPrefix)) {
            throw InputError(fmt::format("bench --scene canvas: --set {}: only canvas.KEY=VALUE applies", o));
        }
        auto found = applySceneOverride(s, "canvas", std::string_view(o).substr(kPrefix.size()));
        issues.insert(issues.end(), found.begin(), found.end());
    }
    if (!issues.empty()) {
        throw SettingsError("--set", std::move(issues));
    }
    return s;
}

struct CanvasPathResult {
    CanvasShading shading;
    std::vector<double> gpuMs;  ///< timer queries, frames back to back (N-buffered, never waited on)
    std::vector<double> wallMs; ///< glFinish-bracketed wall time of one frame's shading
};

/// The benchmark's canvas: procedural, or the colour and material files the settings name.
CanvasImages benchCanvas(const CanvasSceneSettings& cs, int width, int height) {
    CanvasImages images = makeProceduralCanvas({.width = width,
                                                .height = height,
                                                .tileSize = cs.tileSize,
                                                .occupancy = cs.occupancy,
                                                .seed = std::uint32_t(cs.seed)});
    try {
        if (!cs.color.empty()) {
            images.color = loadCanvasColor(cs.color, width, height);
        }
        if (!cs.material.empty()) {
            images.material = loadCanvasMaterial(cs.material, width, height);
        }
    } catch (const IoError& e) {
        throw InputError(e.what());
    }
    return images;
}

/// The lamp at `frame` of the scripted tilt, at 30 frames per second.
CanvasLighting benchCanvasLighting(const CanvasSceneSettings& cs, int frame) {
    const ScriptedTilt tilt{
        .period = cs.sweepPeriod, .rollAmplitude = cs.sweepRoll, .pitchAmplitude = cs.sweepPitch};
    const Attitude a = tilt.at(frame / 30.0);
    return CanvasLighting{.light = canvasLightDirection(a.pitch, a.roll),
                          .lightColor = glm::vec3(cs.lightIntensity),
                          .ambient = cs.ambient,
                          .specular = cs.specular,
                          .sparkleExposure = cs.sparkleExposure,
                          .viewDistance = cs.viewDistance};
}

/// Largest |difference| between the tiled and the full-screen image of one frame a quarter into the sweep,
/// where the highlight and the sparkles are on the canvas.
double canvasPathsDifference(CanvasRenderer& renderer, const CanvasSceneSettings& cs) {
    const int checkFrame = int(std::lround(cs.sweepPeriod * 30.0 / 4.0));
    const CanvasLighting lighting = benchCanvasLighting(cs, checkFrame);
    const ImageF tiled = readTextureF(renderer.execute(lighting, CanvasShading::Tiled));
    const ImageF full = readTextureF(renderer.execute(lighting, CanvasShading::Fullscreen));
    double maxDiff = 0;
    for (std::size_t i = 0; i < tiled.rgba.size(); ++i) {
        maxDiff = std::max(maxDiff, double(std::abs(tiled.rgba[i] - full.rgba[i])));
    }
    return maxDiff;
}

/// Warm-up, then GPU timer queries over back-to-back frames, then glFinish-bracketed wall times.
CanvasPathResult timeCanvasPath(CanvasRenderer& renderer, const CanvasSceneSettings& cs,
                                CanvasShading shading, const BenchOptions& options) {
    CanvasPathResult r{.shading = shading, .gpuMs = {}, .wallMs = {}};
    int frame = 0;
    for (int i = 0; i < options.warmup; ++i) { // shader JIT, first touch of the targets
        renderer.execute(benchCanvasLighting(cs, frame++), shading);
    }
    glFinish();
    // Timer queries as a frame loop takes them: N-buffered in GpuTimers, harvested when available. The
    // flush stands in for a swap; the drain at the end collects what is still in flight.
    GpuTimers timers;
    for (int i = 0; i < options.frames; ++i) {
        timers.beginFrame();
        renderer.execute(benchCanvasLighting(cs, frame++), shading, &timers);
        timers.endFrame();
        glFlush();
    }
    for (const auto& passes : timers.drain()) {
        for (const PassTiming& p : passes) {
            r.gpuMs.push_back(p.gpuMs);
        }
    }
    // Wall clock with glFinish on both sides: everything the shading costs, wherever the driver runs it.
    for (int i = 0; i < options.frames; ++i) {
        glFinish();
        const auto start = std::chrono::steady_clock::now();
        renderer.execute(benchCanvasLighting(cs, frame++), shading);
        glFinish();
        r.wallMs.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    return r;
}

/// The console report of the canvas benchmark; returns the per-path entries of its JSON.
nlohmann::json printCanvasBench(const BenchOptions& options, const CanvasSceneSettings& cs,
                                const CanvasRenderer& renderer, const ContextInfo& info, double maxDiff,
                                const std::vector<CanvasPathResult>& results) {
    const auto [width, height] = parseSize(options.size, 8);
    const int total = renderer.grid().count();
    std::printf("photopic bench --scene canvas: %dx%d, %d frames per path after %d warm-up, %s\n", width,
                height, options.frames, options.warmup, info.renderer.c_str());
    std::printf("tiles of %d px, occupancy %.2f: %d of %d tiles hold material; tiled and full-screen outputs "
                "agree (max |difference| %g)\n",
                cs.tileSize, double(cs.occupancy), renderer.occupiedTiles(), total, maxDiff);
    std::printf(
        "'gpu query ms': GL timer queries, frames back to back (the figure on a GPU); 'wall+finish ms': "
        "glFinish-bracketed wall clock%s\n",
        isSoftwareRenderer()
            ? " (the figure on this software renderer, whose timestamps can miss work run at the flush)"
            : "");
    std::printf("%-12s %16s %10s %14s %16s\n", "path", "tiles shaded", "share", "gpu query ms",
                "wall+finish ms");
    nlohmann::json paths = nlohmann::json::array();
    for (const CanvasPathResult& r : results) {
        const std::string name(canvasShadingNames()[std::size_t(r.shading)]);
        const int shaded = renderer.tilesShaded(r.shading);
        const double gpu = median(r.gpuMs), wall = median(r.wallMs);
        std::printf("%-12s %16s %9.1f%% %14.3f %16.3f\n", name.c_str(),
                    fmt::format("{}/{}", shaded, total).c_str(), 100.0 * shaded / std::max(total, 1), gpu,
                    wall);
        paths.push_back({{"name", name},
                         {"tilesShaded", shaded},
                         {"tilesTotal", total},
                         {"medianGpuMs", gpu},
                         {"medianWallMs", wall},
                         {"gpuSamples", r.gpuMs.size()},
                         {"wallSamples", r.wallMs.size()}});
    }
    return paths;
}

} // namespace

/// Tile-based lighting's claim: the tiled shading (specular + sparkle only on tiles with material, indirect
/// dispatch) against the full-screen shading, after checking that both give the same image.
int runCanvasBench(const BenchOptions& options) {
    if (options.frames < 1) {
        throw InputError("--frames must be at least 1");
    }
    if (!options.input.empty() || options.forceLdr) {
        throw InputError("bench --scene canvas renders its own canvas: --input and --force-ldr do not apply");
    }
    const CanvasSceneSettings cs = canvasBenchSettings(options.settings);
    const auto [width, height] = parseSize(options.size, 8);

    HeadlessContext context(commandContext());
    if (!detectCapabilities(false).timerQueries) {
        throw std::runtime_error("this GL implementation has no timer queries; nothing to measure");
    }
    CanvasRenderer renderer;
    renderer.setCanvas(benchCanvas(cs, width, height), cs.tileSize);

    // The output check comes first: timing two paths that disagree would compare different work.
    const double maxDiff = canvasPathsDifference(renderer, cs);
    // Both paths evaluate the same shading function per pixel; anything above half-float rounding is a bug.
    constexpr double kTolerance = 1.0 / 1024.0;
    if (!(maxDiff <= kTolerance)) {
        std::fprintf(stderr,
                     "photopic: bench --scene canvas: tiled and full-screen shading differ by %g (> %g)\n",
                     maxDiff, kTolerance);
        return kFailure;
    }

    std::vector<CanvasPathResult> results;
    for (const CanvasShading shading : {CanvasShading::Tiled, CanvasShading::Fullscreen}) {
        results.push_back(timeCanvasPath(renderer, cs, shading, options));
    }

    const ContextInfo& info = context.info();
    const nlohmann::json paths = printCanvasBench(options, cs, renderer, info, maxDiff, results);

    if (!options.json.empty()) {
        const nlohmann::json doc = {{"scene", "canvas"},
                                    {"width", width},
                                    {"height", height},
                                    {"frames", options.frames},
                                    {"warmup", options.warmup},
                                    {"renderer", info.renderer},
                                    {"tileSize", cs.tileSize},
                                    {"occupancy", cs.occupancy},
                                    {"occupiedTiles", renderer.occupiedTiles()},
                                    {"maxAbsDifference", maxDiff},
                                    {"paths", paths}};
        writeJsonAtomically(options.json, doc);
        std::printf("wrote %s\n", options.json.string().c_str());
    }
    return kOk;
}

} // namespace photopic::cli
