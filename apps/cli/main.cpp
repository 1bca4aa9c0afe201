// photopic: the command-line front end. Exit codes: 0 ok, 2 bad usage or input, 1 other failure.

#include "Bench.h"
#include "Commands.h"
#include "TabletopDemo.h"

#include "core/Log.h"
#include "core/settings/SettingsJson.h"
#include "gl/Gl.h"
#include "io/DataPath.h"
#include "scenes/Scene.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <cstdio>

using namespace photopic;
using namespace photopic::cli;

namespace {

void addSettingsOptions(CLI::App* cmd, SettingsSources& s) {
    cmd->add_option("--settings", s.file, "settings JSON file ({\"version\": 1, \"postEffects\": {...}})")
        ->check(CLI::ExistingFile);
    cmd->add_option("--tonemap", s.tonemap, "tone curve (same as --set tonemapping.mode=NAME)");
    cmd->add_option("--exposure", s.exposure,
                    "manual exposure in EV (same as --set tonemapping.exposure=EV)");
    cmd->add_option(
        "--debug", s.debugView,
        "debug view: none, exposure, luma, ev, metering, histogram, bloom (same as --set debug.view=NAME)");
    cmd->add_option("--set", s.overrides, "override one setting: path=value, e.g. tonemapping.mode=agx")
        ->take_first();
}

void addMaxPixelsOption(CLI::App* cmd, std::int64_t& maxPixels) {
    cmd->add_option("--max-pixels", maxPixels,
                    "refuse input images with more pixels than this, before decoding them (memory bound)")
        ->check(CLI::Range(std::int64_t(1), std::int64_t(1) << 40))
        ->capture_default_str();
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"Photopic: HDR post-processing and eye adaptation on OpenGL 4.5"};
    app.require_subcommand(1);
    bool forceLdr = false;

    auto* info =
        app.add_subcommand("info", "GL vendor, renderer, version, and whether the HDR or LDR path runs");
    info->add_flag("--force-ldr", forceLdr, "report as if the LDR path were forced");
    SettingsSources infoSettings;
    addSettingsOptions(info, infoSettings);

    ImageOptions image;
    auto* imageCmd =
        app.add_subcommand("image", "process HDR images (EXR, HDR, PNG) into PNG (display) or EXR "
                                    "(scene-referred, before tone mapping)");
    imageCmd
        ->add_option("inputs", image.inputs, "input images; several are frames of a sequence in name order")
        ->required();
    imageCmd->add_option("-o,--output", image.output,
                         "output file (.png/.exr) or folder (several inputs); required unless --info");
    imageCmd->add_option("--format", image.format, "file type written into an output folder")
        ->check(CLI::IsMember({"png", "exr"}));
    imageCmd->add_option("--fps", image.fps, "frame rate of a sequence")->check(CLI::Range(0.001f, 10000.0f));
    imageCmd->add_flag("--force-ldr", image.forceLdr, "run the LDR (RGBA8) path");
    imageCmd->add_option("--telemetry", image.telemetry,
                         "write exposure telemetry as CSV, one row per frame (frame,time_s,measured_luma,"
                         "target_log2,applied_log2,exposure,...)");
    imageCmd->add_flag(
        "--info", image.info,
        "list each input's channels and attributes and what each feeds (depth, normals, motion, "
        "camera); no rendering");
    imageCmd
        ->add_option("--camera", image.camera,
                     "camera JSON for EXR inputs without worldToCamera/worldToNDC (docs/camera-json.md)")
        ->check(CLI::ExistingFile);
    imageCmd->add_option(
        "--write-aux", image.writeAux,
        "write each frame's decoded depth (linear view), normals (view space) and motion (UV, "
        "y up) as DIR/NAME.aux.exr");
    imageCmd
        ->add_option("--jitter", image.jitter,
                     "how a sequence's frames were jittered, for TAA and the motion unjitter: attribute (the "
                     "EXR `jitter` attribute, pixels, x right, y down; none when absent) or halton "
                     "(Photopic's Halton(2,3) from index 1, as Pipeline::beginFrame hands it out)")
        ->check(CLI::IsMember({"attribute", "halton"}));
    addSettingsOptions(imageCmd, image.settings);
    addMaxPixelsOption(imageCmd, image.maxPixels);

    auto* settingsCmd = app.add_subcommand("settings", "print the default settings or check a settings file");
    bool defaults = false;
    std::filesystem::path checkFile;
    auto* defaultsFlag = settingsCmd->add_flag("--defaults", defaults, "print the full default JSON");
    auto* checkOption = settingsCmd->add_option("--check", checkFile, "validate FILE and list every issue");
    defaultsFlag->excludes(checkOption);
    settingsCmd->require_option(1);

