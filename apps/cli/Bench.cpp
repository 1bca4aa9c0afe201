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
#include "Progress.h"

#include "core/Log.h"
#include "core/Motion.h"
#include "core/settings/SettingsJson.h"
#include "gl/Capabilities.h"
#include "gl/Context.h"
#include "gl/GpuTimers.h"
#include "gl/ShaderLibrary.h"
#include "gl/TextureIo.h"
#include "io/ImageIO.h"
#include "pipeline/Pipeline.h"
#include "scenes/SceneSettings.h"
#include "scenes/SyntheticHdr.h"
#include "scenes/canvas/CanvasScene.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

namespace photopic::cli {

namespace fs = std::filesystem;

double median(std::vector<double> values) {
    if (values.empty()) {
        return 0;
    }
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

namespace {

/// The table as JSON, through the io library's atomic writer: flushed to disk and renamed into place, so a
/// reader never sees half a table. Throws IoError naming the file.
void writeJsonAtomically(const fs::path& path, const nlohmann::json& doc) {
    // A file name need not be UTF-8 (the input's is in the document): its stray bytes become U+FFFD.
    writeTextFile(path, doc.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

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

} // namespace

/// The image the pipeline benchmark processes: --input, or a synthetic HDR frame of --size.
ImageF benchInput(const BenchOptions& options) {
    if (options.input.empty()) {
        const auto [w, h] = parseSize(options.size, 8);
        return makeSyntheticHdr(w, h);
    }
    if (options.sizeGiven) {
        const auto [w, h] = parseSize(options.size, 8); // before the decode: a bad size fails at once
        return mirroredTo(readInput(options.input, options.maxPixels), w, h);
    }
    return readInput(options.input, options.maxPixels);
}

/// Depth (R32F linear), view-space normals (RGBA16F, facing the camera), motion (RG16F, zero), a camera, a
/// sun and a sun shadow map for the benchmark frame: a wall 10 units away. The shadow map (1024 texels,
/// 32-bit float depth) is synthetic: an orthographic sun view 40 units across over the space between the
/// camera and the wall, with square casters of 64 texels in a checkerboard halfway along the light's depth,
/// so volumetric light's shadow-map march (mode auto) reads a map that shadows half its steps.
class BenchInputs3d {
public:
    /// `sunInView`: the sun ahead of the camera, near the image's centre, so volumetric light marches every
    /// sample of every pixel (its worst case); else behind it (contact shadows' worst case, see frame()).
    BenchInputs3d(int width, int height, bool sunInView)
        : mSunDirection(sunInView ? glm::normalize(glm::vec3(0.05f, 0.03f, -1.0f))
                                  : glm::normalize(glm::vec3(0.3f, 0.5f, 0.8f)))
        , mDepth({.extent = {width, height}, .format = GL_R32F, .debugName = "bench depth"})
        , mNormals({.extent = {width, height}, .format = GL_RGBA16F, .debugName = "bench normals"})
        , mMotion({.extent = {width, height}, .format = GL_RG16F, .debugName = "bench motion"})
        , mShadowMap({.extent = {kShadowMapSize, kShadowMapSize},
                      .format = GL_DEPTH_COMPONENT32F,
                      .debugName = "bench sun shadow map"}) {
        const float depth = 10.0f;
        glClearTexImage(mDepth.id(), 0, GL_RED, GL_FLOAT, &depth);
        const float zero[2] = {0.0f, 0.0f};
        glClearTexImage(mMotion.id(), 0, GL_RG, GL_FLOAT, zero);
        const float facing[4] = {0.0f, 0.0f, 1.0f, 0.0f};
        glClearTexImage(mNormals.id(), 0, GL_RGBA, GL_FLOAT, facing);
        mCamera.projection = perspectiveProjection(mCamera.verticalFov, float(width) / float(height),
                                                   mCamera.nearPlane, mCamera.farPlane);
        mCamera.prevViewProjection = mCamera.viewProjection();
        std::vector<float> casters(std::size_t(kShadowMapSize) * kShadowMapSize);
        for (int y = 0; y < kShadowMapSize; ++y) {
            for (int x = 0; x < kShadowMapSize; ++x) {
                casters[std::size_t(y) * kShadowMapSize + std::size_t(x)] =
                    ((x / 64 + y / 64) % 2) ? 0.5f : 1.0f;
            }
        }
        glTextureSubImage2D(mShadowMap.id(), 0, 0, 0, kShadowMapSize, kShadowMapSize, GL_DEPTH_COMPONENT,
                            GL_FLOAT, casters.data());
        const glm::vec3 centre(0.0f, 0.0f, -5.0f);
        mShadowWorldToClip = glm::ortho(-20.0f, 20.0f, -20.0f, 20.0f, 0.0f, 40.0f) *
                             glm::lookAt(centre + 20.0f * mSunDirection, centre, glm::vec3(0.0f, 1.0f, 0.0f));
    }
    [[nodiscard]] FrameInputs frame(const Texture& color) const {
        return {.color = &color,
                .depth = &mDepth,
                .depthKind = DepthKind::LinearView,
                .normals = &mNormals,
                .motion = &mMotion,
                .camera = &mCamera,
                // Unless the sun is in view: behind the camera, up and to the right; the wall faces it, so
                // contact shadows march every step of every pixel (their worst case).
                .sunDirection = mSunDirection,
                .sunShadow = {.depth = &mShadowMap, .worldToClip = mShadowWorldToClip}};
    }

private:
    static constexpr int kShadowMapSize = 1024;
    glm::vec3 mSunDirection;
    Texture mDepth;
    Texture mNormals;
    Texture mMotion;
    Texture mShadowMap;
    glm::mat4 mShadowWorldToClip{1.0f};
    Camera mCamera;
};

/// `--queue-ahead`: untimed GPU work (gl/gpu_busy.comp.glsl) submitted before each timed frame and lasting
/// longer than the CPU takes to submit the frame, so the GPU reaches the frame with all of its commands
/// queued and the frame's timestamps hold the GPU's own work, not the gaps where it waited for the CPU (a
/// frame submitted to an idle GPU runs as fast as the CPU hands it over). Whether that held is checked on
/// every timed frame: the GPU clock when the CPU had submitted the whole frame
/// (glGetInteger64v(GL_TIMESTAMP), which waits for nothing) must be earlier than the busy work's end
/// timestamp.
class QueueAhead {
public:
    QueueAhead()
        : mProgram(makeComputeProgram("gl/gpu_busy.comp.glsl"))
        , mSink({.size = kInvocations * sizeof(float), .flags = 0, .debugName = "bench busy sink"})
        , mEnd(GL_TIMESTAMP) {}

    /// Lengthens the busy work until one run, submitted and waited for, takes at least `ms` of wall time (at
    /// most kMaxMs): it must outlast the CPU's submission of a frame, which runs on the wall clock. Each step
    /// aims a quarter past the target, so the last run stays under 1.25 times it. The chain grows to
    /// kMaxIterations, then the number of groups (Mesa's llvmpipe ends a shader loop after 65535 iterations).
    void calibrate(double ms) {
        const double target = std::min(ms, kMaxMs);
        for (;;) {
            glFinish();
            const auto start = std::chrono::steady_clock::now();
            submit();
            glFinish();
            mBusyMs =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            if (mBusyMs >= target || mGroups >= kMaxGroups) {
                return;
            }
            const double scale = std::clamp(mBusyMs > 0 ? 1.25 * target / mBusyMs : 16.0, 1.1, 16.0);
            if (mIterations < kMaxIterations) {
                mIterations = GLuint(std::min(double(mIterations) * scale, double(kMaxIterations)));
            } else {
                mGroups = GLuint(std::min(double(mGroups) * scale, double(kMaxGroups)));
            }
        }
    }
    /// The busy work and a timestamp at its end, after a barrier (so the frame's first pass cannot overlap
    /// it), then a flush (so the GPU starts on it while the CPU submits the frame).
    void submit() {
        mProgram.use();
        glProgramUniform1ui(mProgram.id(), 0, mIterations);
        glProgramUniform1f(mProgram.id(), 1, -1.0f);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, mSink.id());
        glDispatchCompute(mGroups, 1, 1);
        glMemoryBarrier(GL_ALL_BARRIER_BITS);
        glQueryCounter(mEnd.id(), GL_TIMESTAMP);
        glFlush();
    }
    /// Right after the CPU has submitted the timed work.
    void markSubmitted() { glGetInteger64v(GL_TIMESTAMP, &mSubmittedAt); }
    /// After the timed work has finished on the GPU: counts whether the GPU was still on the busy work when
    /// the CPU had submitted it.
    void settle() {
        GLuint64 end = 0;
        glGetQueryObjectui64v(mEnd.id(), GL_QUERY_RESULT, &end);
        mHeld += mSubmittedAt >= 0 && GLuint64(mSubmittedAt) < end ? 1 : 0;
        ++mTimed;
    }
    [[nodiscard]] double busyMs() const { return mBusyMs; }
    [[nodiscard]] int held() const { return mHeld; }
    [[nodiscard]] int timed() const { return mTimed; }

private:
    static constexpr std::size_t kInvocations = 64; // one group's (gl/gpu_busy.comp.glsl)
    static constexpr double kMaxMs = 40.0;
    static constexpr GLuint kMaxIterations = 65535;
    static constexpr GLuint kMaxGroups = 1u << 20;
    Program mProgram;
    Buffer mSink;
    Query mEnd;
    GLuint mIterations = 4096;
    GLuint mGroups = 1;
    double mBusyMs = 0;
    GLint64 mSubmittedAt = -1;
    int mHeld = 0, mTimed = 0;
};

/// One timed run: `submit` issues the timed work (behind the busy work, with `ahead`), `collect` takes its
/// results once the GPU has done it; with `ahead`, whether the queue stayed ahead is counted.
template <class Submit, class Collect>
void timedRun(QueueAhead* ahead, Submit&& submit, Collect&& collect) {
    if (ahead) {
        ahead->submit();
    }
    submit();
    if (ahead) {
        ahead->markSubmitted();
    }
    collect();
    if (ahead) {
        ahead->settle();
    }
}

/// The median time of `work` over `frames` runs, each between one pair of GPU timestamps collected before the
/// next run (the wall time around it with --sync); `afterEach` runs between runs, outside the timestamps.
/// With `ahead`, its busy work precedes each run, outside the timestamps (timedRun).
template <class Work, class AfterEach>
double medianTimed(const BenchOptions& options, QueueAhead* ahead, Work&& work, AfterEach&& afterEach) {
    GpuTimers timers;
    timers.setSynchronous(options.sync);
    std::vector<double> ms;
    for (int i = 0; i < options.frames; ++i) {
        timedRun(
            ahead,
            [&] {
                timers.beginFrame();
                {
                    ScopedGpuTimer timer(&timers, "timed");
                    work();
                }
                timers.endFrame();
            },
            [&] {
                for (const auto& frame : timers.drain()) {
                    for (const PassTiming& t : frame) {
                        ms.push_back(options.sync ? t.wallMs : t.gpuMs);
                    }
                }
            });
        afterEach();
    }
    return median(ms);
}

/// The bandwidth reference measured in the same run: a compute copy of the frame's own texture into another
/// of its format and size, timed as the passes are (GPU timestamps around each copy after a warm-up,
/// collected every frame), its output checked against its input. The passes read the frame's texels, so the
/// copy moves them too: on a GPU that compresses memory, a texture of one value (what the reference copied
/// before) can move fewer bytes than its size, and a copy of it would be a best case no frame gets. That copy
/// is still measured beside it (`constantCopy`), for comparison with the records taken with it.
struct CopyReference {
    std::string format; ///< GLSL image format of the copy
    std::string source; ///< "frame": the frame's texture; "constant": a texture cleared to one value
    double medianMs = 0;
    double bytes = 0; ///< read + written per copy
    [[nodiscard]] double gbPerSecond() const { return medianMs > 0 ? bytes / (medianMs * 1e6) : 0.0; }
    [[nodiscard]] nlohmann::json json() const {
        return {{"format", format},
                {"source", source},
                {"medianMs", medianMs},
                {"bytesMoved", bytes},
                {"gbPerSecond", gbPerSecond()}};
    }
};

/// GLSL image format qualifier of the formats a frame comes in.
std::string imageFormatName(GLenum format) {
    switch (format) {
    case GL_RGBA32F:
        return "rgba32f";
    case GL_RGBA8:
        return "rgba8";
    default:
        return "rgba16f";
    }
}

/// Rows 0, height / 2 and height - 1 of level 0 of `texture` as RGBA floats.
std::vector<float> sampleRows(const Texture& texture) {
    const Extent e = texture.extent();
    std::vector<float> rows;
    for (const int y : {0, e.height / 2, e.height - 1}) {
        const std::size_t at = rows.size(), count = std::size_t(e.width) * 4;
        rows.resize(at + count);
        glGetTextureSubImage(texture.id(), 0, 0, y, 0, e.width, 1, 1, GL_RGBA, GL_FLOAT,
                             GLsizei(count * sizeof(float)), rows.data() + at);
    }
    return rows;
}

/// A reference's median time: `run` warmed up, then timed as the passes are.
template <class Work>
double timeReference(const BenchOptions& options, QueueAhead* ahead, const Work& run) {
    for (int i = 0; i < options.warmup; ++i) {
        run();
    }
    return medianTimed(options, ahead, run, [] {});
}

/// The reference copy of `source` (the frame's texture, or the one-value texture: `what`) into a texture of
/// its format and size. Throws when the copy did not reproduce its source.
CopyReference measureCopy(const Texture& source, const char* what, const BenchOptions& options,
                          QueueAhead* ahead) {
    const GLenum format = source.format();
    if (format != GL_RGBA32F && format != GL_RGBA16F && format != GL_RGBA8) {
        throw std::logic_error(fmt::format("bench: no reference copy of GL format {:#x}", format));
    }
    const std::string name = imageFormatName(format);
    const Extent e = source.extent();
    const Program program = makeComputeProgram("gl/bandwidth_copy.comp.glsl", {{"FORMAT", name}});
    const Texture target({.extent = e, .format = format, .debugName = "bench copy target"});
    const auto copy = [&] {
        program.use();
        glBindTextureUnit(0, source.id());
        glBindImageTexture(0, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
        dispatchPixels(e);
        imageWriteBarrier();
    };
    CopyReference r{
        .format = name, .source = what, .bytes = 2.0 * double(e.width) * e.height * bytesPerTexel(format)};
    r.medianMs = timeReference(options, ahead, copy);
    // A copy that did not copy would make every fraction meaningless: a copy into the same format gives
    // back every value as it was.
    const std::vector<float> in = sampleRows(source), out = sampleRows(target);
    const bool same = std::ranges::equal(
        in, out, [](float a, float b) { return a == b || (std::isnan(a) && std::isnan(b)); });
    if (!same) {
        throw std::runtime_error(
            fmt::format("bench: the bandwidth reference copy of the {} did not reproduce its input", what));
    }
    return r;
}

/// The reduction reference: the 2x2 box mean of `source` into an RGBA16F texture of half its size, timed as
/// the copy is. A pass that reads the whole frame and writes a quarter of it (the bloom prefilter) moves its
/// bytes at no more than this pace: its share of the copy's is that kind of pass's ceiling on the device.
/// Throws when the means are not the source's.
CopyReference measureReduction(const Texture& source, const BenchOptions& options, QueueAhead* ahead) {
    const Extent e = source.extent();
    const Extent half{e.width / 2, e.height / 2}; // the bench's frames are 8x8 at least
    const Program program = makeComputeProgram("gl/bandwidth_reduce.comp.glsl", {});
    const Texture target({.extent = half, .format = GL_RGBA16F, .debugName = "bench reduction target"});
    const auto reduce = [&] {
        program.use();
        glBindTextureUnit(0, source.id());
        glBindImageTexture(0, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        dispatchPixels(half);
        imageWriteBarrier();
    };
    CopyReference r{.format = "rgba16f",
                    .source = "frame, 2x2 box mean at half size",
                    .bytes = double(e.width) * e.height * bytesPerTexel(source.format()) +
                             double(half.width) * half.height * bytesPerTexel(GL_RGBA16F)};
    r.medianMs = timeReference(options, ahead, reduce);
    // Its first row against the mean of the source's first two, within the rounding to halves.
    const int w = e.width;
    std::vector<float> in(std::size_t(w) * 2 * 4), out(std::size_t(half.width) * 4);
    glGetTextureSubImage(source.id(), 0, 0, 0, 0, w, 2, 1, GL_RGBA, GL_FLOAT,
                         GLsizei(in.size() * sizeof(float)), in.data());
    glGetTextureSubImage(target.id(), 0, 0, 0, 0, half.width, 1, 1, GL_RGBA, GL_FLOAT,
                         GLsizei(out.size() * sizeof(float)), out.data());
    for (int x = 0; x < half.width; ++x) {
        for (int c = 0; c < 4; ++c) {
            const auto at = [&](int px, int py) { return in[(std::size_t(py) * w + px) * 4 + c]; };
            const float mean = 0.25f * (at(2 * x, 0) + at(2 * x + 1, 0) + at(2 * x, 1) + at(2 * x + 1, 1));
            const float got = out[std::size_t(x) * 4 + c];
            const bool ok = (std::isnan(mean) && std::isnan(got)) ||
                            (std::abs(mean) > 65504.0f && std::isinf(got)) ||
                            std::abs(got - mean) <= 1e-3f * std::abs(mean) + 1e-7f;
            if (!ok) {
                throw std::runtime_error(fmt::format("bench: the reduction reference gave {} where the mean "
                                                     "of its texels is {} (texel {}, channel {})",
                                                     got, mean, x, c));
            }
        }
    }
    return r;
}

/// A texture of `extent` and `format` cleared to one colour: the source of the copy earlier records used.
Texture constantTexture(Extent extent, GLenum format) {
    Texture texture({.extent = extent, .format = format, .debugName = "bench one-value copy source"});
    const float value[4] = {0.25f, 0.5f, 0.75f, 1.0f};
    glClearTexImage(texture.id(), 0, GL_RGBA, GL_FLOAT, value);
    return texture;
}

/// Per-pass timings over the measured frames, passes in the order they first ran.
struct PassSamples {
    std::vector<std::string> order;
    std::map<std::string, std::vector<double>> times; ///< GPU ms per frame
    std::map<std::string, std::vector<double>> walls; ///< wall ms per frame, where measured (--sync)
    std::map<std::string, double> bytes;              ///< bytes moved per frame
    std::vector<double> totals, wallTotals;           ///< per-frame sums

    void add(const std::vector<std::vector<PassTiming>>& frames) {
        for (const auto& passes : frames) {
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
};

struct PassTable {
    nlohmann::json passes;
    double totalBytes = 0, totalMs = 0, totalWallMs = 0;
};

/// The per-pass table on stdout: median GPU time, bytes moved, bandwidth and its fraction of the same run's
/// copy (and wall time with --sync).
PassTable printPassTable(const BenchOptions& options, PassSamples& samples, const CopyReference& copy) {
    std::printf("%-36s %12s %12s %10s %8s%s\n", "pass", "median ms", "MB moved", "GB/s", "of copy",
                options.sync ? "      wall ms" : "");
    const double copyGbps = copy.gbPerSecond();
    const auto fractionOf = [copyGbps](double gbps) { return copyGbps > 0 ? gbps / copyGbps : 0.0; };
    PassTable table{.passes = nlohmann::json::array()};
    double& totalBytes = table.totalBytes;
    for (const auto& name : samples.order) {
        const double ms = median(samples.times[name]);
        const double b = samples.bytes[name];
        const double gbps = ms > 0 ? b / (ms * 1e6) : 0.0;
        totalBytes += b;
        nlohmann::json row = {{"name", name},
                              {"medianGpuMs", ms},
                              {"bytesMoved", b},
                              {"gbPerSecond", gbps},
                              {"fractionOfCopy", fractionOf(gbps)},
                              {"samples", samples.times[name].size()}};
        std::printf("%-36s %12.3f %12.2f %10.2f %7.0f%%", name.c_str(), ms, b / 1e6, gbps,
                    100.0 * fractionOf(gbps));
        if (options.sync) {
            const double wall = median(samples.walls[name]);
            std::printf(" %12.3f", wall);
            row["medianWallMs"] = wall;
        }
        std::printf("\n");
        table.passes.push_back(row);
    }
    const double totalMs = table.totalMs = median(samples.totals);
    const double totalWallMs = table.totalWallMs = median(samples.wallTotals);
    const double totalGbps = totalMs > 0 ? totalBytes / (totalMs * 1e6) : 0.0;
    std::printf("%-36s %12.3f %12.2f %10.2f %7.0f%%", "total (median of frame sums)", totalMs,
                totalBytes / 1e6, totalGbps, 100.0 * fractionOf(totalGbps));
    if (options.sync) {
        std::printf(" %12.3f", totalWallMs);
    }
    std::printf("\n");
    return table;
}

int runBench(const BenchOptions& options) {
    if (!options.json.empty()) {
        RunOutputs::requireFile(options.json); // before the minutes of timing, not after
    }
    if (!options.scene.empty()) {
        if (options.queueAhead) {
            throw InputError("bench --scene canvas: --queue-ahead times the pipeline's chain only");
        }
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
    const ImageF image = benchInput(options);

    HeadlessContext context(commandContext());
    if (!options.input.empty()) {
        requireTextureFits(options.input, image.width, image.height);
    }
    Pipeline pipeline({.settings = settings, .forceLdr = options.forceLdr});
    if (!pipeline.capabilities().timerQueries) {
        throw std::runtime_error("this GL implementation has no timer queries; nothing to measure");
    }
    pipeline.timers().setSynchronous(options.sync);
    const Texture input =
        makeTexture(image, "bench input", options.inputFormat == "rgba16f" ? GL_RGBA16F : GL_RGBA32F);
    // 3D inputs for the passes that need them (TAA; contact shadows in the lighting stage): a wall 10 units
    // away, still, seen by a still camera. The sequencer runs nothing on them unless such a pass is on, so
    // the 2D chain's figures are unchanged.
    // Volumetric light alone: its worst case. With contact shadows too, theirs (the sun behind the camera,
    // where volumetric light does no work).
    const BenchInputs3d inputs3d(image.width, image.height,
                                 settings.volumetricLight.enabled && !settings.contactShadows.enabled);
    const FrameInputs inputs = inputs3d.frame(input);
    std::uint64_t frame = 0;
    // The line is drawn between frames, never inside a timed pass or the whole-frame pair of timestamps.
    Progress progress("bench", std::size_t(options.warmup) + 2 * std::size_t(options.frames));
    // One frame's submission; returns the CPU's milliseconds from beginFrame to execute's return.
    const auto submitFrame = [&] {
        const auto start = std::chrono::steady_clock::now();
        pipeline.beginFrame({.frameIndex = frame});
        pipeline.renderLighting(inputs, {.frameIndex = frame});
        pipeline.execute(inputs, {.frameIndex = frame++});
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    };
    std::vector<double> warmupSubmitMs;
    for (int i = 0; i < options.warmup; ++i) {
        warmupSubmitMs.push_back(submitFrame());
        pipeline.timers().drain();
        progress.advance();
    }
    // Four times what a warm frame took the CPU to submit, at least half a millisecond.
    const std::unique_ptr<QueueAhead> ahead = options.queueAhead ? std::make_unique<QueueAhead>() : nullptr;
    if (ahead) {
        ahead->calibrate(std::max(0.5, 4.0 * median(warmupSubmitMs)));
    }
    PassSamples samples;
    std::vector<double> submitMs;
    for (int i = 0; i < options.frames; ++i) {
        timedRun(
            ahead.get(), [&] { submitMs.push_back(submitFrame()); },
            [&] { samples.add(pipeline.timers().drain()); });
        progress.advance();
    }

    // The whole frame between one pair of timestamps, with the passes' own timers off: the chain as a frame
    // loop runs it, gaps between passes included and no per-pass timestamps.
    pipeline.timers().setEnabled(false);
    const double wholeFrameMs = medianTimed(
        options, ahead.get(), [&] { submitFrame(); }, [&] { progress.advance(); });
    // With the queue kept ahead, the frame as a host submits it to an idle GPU too, beside it.
    const double asSubmittedMs = ahead ? medianTimed(
                                             options, nullptr, [&] { submitFrame(); }, [] {})
                                       : wholeFrameMs;
    pipeline.timers().setEnabled(true);
    const double submitMedianMs = median(submitMs);

    const PipelineStatus t = pipeline.status();
    const ContextInfo& info = context.info();
    // "synthetic", or the --input file (mirrored to the frame's size when --size was given)
    const std::string inputName = options.input.empty() ? std::string("synthetic") : options.input.string();
    const bool mirrored = !options.input.empty() && options.sizeGiven;
    std::printf("photopic bench: %dx%d %s input (%s%s), %d frames after %d warm-up, %s\n", image.width,
                image.height, imageFormatName(input.format()).c_str(), inputName.c_str(),
                mirrored ? ", mirrored to this size" : "", options.frames, options.warmup,
                info.renderer.c_str());
    std::printf("colour path: %s (%s), quality %s, bloom levels %d\n", t.path == ColorPath::Hdr ? "HDR" : "LDR",
                t.pathReason.c_str(), std::string(qualityNames()[std::size_t(t.quality)]).c_str(),
                t.bloomLevels);
    if (options.sync) {
        std::printf("--sync: glFinish() around every pass; 'wall ms' holds the pass's own work and nothing "
                    "else\n");
    } else if (isSoftwareRenderer()) {
        std::printf("note: %s runs a draw when its scene is flushed, which can fall outside the pass's "
                    "timestamps and into a later pass's: run with --sync for per-pass wall times\n",
                    info.renderer.c_str());
    }
    // The one-value copy first: on llvmpipe whichever copy runs first reads up to 20% slower.
    const CopyReference constantCopy =
        measureCopy(constantTexture(input.extent(), input.format()), "constant", options, ahead.get());
    const CopyReference copy = measureCopy(input, "frame", options, ahead.get());
    const CopyReference reduction = measureReduction(input, options, ahead.get());
    std::printf("bandwidth reference: %s copy of the frame %dx%d, %.3f ms, %.2f MB, %.2f GB/s (%s); of a "
                "texture of one value: %.3f ms, %.2f GB/s\n",
                copy.format.c_str(), image.width, image.height, copy.medianMs, copy.bytes / 1e6,
                copy.gbPerSecond(), options.sync ? "wall ms with glFinish" : "GPU timestamps",
                constantCopy.medianMs, constantCopy.gbPerSecond());
    std::printf(
        "reduction reference: 2x2 box means of the frame into RGBA16F at half size, %.3f ms, %.2f MB, "
        "%.2f GB/s, %.0f%% of the copy's (what a pass that reads a frame and writes a quarter of it "
        "can reach)\n",
        reduction.medianMs, reduction.bytes / 1e6, reduction.gbPerSecond(),
        copy.gbPerSecond() > 0 ? 100.0 * reduction.gbPerSecond() / copy.gbPerSecond() : 0.0);
    std::printf("CPU: %.3f ms to submit a frame (median, beginFrame to execute's return)\n", submitMedianMs);
    if (ahead) {
        std::printf(
            "--queue-ahead: %.3f ms of untimed GPU work before each timed frame and copy; the GPU was "
            "still on it when the CPU had submitted the frame on %d of %d%s\n",
            ahead->busyMs(), ahead->held(), ahead->timed(),
            ahead->held() < ahead->timed()
                ? " (on the others the timestamps also hold time the GPU waited for the CPU)"
                : "");
    }
    const PassTable table = printPassTable(options, samples, copy);
    std::printf("%-36s %12.3f   (one timestamp pair around each frame, the passes' timers off)\n",
                "whole frame", wholeFrameMs);
    if (ahead) {
        std::printf("%-36s %12.3f   (the same, each frame submitted to an idle GPU)\n",
                    "whole frame, as submitted", asSubmittedMs);
    }
    const nlohmann::json& passesJson = table.passes;
    const double totalBytes = table.totalBytes, totalMs = table.totalMs, totalWallMs = table.totalWallMs;

    if (!options.json.empty()) {
        nlohmann::json doc = {
            {"width", image.width},
            {"height", image.height},
            {"frames", options.frames},
            {"warmup", options.warmup},
            {"renderer", info.renderer},
            {"vendor", info.vendor},
            {"driver", info.version},
            {"platform", info.platform},
            {"inputFormat", imageFormatName(input.format())},
            {"input", inputName},
            {"inputMirrored", mirrored},
            {"copyReference", copy.json()},
            {"constantCopy", constantCopy.json()},
            {"reduceReference", reduction.json()},
            {"colourPath", t.path == ColorPath::Hdr ? "hdr" : "ldr"},
            {"colourPathReason", t.pathReason},
            {"quality", std::string(qualityNames()[std::size_t(t.quality)])},
            {"bloomLevels", t.bloomLevels},
            {"passes", passesJson},
            {"totalMedianGpuMs", totalMs},
            {"frameMedianGpuMs", wholeFrameMs},
            {"totalBytesMoved", totalBytes},
            {"sync", options.sync},
            {"cpuSubmitMedianMs", submitMedianMs},
        };
        if (ahead) {
            doc["queueAhead"] = {{"busyMs", ahead->busyMs()},
                                 {"framesHeld", ahead->held()},
                                 {"framesTimed", ahead->timed()},
                                 {"frameAsSubmittedMedianGpuMs", asSubmittedMs}};
        }
        if (options.sync) {
            doc["totalMedianWallMs"] = totalWallMs;
        }
        writeJsonAtomically(options.json, doc);
        std::printf("wrote %s\n", options.json.string().c_str());
    }
    return kOk;
}

} // namespace photopic::cli
