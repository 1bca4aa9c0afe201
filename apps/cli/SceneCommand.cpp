// `photopic scene NAME`: renders a built-in scene's frames through the pipeline, with per-frame telemetry.

#include "SceneCommand.h"

#include "CommandOptions.h"
#include "FrameStream.h"
#include "Interrupt.h"
#include "Outputs.h"
#include "Progress.h"
#include "TelemetryCsv.h"

#include "core/Color.h"
#include "core/Hash.h"
#include "core/Log.h"
#include "core/settings/SettingsJson.h"
#include "gl/Context.h"
#include "gl/TextureIo.h"
#include "gl/TextureReadback.h"
#include "io/ExrFrame.h"
#include "io/ImageIO.h"
#include "scenes/Scene.h"
#include "scenes/SceneExr.h"
#include "scenes/testbed/TestbedRaytracer.h"
#include "scenes/testbed/TestbedScene.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <ranges>
#include <string>
#include <tuple>
#include <utility>

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

/// A PNG preview of a truth image: colours tone mapped (x / (1 + x)), values as grey, normals as
/// 0.5 + 0.5 n, motion as 0.5 + px / 20 in red (x) and green (y down), ids as hashed colours.
Image8 truthPreview(testbed::TruthKind kind, const ImageF& image) {
    using testbed::TruthKind;
    Image8 out(image.width, image.height);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const float* p = image.at(x, y);
            glm::vec3 c(0.0f);
            switch (kind) {
            case TruthKind::Depth:
                c = glm::vec3(std::isfinite(p[0]) ? 1.0f / (1.0f + p[0] / 5.0f) : 0.0f);
                break;
            case TruthKind::Normals:
                c = 0.5f + 0.5f * glm::vec3(p[0], p[1], p[2]);
                break;
            case TruthKind::Motion:
                c = glm::vec3(0.5f + p[0] * float(image.width) / 20.0f,
                              0.5f - p[1] * float(image.height) / 20.0f, 0.5f);
                break;
            case TruthKind::ObjectId: {
                const std::uint32_t h = p[0] > 0.0f ? hash32(std::uint32_t(p[0])) : 0u;
                c = glm::vec3(float(h & 255u), float((h >> 8) & 255u), float((h >> 16) & 255u)) / 255.0f;
                break;
            }
            case TruthKind::Ao:
            case TruthKind::Sun:
                c = glm::vec3(p[0]);
                break;
            default:
                c = glm::vec3(p[0], p[1], p[2]) / (1.0f + glm::vec3(p[0], p[1], p[2]));
                break;
            }
            const bool encoded =
                kind != TruthKind::Normals && kind != TruthKind::Motion && kind != TruthKind::ObjectId;
            const glm::vec3 v = glm::clamp(encoded ? srgbEncode(c) : c, 0.0f, 1.0f);
            std::uint8_t* o = out.at(x, y);
            o[0] = std::uint8_t(std::lround(v.r * 255.0f));
            o[1] = std::uint8_t(std::lround(v.g * 255.0f));
            o[2] = std::uint8_t(std::lround(v.b * 255.0f));
            o[3] = 255;
        }
    }
    return out;
}

/// A truth image as an EXR frame: RGBA as the ray tracer produced it (view-space normals, UV motion), plus
/// the file-convention layers for depth (Z), normals (N, world) and motion (pixels, y down), and the camera.
ExrFrame truthExr(testbed::TruthKind kind, const ImageF& image, const Camera& camera) {
    using testbed::TruthKind;
    ExrFrame f;
    f.color = image;
    const std::size_t pixels = image.pixelCount();
    if (kind == TruthKind::Depth) {
        f.depth.resize(pixels);
        for (std::size_t i = 0; i < pixels; ++i) {
            f.depth[i] = image.rgba[4 * i];
        }
    } else if (kind == TruthKind::Normals) {
        const glm::mat3 toWorld = glm::transpose(glm::mat3(camera.view));
        f.normals.resize(pixels * 3);
        for (std::size_t i = 0; i < pixels; ++i) {
            const glm::vec3 n =
                toWorld * glm::vec3(image.rgba[4 * i], image.rgba[4 * i + 1], image.rgba[4 * i + 2]);
            f.normals[3 * i] = n.x;
            f.normals[3 * i + 1] = n.y;
            f.normals[3 * i + 2] = n.z;
        }
    } else if (kind == TruthKind::Motion) {
        f.motion.resize(pixels * 2);
        for (std::size_t i = 0; i < pixels; ++i) {
            f.motion[2 * i] = image.rgba[4 * i] * float(image.width);
            f.motion[2 * i + 1] = -image.rgba[4 * i + 1] * float(image.height);
        }
    }
    f.camera = exrFromCamera(camera, image.width, image.height);
    return f;
}

