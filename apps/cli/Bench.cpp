// `photopic bench`: renders a frame N times after a warm-up and prints, for every pass, the median GPU time
// (timer queries, harvested after each frame so none is dropped), the estimated bytes it moves and the
// bandwidth that implies: a pass far below the device's bandwidth is bound by something else. `--sync` adds a
// glFinish-bracketed wall time per pass (gl/GpuTimers.h synchronous mode).
// `--scene canvas` instead times the canvas scene's two shading paths (scenes/canvas/CanvasRenderer.h).
//
// Reading the numbers on Mesa llvmpipe (software GL): a draw is binned and rasterised when its scene is
// flushed (a framebuffer change, a glFinish), so its work can land after the pass's end timestamp and be
// counted in whichever later pass's bracket holds the flush. The timer query is the figure on a GPU; on
// llvmpipe the --sync wall time is the one that holds a pass's own work.

#include "Bench.h"

#include "Outputs.h"

#include "core/Log.h"
#include "core/Motion.h"
#include "core/settings/SettingsJson.h"
#include "gl/Capabilities.h"
#include "gl/Context.h"
#include "gl/TextureIo.h"
#include "io/ImageIO.h"
#include "pipeline/Pipeline.h"
#include "scenes/SceneSettings.h"
#include "scenes/SyntheticHdr.h"
#include "scenes/canvas/CanvasScene.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

namespace photopic::cli {

namespace fs = std::filesystem;

namespace {

double median(std::vector<double> v) {
    if (v.empty()) {
        return 0;
    }
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

bool isSoftwareRenderer(const std::string& renderer) {
    return renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos ||
           renderer.find("SwiftShader") != std::string::npos;
}

void writeJsonAtomically(const fs::path& path, const nlohmann::json& doc) {
    const fs::path tmp = path.string() + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) {
            throw std::runtime_error(fmt::format("cannot write {}", path.string()));
        }
        out << doc.dump(2) << "\n";
        if (!out.flush()) {
            std::error_code ec;
            fs::remove(tmp, ec);
            throw std::runtime_error(fmt::format("cannot write {}", path.string()));
        }
    }
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw std::runtime_error(fmt::format("cannot write {}: {}", path.string(), ec.message()));
    }
}

