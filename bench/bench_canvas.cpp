// Canvas scene: GPU time of the tiled shading (specular + sparkle only on the tiles with
// material, indirect dispatch) against the full-screen shading, at 1920x1080 with 30% of the 256 px tiles
// occupied. Timed with GL_TIME_ELAPSED queries around each dispatch, after warm-up; the output is checked
// (the two paths must give the same image, and the tiled path must list 30% of the tiles) before anything is
// timed.

#include "core/Motion.h"
#include "gl/TextureIo.h"
#include "scenes/canvas/CanvasRenderer.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

namespace {

using namespace photopic;

constexpr int kWidth = 1920, kHeight = 1080, kTileSize = 256;
constexpr double kOccupancy = 0.3;

struct CanvasBench {
    CanvasRenderer renderer;
    Query query{GL_TIME_ELAPSED};
    bool checked = false;
    std::string error;

    CanvasBench() {
        renderer.setCanvas(
            makeProceduralCanvas(
                {.width = kWidth, .height = kHeight, .tileSize = kTileSize, .occupancy = kOccupancy}),
            kTileSize);
    }

    static CanvasLighting lighting(int frame) {
        const Attitude a = ScriptedTilt{}.at(frame / 30.0);
        return {.light = canvasLightDirection(a.pitch, a.roll)};
    }

    /// The bench's own output check: both paths agree to the bit, 30% of the tiles are listed.
    void check() {
        if (checked) {
            return;
        }
        checked = true;
        const int expected = int(std::lround(kOccupancy * renderer.grid().count()));
        if (renderer.occupiedTiles() != expected) {
            error = "tiled path lists " + std::to_string(renderer.occupiedTiles()) + " tiles, expected " +
                    std::to_string(expected);
            return;
        }
        const ImageF tiled = readTextureF(renderer.execute(lighting(45), CanvasShading::Tiled));
        const ImageF full = readTextureF(renderer.execute(lighting(45), CanvasShading::Fullscreen));
        if (tiled.rgba != full.rgba) {
            error = "tiled and full-screen shading differ";
        }
    }

    struct Timing {
        double gpuMs = 0;  ///< GL_TIME_ELAPSED around the dispatches
        double wallMs = 0; ///< glFinish-bracketed wall time of the same dispatches
    };

    /// One shading pass, timed (blocks on the query and on glFinish: benchmarks only).
    Timing timeOnce(CanvasShading shading, int frame) {
        glFinish();
        const auto start = std::chrono::steady_clock::now();
        glBeginQuery(GL_TIME_ELAPSED, query.id());
        renderer.execute(lighting(frame), shading);
        glEndQuery(GL_TIME_ELAPSED);
        glFinish();
        const auto end = std::chrono::steady_clock::now();
        GLuint64 ns = 0;
        glGetQueryObjectui64v(query.id(), GL_QUERY_RESULT, &ns);
        return {double(ns) * 1e-6, std::chrono::duration<double, std::milli>(end - start).count()};
    }
};

CanvasBench& bench() {
    static std::unique_ptr<CanvasBench> instance = std::make_unique<CanvasBench>();
    return *instance;
}

void shade(benchmark::State& state, CanvasShading shading) {
    CanvasBench& b = bench();
    b.check();
    if (!b.error.empty()) {
        state.SkipWithError(b.error.c_str());
        return;
    }
    for (int i = 0; i < 3; ++i) { // warm-up: shader JIT, first-touch of the targets
        b.timeOnce(shading, i);
    }
    int frame = 0;
    double gpuMs = 0, wallMs = 0;
    for (auto _ : state) {
        const CanvasBench::Timing t = b.timeOnce(shading, frame++);
        gpuMs += t.gpuMs;
        wallMs += t.wallMs;
        // The timer query is the measure on a GPU; Mesa llvmpipe executes the dispatch at the flush, outside
        // the query's bracket, and reports ~0, so there the glFinish-bracketed wall time stands in.
        state.SetIterationTime((t.gpuMs > 0.01 ? t.gpuMs : t.wallMs) * 1e-3);
    }
    state.counters["gpu_query_ms"] = gpuMs / double(std::max(frame, 1));
    state.counters["finish_wall_ms"] = wallMs / double(std::max(frame, 1));
    state.counters["tiles_shaded"] = b.renderer.tilesShaded(shading);
    state.counters["tiles_total"] = b.renderer.grid().count();
}

void BM_CanvasShadeTiled(benchmark::State& state) {
    shade(state, CanvasShading::Tiled);
}
void BM_CanvasShadeFullscreen(benchmark::State& state) {
    shade(state, CanvasShading::Fullscreen);
}

BENCHMARK(BM_CanvasShadeTiled)
    ->Name("canvas_shade/tiled/1920x1080/occupancy:0.3")
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(20);
BENCHMARK(BM_CanvasShadeFullscreen)
    ->Name("canvas_shade/fullscreen/1920x1080/occupancy:0.3")
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(20);

} // namespace