/// A 3D scene's frame as `photopic image` reads it: scene-referred colour, depth, normals, motion and camera.
/// A jittered frame carries its sample offset, so TAA over the files knows the frames were jittered; its
/// motion is the surfaces' own (between unjittered positions), as renderers and engines write it. Moving
/// the image by j (x right, y up) samples it at the pixel centre - j: in the file's convention (y down) that
/// offset is (-j.x, j.y).
ExrFrame sceneExr(const FrameInputs& inputs, glm::vec2 pipelineJitter) {
    ExrFrame exr = exrFrameFromInputs(inputs);
    if (pipelineJitter != glm::vec2(0.0f))
        exr.camera.jitter = glm::vec2(-pipelineJitter.x, pipelineJitter.y);
    return exr;
}

fs::path framePath(const fs::path& outDir, std::size_t index, const std::string& format) {
    return outDir / fmt::format("frame_{:04d}.{}", index, format);
}

/// The frames stream as `photopic image`'s do: each frame's read starts once it is processed and finishes
/// once the next one is (one read buffer: the next read starts after it), so the GPU ends a frame while the
/// CPU renders the next one's inputs; frames are encoded and written on worker threads (a bounded number at
/// once, their storage recycled), in order.
class SceneFrameWriter {
public:
    SceneFrameWriter(RunOutputs& outputs, fs::path outDir, std::string format, DisplayEncoding encoding)
        : mOutDir(std::move(outDir))
        , mFormat(std::move(format))
        , mEncoding(encoding)
        , mWriter(outputs, std::size_t(std::max(defaultFramesInFlight() - 1, 1)), encoding,
                  FrameRecord::Sequence)
        , mReadback(1, "cli.scene") {}

    /// Starts reading back output frame `index`, once the frame read before it is written.
    void start(std::size_t index, Pipeline& pipeline, const Texture& display) {
        if (mReading) {
            writeRead(); // the frame written before this one
        }
        if (mFormat == "exr") {
            mReadback.start(pipeline.sceneReferred(), GL_FLOAT);
        } else {
            mReadback.start(display, mEncoding.bitDepth == 16 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_BYTE);
        }
        mReading = index;
    }

    /// Writes the last frame read and waits for every write.
    void finish() {
        if (mReading) {
            writeRead();
        }
        mWriter.finish();
    }

private:
    void writeRead() {
        FrameImage image = mWriter.storage();
        if (mFormat == "exr") {
            mReadback.finish(image.scene);
        } else if (mEncoding.bitDepth == 16) {
            mReadback.finish(image.display16);
        } else {
            mReadback.finish(image.display);
        }
        const fs::path frame = framePath(mOutDir, *mReading, mFormat);
        mReading.reset();
        mWriter.write(frame, std::move(image), [frame] { logDebug("wrote {}", frame.string()); });
    }

    fs::path mOutDir;
    std::string mFormat;
    DisplayEncoding mEncoding;
    FrameWriter mWriter;
    TextureReadback mReadback;
    std::optional<std::size_t> mReading; ///< the frame whose read is started
};

} // namespace