    SceneOptions scene;
    auto* sceneCmd = app.add_subcommand("scene", "render a built-in scene's frames and telemetry.csv");
    sceneCmd->add_option("name", scene.name, "scene name (photopic scene --list)");
    bool listScenes = false;
    sceneCmd->add_flag("--list", listScenes, "list the built-in scenes");
    sceneCmd->add_option("-o,--output", scene.output, "output folder (default out/scene-NAME)");
    sceneCmd->add_option("--frames", scene.frames, "number of frames")->check(CLI::Range(1, 100000));
    sceneCmd->add_option("--fps", scene.fps, "frame rate")->check(CLI::Range(0.001f, 10000.0f));
    sceneCmd->add_option("--size", scene.size, "WIDTHxHEIGHT");
    sceneCmd->add_option("--format", scene.format, "frame files: png (display) or exr (scene-referred)")
        ->check(CLI::IsMember({"png", "exr"}));
    sceneCmd->add_flag("--force-ldr", scene.forceLdr, "run the LDR (RGBA8) path");
    sceneCmd->add_option("--every", scene.every, "write every Nth frame (telemetry keeps every frame)")
        ->check(CLI::Range(1, 100000));
    sceneCmd->add_flag("--report-rss", scene.reportRss,
                       "print resident memory (VmRSS) after the first and the last frame");
        sceneCmd->add_option("--canvas", scene.canvasColor, "canvas scene: the painting's colour image");
    sceneCmd->add_option("--material", scene.canvasMaterial,
                         "canvas scene: material PNG (RGBA: normal x, y; shininess; glitter mask)");
    sceneCmd->add_option("--motion", scene.motion, "canvas scene: device motion CSV (time_s,pitch,roll,yaw)");
    sceneCmd->add_option(
        "--truth", scene.truth,
        "testbed scene: write the CPU ray tracer's KIND (color, depth, normals, motion, objectid, "
        "ao, sun, shutter, thinlens, reflection, or all) for the frames instead of rendering");
    sceneCmd->add_option("--start", scene.start, "first frame index (--truth)")
        ->check(CLI::Range(0, 10000000));
    addSettingsOptions(sceneCmd, scene.settings);

    TabletopWalkOptions walk;
    std::filesystem::path demoData; // empty: findDataDir() looks it up
    std::string demoSize = "320x180";
    auto* demo = app.add_subcommand(
        "demo", "the main demo: the tabletop walk (eye adaptation) into out/demo (or -o DIR)");
    demo->add_option("-o,--output", walk.output, "output folder");
    demo->add_option("--size", demoSize, "WIDTHxHEIGHT")->capture_default_str();
    demo->add_option("--fps", walk.fps, "frame rate")->check(CLI::Range(1.0f, 240.0f))->capture_default_str();
    demo->add_option("--seconds", walk.seconds, "length of the walk")
        ->check(CLI::Range(0.1f, 600.0f))
        ->capture_default_str();
    demo->add_option("--every", walk.frameEvery, "write every Nth frame as PNG")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    bool noVideo = false;
    demo->add_flag("--no-video", noVideo, "do not encode demo.mp4 even when ffmpeg is present");
    bool demoImages = false;
    demo->add_flag("--images", demoImages,
                   "the former demo instead: every HDR image in --data through three tone curves");
    demo->add_option("--data", demoData,
                     "folder of HDR images for --images (default: $PHOTOPIC_DATA_DIR, else the installed "
                     "share/photopic/data, else the checkout's data/)");
    std::int64_t demoMaxPixels = kDefaultMaxPixels;
    addMaxPixelsOption(demo, demoMaxPixels);

    BenchOptions bench;
    auto* benchCmd =
        app.add_subcommand("bench", "per-pass GPU timings (median ms, bytes moved, GB/s) over N "
                                    "frames of a synthetic HDR frame or --input FILE, or the canvas "
                                    "scene's shading paths (--scene canvas)");
    benchCmd->add_option("--size", bench.size, "WxH of the synthetic frame")->capture_default_str();
    benchCmd->add_option("--frames", bench.frames, "timed frames after the warm-up")
        ->check(CLI::Range(1, 100000))
        ->capture_default_str();
    benchCmd->add_option("--warmup", bench.warmup, "untimed frames first")->check(CLI::Range(0, 1000));
    benchCmd->add_option("--input", bench.input, "an HDR image (EXR, HDR) instead of the synthetic frame")
        ->check(CLI::ExistingFile);
    benchCmd->add_option("--json", bench.json, "also write the table as JSON to FILE (atomically)");
    benchCmd->add_flag("--force-ldr", bench.forceLdr, "run the LDR (RGBA8) path");
    benchCmd->add_flag("--sync", bench.sync,
                       "debug: glFinish() around every pass and report its wall time too (stalls each pass; "
                       "for drivers whose timer queries miss deferred work, e.g. llvmpipe)");
    benchCmd->add_option("--scene", bench.scene,
                         "canvas: time the canvas scene's tiled and full-screen shading paths instead "
                         "(--set canvas.KEY=VALUE, e.g. canvas.occupancy=0.3, the default)");
    addSettingsOptions(benchCmd, bench.settings);
    addMaxPixelsOption(benchCmd, bench.maxPixels);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? kOk : kBadInput;
    }

    try {
        if (*info) {
            return runInfo(forceLdr, infoSettings);
        }
        if (*imageCmd) {
            return runImage(image);
        }
        if (*settingsCmd) {
            return defaults ? runSettingsDefaults() : runSettingsCheck(checkFile);
        }
        if (*sceneCmd) {
            if (listScenes) {
                for (const auto& s : builtInScenes()) {
                    std::printf("%-10s %s\n", s.name.c_str(), s.description.c_str());
                }
                return kOk;
            }
            if (scene.name.empty()) {
                throw InputError("scene: a scene name is required (photopic scene --list)");
            }
            return runScene(scene);
        }
        if (*benchCmd) {
            return runBench(bench);
        }
        if (*demo) {
            if (demoImages) {
                return runDemo(findDataDir(demoData), walk.output, demoMaxPixels);
            }
            const Extent size = parseSize(demoSize);
            walk.width = size.width;
            walk.height = size.height;
            walk.video = !noVideo;
            return runTabletopWalk(walk);
        }
    } catch (const InputError& e) {
        std::fprintf(stderr, "photopic: %s\n", e.what());
        return kBadInput;
    } catch (const SettingsError& e) {
        std::fprintf(stderr, "photopic: invalid settings in %s", e.what());
        return kBadInput;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photopic: %s\n", e.what());
        return kFailure;
    }
    return kFailure;
}
