// `photopic scene NAME`: renders a built-in scene's frames through the pipeline, with per-frame telemetry.

#include "Commands.h"
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

namespace {

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

/// `--truth KIND`: the testbed's ray-traced references for frames [start, start + frames).
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

int runTruth(const SceneOptions& options, Scene& scene, const fs::path& outDir, RunOutputs& outputs) {
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

} // namespace

int runScene(const SceneOptions& options) {
    const Extent size = parseSize(options.size);
    if (options.frames < 1) {
        throw InputError(fmt::format("--frames {} must be at least 1", options.frames));
    }
    HeadlessContext context(commandContext());
    std::unique_ptr<Scene> scene;
    try {
        scene = makeScene(options.name);
    } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
    }

    // The canvas and orbit scenes' file flags are shorthands for their settings, applied before the --set
    // overrides.
    std::vector<std::string> overrides;
    for (const auto& [flag, owner, key, value] :
         {std::tuple{"--canvas", "canvas", "colour", options.canvasColor},
          std::tuple{"--material", "canvas", "material", options.canvasMaterial},
          std::tuple{"--motion", "canvas", "motion", options.motion},
          std::tuple{"--model", "orbit", "model", options.model},
          std::tuple{"--env", "orbit", "env", options.env}}) {
        if (!value.empty()) {
            if (scene->name() != owner) {
                throw InputError(
                    fmt::format("{} is an option of the {} scene, not of '{}'", flag, owner, scene->name()));
            }
            // A JSON string must be UTF-8; a file name need not be. Say so rather than let dump() throw.
            if (const auto bad = invalidUtf8Offset(value)) {
                throw InputError(fmt::format("{}: the file name is not valid UTF-8 (byte {})", flag, *bad));
            }
            overrides.push_back(fmt::format("{}.{}={}", owner, key, nlohmann::json(value).dump()));
        }
    }
    overrides.insert(overrides.end(), options.settings.overrides.begin(), options.settings.overrides.end());
    const SplitOverrides split = splitSceneOverrides(scene->name(), overrides);
    applySceneOverrides(*scene, split.scene);
    // Post settings: the scene's defaults, then --settings, the shorthands and every --set that is not the
    // scene's.
    SettingsSources post = options.settings;
    post.overrides = split.post;
    Settings resolved = resolveSettings(post, scene->defaultSettings());
    if (options.bitDepth) {
        resolved.output.bitDepth = *options.bitDepth;
    }
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
    if (!options.truth.empty()) {
        return runTruth(options, *scene, outDir, outputs);
    }
    const auto framePath = [&](std::size_t index) {
        return outDir / fmt::format("frame_{:04d}.{}", index, options.format);
    };
    RunOutputs::requireFile(framePath(0));
    requireBitDepthFits({framePath(0)}, resolved.output.bitDepth,
                        options.bitDepth ? "--bit-depth" : "the settings' output.bitDepth");
    const DisplayEncoding encoding{.bitDepth = resolved.output.bitDepth, .jpegQuality = options.jpegQuality};
    outputs.sequence(framePath);
    // The frames stream as `photopic image`'s do: each frame's read starts once it is processed and finishes
    // once the next one is (one read buffer: the next read starts after it), so the GPU ends a frame while
    // the CPU renders the next one's inputs; frames are encoded and written on worker threads (a bounded
    // number at once, their storage recycled), in order.
    FrameWriter writer(outputs, std::size_t(std::max(defaultFramesInFlight() - 1, 1)), encoding,
                       FrameRecord::Sequence);
    TextureReadback readback(1, "cli.scene");
    std::optional<std::size_t> reading; ///< the frame whose read is started
    const auto writeRead = [&] {
        FrameImage image = writer.storage();
        if (options.format == "exr") {
            readback.finish(image.scene);
        } else if (encoding.bitDepth == 16) {
            readback.finish(image.display16);
        } else {
            readback.finish(image.display);
        }
        const fs::path frame = framePath(*reading);
        reading.reset();
        writer.write(frame, std::move(image), [frame] { logDebug("wrote {}", frame.string()); });
    };
    const float dt = 1.0f / options.fps;
    const fs::path telemetryPath = outDir / "telemetry.csv";
    TelemetryCsv telemetry(telemetryPath, dt, scene->telemetryColumns());

    Pipeline pipeline({.settings = resolved, .forceLdr = options.forceLdr, .keepTelemetryHistory = true});
    const int every = std::max(1, options.every);
    Progress progress("scene " + options.name, std::size_t(options.frames));
    for (int i = 0; i < options.frames; ++i) {
        throwIfInterrupted();
        const FrameTime time{.dt = dt, .frameIndex = std::uint64_t(i)};
        std::vector<double> values;
        const FrameInputs inputs = scene->render(time, pipeline, values);
        const Texture& display = pipeline.execute(inputs, time);
        if (i % every == 0) {
            if (inputs.camera != nullptr) {
                const fs::path path = outDir / fmt::format("scene_{:04d}.exr", i / every);
                writeExrFrame(path, sceneExr(inputs, pipeline.jitter()));
                outputs.wrote(path);
            }
            if (reading) {
                writeRead(); // the frame written before this one
            }
            if (options.format == "exr") {
                readback.start(pipeline.sceneReferred(), GL_FLOAT);
            } else {
                readback.start(display, encoding.bitDepth == 16 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_BYTE);
            }
            reading = std::size_t(i / every);
            logDebug("frame {} -> {}", i, framePath(*reading).string());
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
    if (reading) {
        writeRead();
    }
    writer.finish();
    telemetry.commit(std::uint64_t(options.frames), pipeline.droppedTelemetry());
    outputs.wrote(telemetryPath);
    outputs.commit();
    if (statusLines())
        std::printf("%s: %d frames at %dx%d, %.3g fps -> %s (frames + telemetry.csv)\n", options.name.c_str(),
                    options.frames, size.width, size.height, double(options.fps), outDir.string().c_str());
    return kOk;
}

} // namespace photopic::cli