SceneCommand::SceneCommand(CLI::App& parent)
    : Command(parent.add_subcommand("scene", "render a built-in scene's frames and telemetry.csv")) {
    CLI::App& cmd = app();
    SceneOptions& o = mOptions;
    cmd.add_option("name", o.name,
                   "scene name: " + builtInSceneNames() + " (photopic scene --list says what each shows)");
    cmd.add_flag("--list", mList, "list the built-in scenes");
    cmd.add_option("-o,--output", o.output, "output folder (default out/scene-NAME)")->check(kOutputPath);
    cmd.add_option("--frames", o.frames, "number of frames")->check(CLI::Range(1, 100000));
    cmd.add_option("--fps", o.fps, "frame rate")->check(CLI::Range(0.001f, 10000.0f));
    cmd.add_option("--size", o.size, "WIDTHxHEIGHT");
    cmd.add_option("--format", o.format,
                   "frame files: png, tif, tiff, jpg, jpeg (display) or exr (scene-referred)")
        ->check(CLI::IsMember(kFrameFormats))
        ->capture_default_str();
    addDisplayEncodingOptions(&cmd, o.bitDepth, o.jpegQuality);
    cmd.add_flag("--force-ldr", o.forceLdr, "run the LDR (RGBA8) path");
    cmd.add_option("--every", o.every, "write every Nth frame (telemetry keeps every frame)")
        ->check(CLI::Range(1, 100000));
    cmd.add_flag("--report-rss", o.reportRss,
                 "print resident memory (VmRSS) after the first and the last frame");
    addSceneFileOptions();
    addSettingsOptions(&cmd, o.settings, "the scene's own look (realtime)");
    cmd.footer("Examples:\n"
               "  photopic scene --list\n"
               "  photopic scene canvas -o out/canvas --frames 60 --size 960x540 --motion "
               "examples/canvas-motion/tilt.csv\n"
               "  photopic scene testbed -o out/testbed --frames 48 --tonemap agx --debug normals\n"
               "  photopic scene orbit -o out/orbit --model data/gltf/2CylinderEngine.glb --set "
               "orbit.post=raw");
}

void SceneCommand::addSceneFileOptions() {
    CLI::App& cmd = app();
    SceneOptions& o = mOptions;
    cmd.add_option("--canvas", o.canvasColor, "canvas scene: the painting's colour image");
    cmd.add_option("--material", o.canvasMaterial,
                   "canvas scene: material PNG (RGBA: normal x, y; shininess; glitter mask)");
    cmd.add_option("--motion", o.motion,
                   "canvas scene: device motion CSV, header time_s,pitch,roll,yaw: seconds, then "
                   "radians (examples/canvas-motion/tilt.csv)");
    cmd.add_option("--model", o.model,
                   "orbit scene: a glTF 2.0 model (.gltf or .glb) in place of the ship (= --set "
                   "orbit.model=FILE)");
    cmd.add_option("--env", o.env,
                   "orbit scene: an equirectangular HDR image (.exr, .hdr) for the image-based light "
                   "(= --set orbit.env=FILE)");
    cmd.add_option("--truth", o.truth,
                   "testbed scene: write the CPU ray tracer's KIND (" +
                       joined(testbed::allTruthKinds() | std::views::transform(testbed::truthKindName)) +
                       ", or all) for the frames instead of rendering");
    cmd.add_option("--start", o.start, "first frame index (--truth)")->check(CLI::Range(0, 10000000));
}

int SceneCommand::list() {
    for (const auto& s : builtInScenes()) {
        std::printf("%-10s %s\n", s.name.c_str(), s.description.c_str());
    }
    return kOk;
}