/// `--set canvas.key=value` into the canvas scene's settings; any other key is an error (this bench shades
/// the canvas and runs no post-processing).
CanvasSceneSettings canvasBenchSettings(const SettingsSources& sources) {
    if (!sources.file.empty() || !sources.tonemap.empty() || sources.exposure || !sources.debugView.empty()) {
        throw InputError(
            "bench --scene canvas times the canvas shading only: post-processing settings do not "
            "apply (use --set canvas.KEY=VALUE)");
    }
    CanvasSceneSettings s;
    s.occupancy = 0.3f; // seed 003's benchmark case: 30% of the tiles hold material
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

/// seed 003 §5: the tiled shading (specular + sparkle only on tiles with material, indirect dispatch) against
/// the full-screen shading, after checking that both give the same image.
int runCanvasBench(const BenchOptions& options) {
    if (options.frames < 1) {
        throw InputError("--frames must be at least 1");
    }
    if (!options.input.empty() || options.forceLdr) {
        throw InputError("bench --scene canvas renders its own canvas: --input and --force-ldr do not apply");
    }
    const CanvasSceneSettings cs = canvasBenchSettings(options.settings);
    const auto [width, height] = parseSize(options.size, 8);

    HeadlessContext context;
    if (!detectCapabilities(false).timerQueries) {
        throw std::runtime_error("this GL implementation has no timer queries; nothing to measure");
    }
    CanvasImages images = makeProceduralCanvas({.width = width,
                                                .height = height,
                                                .tileSize = cs.tileSize,
                                                .occupancy = cs.occupancy,
                                                .seed = std::uint32_t(cs.seed)});
    try {
        if (!cs.colour.empty()) {
            images.colour = loadCanvasColour(cs.colour, width, height);
        }
        if (!cs.material.empty()) {
            images.material = loadCanvasMaterial(cs.material, width, height);
        }
    } catch (const IoError& e) {
        throw InputError(e.what());
    }
    CanvasRenderer renderer;
    renderer.setCanvas(images, cs.tileSize);

    const ScriptedTilt tilt{
        .period = cs.sweepPeriod, .rollAmplitude = cs.sweepRoll, .pitchAmplitude = cs.sweepPitch};
    const auto lighting = [&](int frame) {
        const Attitude a = tilt.at(frame / 30.0);
        return CanvasLighting{.light = canvasLightDirection(a.pitch, a.roll),
                              .lightColour = glm::vec3(cs.lightIntensity),
                              .ambient = cs.ambient,
                              .specular = cs.specular,
                              .sparkleExposure = cs.sparkleExposure,
                              .viewDistance = cs.viewDistance};
    };

    // The output check comes first: timing two paths that disagree would compare different work. A frame a
    // quarter into the sweep, where the highlight and the sparkles are on the canvas.
    const int checkFrame = int(std::lround(cs.sweepPeriod * 30.0 / 4.0));
    const ImageF tiled = readTextureF(renderer.execute(lighting(checkFrame), CanvasShading::Tiled));
    const ImageF full = readTextureF(renderer.execute(lighting(checkFrame), CanvasShading::Fullscreen));
    double maxDiff = 0;
    for (std::size_t i = 0; i < tiled.rgba.size(); ++i) {
        maxDiff = std::max(maxDiff, double(std::abs(tiled.rgba[i] - full.rgba[i])));
    }
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
        CanvasPathResult r{.shading = shading};
        int frame = 0;
        for (int i = 0; i < options.warmup; ++i) { // shader JIT, first touch of the targets
            renderer.execute(lighting(frame++), shading);
        }
        glFinish();
        // Timer queries as a frame loop takes them: N-buffered in GpuTimers, harvested when available. The
        // flush stands in for a swap; the drain at the end collects what is still in flight.
        GpuTimers timers;
        for (int i = 0; i < options.frames; ++i) {
            timers.beginFrame();
            renderer.execute(lighting(frame++), shading, &timers);
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
            renderer.execute(lighting(frame++), shading);
            glFinish();
            r.wallMs.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
        results.push_back(std::move(r));
    }

    const ContextInfo& info = context.info();
    const int total = renderer.grid().count();
    std::printf("photopic bench --scene canvas: %dx%d, %d frames per path after %d warm-up, %s\n", width,
                height, options.frames, options.warmup, info.renderer.c_str());
    std::printf("tiles of %d px, occupancy %.2f: %d of %d tiles hold material; tiled and full-screen outputs "
                "agree (max |difference| %g)\n",
                cs.tileSize, double(cs.occupancy), renderer.occupiedTiles(), total, maxDiff);
    std::printf(
        "'gpu query ms': GL timer queries, frames back to back (the figure on a GPU); 'wall+finish ms': "
        "glFinish-bracketed wall clock%s\n",
        isSoftwareRenderer(info.renderer)
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

} // namespace

int runBench(const BenchOptions& options) {
    if (!options.json.empty()) {
        RunOutputs::requireFile(options.json); // before the minutes of timing, not after
    }
    if (!options.scene.empty()) {
        if (options.scene != "canvas") {
            throw InputError(
                fmt::format("bench --scene {}: the only scene with a benchmark is 'canvas'", options.scene));
        }
        return runCanvasBench(options);
    }
    const Settings settings = resolveSettings(options.settings);
    if (options.frames < 1) {
        throw InputError("--frames must be at least 1");
    }
    ImageF image;
    if (!options.input.empty()) {
        image = readInput(options.input, options.maxPixels);
    } else {
        const auto [w, h] = parseSize(options.size, 8);
        image = makeSyntheticHdr(w, h);
    }

    HeadlessContext context;
    if (!options.input.empty()) {
        requireTextureFits(options.input, image.width, image.height);
    }
    Pipeline pipeline({.settings = settings, .forceLdr = options.forceLdr});
    if (!pipeline.capabilities().timerQueries) {
        throw std::runtime_error("this GL implementation has no timer queries; nothing to measure");
    }
    pipeline.timers().setSynchronous(options.sync);
    const Texture input = makeTexture(image, "bench input");
    std::uint64_t frame = 0;
    for (int i = 0; i < options.warmup; ++i) {
        pipeline.execute({.color = &input}, {.frameIndex = frame++});
        pipeline.timers().drain();
    }
    std::vector<std::string> order;
    std::map<std::string, std::vector<double>> times;
    std::map<std::string, std::vector<double>> walls;
    std::map<std::string, double> bytes;
    std::vector<double> totals, wallTotals;
    for (int i = 0; i < options.frames; ++i) {
        pipeline.execute({.color = &input}, {.frameIndex = frame++});
        for (const auto& passes : pipeline.timers().drain()) {
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

    const PipelineStatus t = pipeline.status();
    const ContextInfo& info = context.info();
    std::printf("photopic bench: %dx%d, %d frames after %d warm-up, %s\n", image.width, image.height,
                options.frames, options.warmup, info.renderer.c_str());
    std::printf("colour path: %s (%s), quality %s, bloom levels %d\n",
                t.path == ColorPath::Hdr ? "HDR" : "LDR", t.pathReason.c_str(),
                std::string(qualityNames()[std::size_t(t.quality)]).c_str(), t.bloomLevels);
    if (options.sync) {
        std::printf("--sync: glFinish() around every pass; 'wall ms' holds the pass's own work and nothing "
                    "else\n");
    } else if (isSoftwareRenderer(info.renderer)) {
        std::printf("note: %s runs a draw when its scene is flushed, which can fall outside the pass's "
                    "timestamps and into a later pass's: run with --sync for per-pass wall times\n",
                    info.renderer.c_str());
    }
    std::printf("%-36s %12s %12s %10s%s\n", "pass", "median ms", "MB moved", "GB/s",
                options.sync ? "      wall ms" : "");
    nlohmann::json passesJson = nlohmann::json::array();
    double totalBytes = 0;
    for (const auto& name : order) {
        const double ms = median(times[name]);
        const double b = bytes[name];
        const double gbps = ms > 0 ? b / (ms * 1e6) : 0.0;
        totalBytes += b;
        nlohmann::json row = {{"name", name},
                              {"medianGpuMs", ms},
                              {"bytesMoved", b},
                              {"gbPerSecond", gbps},
                              {"samples", times[name].size()}};
        if (options.sync) {
            const double wall = median(walls[name]);
            std::printf("%-36s %12.3f %12.2f %10.2f %12.3f\n", name.c_str(), ms, b / 1e6, gbps, wall);
            row["medianWallMs"] = wall;
        } else {
            std::printf("%-36s %12.3f %12.2f %10.2f\n", name.c_str(), ms, b / 1e6, gbps);
        }
        passesJson.push_back(row);
    }
    const double totalMs = median(totals);
    const double totalWallMs = median(wallTotals);
    std::printf("%-36s %12.3f %12.2f %10.2f", "total (median of frame sums)", totalMs, totalBytes / 1e6,
                totalMs > 0 ? totalBytes / (totalMs * 1e6) : 0.0);
    if (options.sync) {
        std::printf(" %12.3f", totalWallMs);
    }
    std::printf("\n");

    if (!options.json.empty()) {
        nlohmann::json doc = {
            {"width", image.width},
            {"height", image.height},
            {"frames", options.frames},
            {"warmup", options.warmup},
            {"renderer", info.renderer},
            {"colourPath", t.path == ColorPath::Hdr ? "hdr" : "ldr"},
            {"colourPathReason", t.pathReason},
            {"quality", std::string(qualityNames()[std::size_t(t.quality)])},
            {"passes", passesJson},
            {"totalMedianGpuMs", totalMs},
            {"totalBytesMoved", totalBytes},
            {"sync", options.sync},
        };
        if (options.sync) {
            doc["totalMedianWallMs"] = totalWallMs;
        }
        writeJsonAtomically(options.json, doc);
        std::printf("wrote %s\n", options.json.string().c_str());
    }
    return kOk;
}

} // namespace photopic::cli