int SceneCommand::run() {
    if (mList) {
        return list();
    }
    if (mOptions.name.empty()) {
        throw InputError("scene: a scene name is required (photopic scene --list)");
    }
    const Extent size = parseSize(mOptions.size);
    if (mOptions.frames < 1) {
        throw InputError(fmt::format("--frames {} must be at least 1", mOptions.frames));
    }
    HeadlessContext context(commandContext());
    Settings settings;
    const std::unique_ptr<Scene> scene = makeNamedScene(settings);
    // The scene reads its input files here, before any output exists: a bad one is bad input (exit 2).
    try {
        scene->resize(size);
    } catch (const SceneInputError& e) {
        throw InputError(e.what());
    }
    const fs::path outDir =
        mOptions.output.empty() ? fs::path("out") / ("scene-" + mOptions.name) : mOptions.output;
    // Every output is checked before the first frame; a run that fails takes back what it wrote.
    RunOutputs outputs;
    outputs.makeFolder(outDir);
    if (!mOptions.truth.empty()) {
        return renderTruth(*scene, outDir, outputs);
    }
    stream(*scene, settings, outDir, outputs);
    if (statusLines())
        std::printf("%s: %d frames at %dx%d, %.3g fps -> %s (frames + telemetry.csv)\n",
                    mOptions.name.c_str(), mOptions.frames, size.width, size.height, double(mOptions.fps),
                    outDir.string().c_str());
    return kOk;
}

std::vector<std::string> SceneCommand::sceneOverrides(const Scene& scene) const {
    // The canvas and orbit scenes' file flags are shorthands for their settings, applied before the --set
    // overrides.
    std::vector<std::string> overrides;
    for (const auto& [flag, owner, key, value] :
         {std::tuple{"--canvas", "canvas", "colour", mOptions.canvasColor},
          std::tuple{"--material", "canvas", "material", mOptions.canvasMaterial},
          std::tuple{"--motion", "canvas", "motion", mOptions.motion},
          std::tuple{"--model", "orbit", "model", mOptions.model},
          std::tuple{"--env", "orbit", "env", mOptions.env}}) {
        if (!value.empty()) {
            if (scene.name() != owner) {
                throw InputError(
                    fmt::format("{} is an option of the {} scene, not of '{}'", flag, owner, scene.name()));
            }
            // A JSON string must be UTF-8; a file name need not be. Say so rather than let dump() throw.
            if (const auto bad = invalidUtf8Offset(value)) {
                throw InputError(fmt::format("{}: the file name is not valid UTF-8 (byte {})", flag, *bad));
            }
            overrides.push_back(fmt::format("{}.{}={}", owner, key, nlohmann::json(value).dump()));
        }
    }
    overrides.insert(overrides.end(), mOptions.settings.overrides.begin(), mOptions.settings.overrides.end());
    return overrides;
}

std::unique_ptr<Scene> SceneCommand::makeNamedScene(Settings& settings) const {
    std::unique_ptr<Scene> scene;
    try {
        scene = makeScene(mOptions.name);
    } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
    }
    const SplitOverrides split = splitSceneOverrides(scene->name(), sceneOverrides(*scene));
    applySceneOverrides(*scene, split.scene);
    // Post settings: the scene's defaults, then --settings, the shorthands and every --set that is not the
    // scene's.
    SettingsSources post = mOptions.settings;
    post.overrides = split.post;
    settings = resolveSettings(post, scene->defaultSettings());
    if (mOptions.bitDepth) {
        settings.output.bitDepth = *mOptions.bitDepth;
    }
    return scene;
}

void SceneCommand::stream(Scene& scene, const Settings& settings, const fs::path& outDir,
                          RunOutputs& outputs) const {
    const SceneOptions& options = mOptions;
    const auto paths = [&](std::size_t index) { return framePath(outDir, index, options.format); };
    RunOutputs::requireFile(paths(0));
    requireBitDepthFits({paths(0)}, settings.output.bitDepth,
                        options.bitDepth ? "--bit-depth" : "the settings' output.bitDepth");
    const DisplayEncoding encoding{.bitDepth = settings.output.bitDepth, .jpegQuality = options.jpegQuality};
    outputs.sequence(paths);
    SceneFrameWriter writer(outputs, outDir, options.format, encoding);
    const float dt = 1.0f / options.fps;
    const fs::path telemetryPath = outDir / "telemetry.csv";
    TelemetryCsv telemetry(telemetryPath, dt, scene.telemetryColumns());
    Pipeline pipeline({.settings = settings, .forceLdr = options.forceLdr, .keepTelemetryHistory = true});
    const int every = std::max(1, options.every);
    Progress progress("scene " + options.name, std::size_t(options.frames));
    for (int i = 0; i < options.frames; ++i) {
        throwIfInterrupted();
        const FrameTime time{.dt = dt, .frameIndex = std::uint64_t(i)};
        std::vector<double> values;
        const FrameInputs inputs = scene.render(time, pipeline, values);
        const Texture& display = pipeline.execute(inputs, time);
        if (i % every == 0) {
            if (inputs.camera != nullptr) {
                const fs::path path = outDir / fmt::format("scene_{:04d}.exr", i / every);
                writeExrFrame(path, sceneExr(inputs, pipeline.jitter()));
                outputs.wrote(path);
            }
            writer.start(std::size_t(i / every), pipeline, display);
            logDebug("frame {} -> {}", i, paths(std::size_t(i / every)).string());
        }
        telemetry.sceneValues(std::uint64_t(i), std::move(values));
        telemetry.take(pipeline, std::uint64_t(i), i + 1 == options.frames);
        if (options.reportRss && (i == 0 || i + 1 == options.frames)) {
            progress.clear();
            std::printf("rss after frame %d: %ld kB\n", i + 1, residentKilobytes());
            std::fflush(stdout);
        }
        progress.advance();
    }
    writer.finish();
    telemetry.commit(std::uint64_t(options.frames), pipeline.droppedTelemetry());
    outputs.wrote(telemetryPath);
    outputs.commit();
}

int SceneCommand::renderTruth(Scene& scene, const fs::path& outDir, RunOutputs& outputs) const {
    const SceneOptions& options = mOptions;
    auto* testbedScene = dynamic_cast<TestbedScene*>(&scene);
    if (testbedScene == nullptr) {
        throw InputError(fmt::format("--truth is an option of the testbed scene, not of '{}'", scene.name()));
    }
    std::vector<testbed::TruthKind> kinds;
    if (options.truth == "all") {
        kinds = testbed::allTruthKinds();
    } else if (const auto kind = testbed::parseTruthKind(options.truth)) {
        kinds.push_back(*kind);
    } else {
        std::string known;
        for (const testbed::TruthKind k : testbed::allTruthKinds()) {
            known += std::string(testbed::truthKindName(k)) + ", ";
        }
        throw InputError(fmt::format("--truth '{}' is not a truth kind ({}or all)", options.truth, known));
    }
    const float dt = 1.0f / options.fps;
    Progress progress(fmt::format("scene {} --truth", scene.name()),
                      std::size_t(options.frames) * kinds.size(), "images");
    for (int i = options.start; i < options.start + options.frames; ++i) {
        const FrameTime time{.dt = dt, .frameIndex = std::uint64_t(i)};
        const testbed::TruthOptions truth = testbedScene->truthOptions(time);
        const Camera camera = testbed::truthCamera(truth);
        for (const testbed::TruthKind kind : kinds) {
            throwIfInterrupted();
            const auto begin = std::chrono::steady_clock::now();
            const ImageF image = testbed::renderTruth(kind, truth);
            const double seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
            const std::string stem = fmt::format("truth_{}_{:04d}", testbed::truthKindName(kind), i);
            writeExrFrame(outDir / (stem + ".exr"), truthExr(kind, image, camera));
            outputs.wrote(outDir / (stem + ".exr"));
            writePng(outDir / (stem + ".png"), truthPreview(kind, image));
            outputs.wrote(outDir / (stem + ".png"));
            progress.clear();
            if (statusLines()) {
                std::printf("%s: %.3f s\n", stem.c_str(), seconds);
                std::fflush(stdout);
            }
            progress.advance();
        }
    }
    outputs.commit();
    if (statusLines())
        std::printf("testbed truth: %zu kind(s) x %d frame(s) from frame %d -> %s\n", kinds.size(),
                    options.frames, options.start, outDir.string().c_str());
    return kOk;
}

} // namespace photopic::cli
