// photopic: the command-line front end. Exit codes: 0 ok, 2 bad usage or input, 1 other failure.

#include "Bench.h"
#include "Commands.h"
#include "Interrupt.h"
#include "OrbitDemo.h"
#include "Progress.h"
#include "SequenceCommands.h"
#include "SettingsReference.h"
#include "TabletopDemo.h"

#include "common/Verbosity.h"
#include "core/Log.h"
#include "core/ShownText.h"
#include "core/ToneCurves.h"
#include "core/settings/SettingsJson.h"
#include "gl/Gl.h"
#include "io/DataPath.h"
#include "scenes/Scene.h"
#include "scenes/testbed/TestbedRaytracer.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <cstdio>
#include <optional>
#include <ranges>
#include <string>
#include <vector>

using namespace photopic;
using namespace photopic::cli;

namespace {

/// An output path that reads as an option ("-o -y" would make a folder named "-y") is refused; "-" alone is
/// standard output, and "./-y" names such a file on purpose.
const CLI::Validator kOutputPath(
    [](std::string& value) {
        return value.size() > 1 && value.front() == '-'
                   ? "\"" + shownText(value) + "\" looks like an option, not a path (write ./" +
                         shownText(value) + " for a file of that name)"
                   : std::string();
    },
    "PATH");

/// "a, b, c": an enum's names as its option's help lists them, from the same list the settings reader checks.
template <class Names>
std::string joined(const Names& names) {
    std::string out;
    for (const auto& name : names) {
        out += (out.empty() ? "" : ", ") + std::string(name);
    }
    return out;
}

/// --preset's help: the presets and what each is for, then where a command's own default comes from.
std::string presetHelp(std::string_view commandDefault) {
    return "look: " + joined(presetNames()) +
           " (stills: photographs, AgX and a tight bloom of what is far past white only; realtime: games and "
           "the built-in scenes, ACES (fitted) and a soft glow over the whole image; neutral: no bloom, "
           "display effects or grading, for measuring). Default: " +
           std::string(commandDefault);
}

void addSettingsOptions(CLI::App* cmd, SettingsSources& s, std::string_view presetDefault) {
    cmd->add_option("--preset", s.preset,
                    presetHelp("the settings file's \"preset\", else " + std::string(presetDefault)) +
                        ". Order: the preset, then the settings file's keys, then "
                        "--tonemap, --exposure, --debug and each --set");
    cmd->add_option("--settings", s.file,
                    "settings JSON file ({\"version\": 1, \"preset\": NAME, \"postEffects\": {...}}, "
                    "every key optional)")
        ->check(CLI::ExistingFile);
    cmd->add_option("--tonemap", s.tonemap,
                    "tone curve: " + joined(toneMapperNames()) + " (same as --set tonemapping.mode=NAME)");
    cmd->add_option("--exposure", s.exposure,
                    "manual exposure in EV (same as --set tonemapping.exposure=EV)");
    cmd->add_option("--debug", s.debugView,
                    "debug view: " + joined(debugViewNames()) +
                        "; views of 3D inputs need them (same as --set debug.view=NAME)");
    cmd->add_option("--set", s.overrides, "override one setting: path=value, e.g. tonemapping.mode=agx")
        ->take_first();
}

void addOcioOptions(CLI::App* cmd, OcioOptions& o) {
    const std::string meaning =
        ": the display image is the OpenColorIO display/view transform of the scene-referred image (after "
        "exposure, bloom and grading, taken as the config's scene_linear role), in place of --tonemap and "
        "the sRGB output; display outputs only (PNG, TIFF, JPEG), and the display-domain effects (FXAA, "
        "SMAA, "
        "grain, vignette, overlays) do not apply to it";
    cmd->add_option("--ocio-display", o.display,
                    "OpenColorIO display (default: the config's default)" + meaning);
    cmd->add_option("--ocio-view", o.view,
                    "OpenColorIO view of the display (default: the display's default)");
    cmd->add_option("--ocio-config", o.config, "OpenColorIO config file (default: $OCIO)");
}

void addMaxPixelsOption(CLI::App* cmd, std::int64_t& maxPixels) {
    cmd->add_option("--max-pixels", maxPixels,
                    "refuse input images with more pixels than this, before decoding them (memory bound)")
        ->check(CLI::Range(std::int64_t(1), std::int64_t(1) << 40))
        ->capture_default_str();
}

/// Every subcommand and the options it fills.
struct Cli {
    CLI::App* info = nullptr;
    bool forceLdr = false;
    SettingsSources infoSettings;
    CLI::App* image = nullptr;
    ImageOptions imageOptions;
    CLI::App* settings = nullptr;
    bool defaults = false;
    bool markdown = false;
    std::filesystem::path checkFile;
    std::string settingsPreset;
    CLI::App* scene = nullptr;
    SceneOptions sceneOptions;
    bool listScenes = false;
    CLI::App* demo = nullptr;
    TabletopWalkOptions walk;
    std::string demoScene = "tabletop";
    std::optional<float> demoSeconds; // unset: the chosen scene's own length
    std::filesystem::path demoData;   // empty: findDataDir() looks it up
    std::string demoSize = "320x180";
    bool noVideo = false;
    bool demoImages = false;
    std::int64_t demoMaxPixels = kDefaultMaxPixels;
    CLI::App* bench = nullptr;
    BenchOptions benchOptions;
    CLI::App* meter = nullptr;
    ImageOptions meterOptions;
    CLI::App* expose = nullptr;
    ExposeOptions exposeOptions;
    CLI::App* farm = nullptr;
    FarmOptions farmOptions;
    Verbosity verbosity;
    bool glDebug = false;
};

void addInfoCommand(CLI::App& app, Cli& c) {
    c.info = app.add_subcommand("info", "GL vendor, renderer, version, and whether the HDR or LDR path runs");
    c.info->add_flag("--force-ldr", c.forceLdr, "report as if the LDR path were forced");
    addSettingsOptions(c.info, c.infoSettings, "the defaults (realtime)");
    c.info->footer("Examples:\n"
                   "  photopic info\n"
                   "  photopic info --force-ldr\n"
                   "  photopic info --set quality=low     the quality tier and the path it takes");
}

/// The file types a frame can be written as: the display image's formats, then EXR (scene-referred).
const std::vector<std::string> kFrameFormats = {"png", "tif", "tiff", "jpg", "jpeg", "exr"};

/// --bit-depth and --jpeg-quality, as `photopic image` and `photopic scene` both take them.
void addDisplayEncodingOptions(CLI::App* cmd, std::optional<int>& bitDepth, int& jpegQuality) {
    cmd->add_option("--bit-depth", bitDepth,
                    "bits per channel of the display image and of PNG and TIFF outputs: 8 or 16 (16 renders "
                    "the display passes at 16 bits, output.bitDepth=16; JPEG is 8-bit only); default: the "
                    "settings' output.bitDepth, 8")
        ->check(CLI::IsMember({8, 16}));
    cmd->add_option("--jpeg-quality", jpegQuality, "quality of JPEG outputs, 1 to 100")
        ->check(CLI::Range(1, 100))
        ->capture_default_str();
}

/// --aovs, --layer and --aov: which channels of an EXR feed what (docs/interop.md).
void addChannelOptions(CLI::App* cmd, std::string& preset, std::string& layer,
                       std::vector<std::string>& aovs) {
    cmd->add_option(
           "--aovs", preset,
           "the channel names and conventions of a renderer: photopic (R G B A, Z, N.*, motion.*) or "
           "blender (<layer>.Combined, .Depth, .Normal, .Vector, .AO, .IndexOB); default: blender "
           "for files that carry Blender's BlenderMultiChannel attribute, else photopic")
        ->check(CLI::IsMember({"photopic", "blender"}));
    cmd->add_option("--layer", layer,
                    "the layer to read (Blender's view layer, or P of P.R/P.G/P.B); default: the only one, "
                    "or the unprefixed channels; several and none chosen is an error listing them");
    cmd->add_option("--aov", aovs,
                    "KIND=CHANNELS[:CONVENTIONS], repeatable: feed KIND (color, depth, normals, motion, ao, "
                    "objectid) from these channels (full names, names in the layer, or a prefix its "
                    "components complete; 'none' reads none), in these conventions (depth: planar|radial; "
                    "normals: world|world-zup|camera; motion: pixels|ndc|uv, current-minus-previous|"
                    "previous-minus-current|next-minus-current, y-up|y-down, jittered|unjittered, "
                    "pair=1|pair=2), e.g. --aov depth=P.Z:radial --aov motion=:jittered")
        ->take_all()
        ->allow_extra_args(false);
}

void addImageCommand(CLI::App& app, Cli& c) {
    c.image = app.add_subcommand("image", "process HDR images (EXR, HDR, PNG) into PNG, TIFF or JPEG "
                                          "(display) or EXR (scene-referred, before tone mapping)");
    c.image
        ->add_option(
            "inputs", c.imageOptions.inputs,
            "input images, or frame-numbered patterns when no such file exists: f%04d.exr (zero padded, "
            "as ffmpeg), f.####.exr (one # a digit), f@.exr (unpadded); several are frames of a sequence, "
            "in natural order (f9 before f10)")
        ->required();
    c.image
        ->add_option(
            "-o,--output", c.imageOptions.output,
            "where results go, required unless --info: an extension means a file (.png, .tif, .tiff, "
            ".jpg, .jpeg: the display image; .exr: scene-referred); a trailing '/', an existing folder or "
            "no extension means a folder (NAME.png, --format), and several inputs need one (or a pattern); "
            "a frame number means a pattern (out/f%04d.png: each input's frame number, or 0, 1, ... when "
            "the inputs carry none); '-', a device or a pipe is streamed (one input, PNG). An output that "
            "is an input, or that two inputs would share, is refused. Existing files are replaced "
            "(atomically) unless -n")
        ->check(kOutputPath);
    auto* noOverwrite = c.image->add_flag("-n,--no-overwrite", c.imageOptions.noOverwrite,
                                          "never overwrite: an output that exists is refused (exit 2) "
                                          "before any work, like ffmpeg -n");
    c.image
        ->add_flag_callback(
            "-y,--overwrite", [] {}, "replace existing outputs (the default; like ffmpeg -y)")
        ->excludes(noOverwrite);
    auto* frames = c.image->add_option("--frames", c.imageOptions.frames,
                                       "frames A-B of a pattern input, inclusive, each of which must exist "
                                       "(1001-1100)");
    c.image
        ->add_option("--start-number", c.imageOptions.startNumber,
                     "a pattern input's first frame (like ffmpeg -start_number); default: the lowest "
                     "that exists. Every frame from it on that exists is taken")
        ->check(CLI::NonNegativeNumber)
        ->excludes(frames);
    c.image->add_option("--format", c.imageOptions.format, "file type written into an output folder")
        ->check(CLI::IsMember(kFrameFormats))
        ->capture_default_str();
    addDisplayEncodingOptions(c.image, c.imageOptions.bitDepth, c.imageOptions.jpegQuality);
    c.image->add_option("--fps", c.imageOptions.fps, "frame rate of a sequence")
        ->check(CLI::Range(0.001f, 10000.0f));
    c.image->add_flag("--force-ldr", c.imageOptions.forceLdr, "run the LDR (RGBA8) path");
    c.image
        ->add_option("--telemetry", c.imageOptions.telemetry,
                     "write exposure telemetry as CSV, one row per frame (frame,time_s,measured_luma,"
                     "target_log2,applied_log2,exposure,...)")
        ->check(kOutputPath);
    c.image->add_flag(
        "--info", c.imageOptions.info,
        "list each input's channels and attributes and what each feeds (depth, normals, motion, "
        "camera); no rendering");
    c.image
        ->add_option("--camera", c.imageOptions.camera,
                     "camera JSON for inputs without worldToCamera/worldToNDC: one camera, or a track of one "
                     "per frame number ({\"frames\": {\"1001\": {...}}}, as tools/blender/photopic_camera.py "
                     "writes it); a frame the track lacks is an error (docs/camera-json.md)")
        ->check(CLI::ExistingFile);
    c.image->add_option("--lens", c.imageOptions.lens,
                        "lens values that replace the file's or the camera's: fNumber=N,focus=D,shutter=DEG "
                        "(any of them), e.g. --lens fNumber=2.8,focus=3.5");
    c.image
        ->add_option("--write-aux", c.imageOptions.writeAux,
                     "write each frame's decoded depth (linear view), normals (view space) and motion (UV, "
                     "y up) as DIR/NAME.aux.exr")
        ->check(kOutputPath);
    c.image
        ->add_option("--jitter", c.imageOptions.jitter,
                     "how a sequence's frames were jittered, for TAA and the motion unjitter: attribute (the "
                     "EXR `jitter` attribute, pixels, x right, y down; none when absent) or halton "
                     "(Photopic's Halton(2,3) from index 1, as Pipeline::beginFrame hands it out)")
        ->check(CLI::IsMember({"attribute", "halton"}));
    addChannelOptions(c.image, c.imageOptions.aovPreset, c.imageOptions.layer, c.imageOptions.aovs);
    addSettingsOptions(c.image, c.imageOptions.settings, "stills");
    addOcioOptions(c.image, c.imageOptions.ocio);
    addMaxPixelsOption(c.image, c.imageOptions.maxPixels);
    c.image
        ->add_option(
            "--frames-in-flight", c.imageOptions.inFlight,
            "frames of a sequence between decode and write at once: 1 decodes, processes and writes "
            "each frame before the next; more decode the next frame (from 4 on, the next two) and write "
            "earlier ones on other threads (same outputs, bounded memory); default 3 with up to 4 cores, "
            "else half the cores, at most 8")
        ->check(CLI::Range(1, 16));
    c.image
        ->add_option("--decode-threads", c.imageOptions.decodeThreads,
                     "threads that decode each EXR frame's chunks (OpenEXR's thread pool): 0 decodes on the "
                     "thread that reads the frame; default every core, or 0 with --frames-in-flight 1; the "
                     "pixels are the same whatever the count")
        ->check(CLI::Range(0, 256));
    c.image
        ->add_option(
            "--exposure-track", c.imageOptions.exposureTrack,
            "each frame's auto exposure from a plan of the whole sequence (photopic expose) instead of "
            "this run's adaptation, so a chunk renders the single run's frames (docs/farm.md)")
        ->check(CLI::ExistingFile);
    c.image
        ->add_option(
            "--preroll", c.imageOptions.preroll,
            "process the N frames before the first of --frames without writing them, so TAA, the "
            "reflections' and volumetric light's histories, the previous camera and exposure are warm "
            "at a chunk's first frame (never past a cut of --exposure-track)")
        ->check(CLI::Range(0, 1000));
    c.image->footer(
        "Examples:\n"
        "  photopic image in.exr -o out.png --tonemap agx --exposure -1.5\n"
        "  photopic image in.exr -o out.png --preset realtime    the scenes' soft glow instead of stills\n"
        "  photopic image f*.exr -o dir/ --fps 24 --telemetry t.csv --set autoExposure.enabled=true\n"
        "  photopic image shot/f%04d.exr --frames 1001-1100 -o out/f%04d.png -n\n"
        "  photopic image shot/f%04d.exr --frames 1101-1200 --preroll 24 --exposure-track exposure.csv -o "
        "out/f%04d.png\n"
        "  photopic image in.exr -o out.tif --bit-depth 16\n"
        "  photopic image in.exr -o out.jpg --jpeg-quality 90\n"
        "  photopic image in.exr -o - | display -\n"
        "  photopic image in.exr -o view.png --debug histogram\n"
        "  photopic image render/frame_%04d.exr --camera track.json --set dof.enabled=true -o out/f%04d.png\n"
        "  photopic image in.exr -o out.png --ocio-config config.ocio --ocio-display sRGB --ocio-view "
        "Standard");
}

void addSettingsCommand(CLI::App& app, Cli& c) {
    c.settings = app.add_subcommand(
        "settings", "print the default settings, check a settings file or print the settings reference");
    auto* defaultsFlag = c.settings->add_flag("--defaults", c.defaults, "print the full default JSON");
    auto* checkOption = c.settings->add_option("--check", c.checkFile, "validate FILE and list every issue");
    auto* markdownFlag = c.settings->add_flag(
        "--markdown", c.markdown,
        "print the reference of every setting (key, type, default, range, meaning) as Markdown: "
        "docs/settings.md");
    defaultsFlag->excludes(checkOption);
    markdownFlag->excludes(defaultsFlag, checkOption);
    c.settings->add_option("--preset", c.settingsPreset,
                           "with --defaults: the defaults with this look (" + joined(presetNames()) +
                               "); with --check: the file over this look, as --preset reads it");
    c.settings->require_option(1, 2);
    c.settings->footer("Examples:\n"
                       "  photopic settings --defaults > mine.json\n"
                       "  photopic settings --defaults --preset stills   what photopic image starts from\n"
                       "  photopic settings --check mine.json\n"
                       "  photopic settings --markdown > docs/settings.md");
}

void addSceneCommand(CLI::App& app, Cli& c) {
    c.scene = app.add_subcommand("scene", "render a built-in scene's frames and telemetry.csv");
    c.scene->add_option("name", c.sceneOptions.name,
                        "scene name: " + builtInSceneNames() +
                            " (photopic scene --list says what each shows)");
    c.scene->add_flag("--list", c.listScenes, "list the built-in scenes");
    c.scene->add_option("-o,--output", c.sceneOptions.output, "output folder (default out/scene-NAME)")
        ->check(kOutputPath);
    c.scene->add_option("--frames", c.sceneOptions.frames, "number of frames")->check(CLI::Range(1, 100000));
    c.scene->add_option("--fps", c.sceneOptions.fps, "frame rate")->check(CLI::Range(0.001f, 10000.0f));
    c.scene->add_option("--size", c.sceneOptions.size, "WIDTHxHEIGHT");
    c.scene
        ->add_option("--format", c.sceneOptions.format,
                     "frame files: png, tif, tiff, jpg, jpeg (display) or exr (scene-referred)")
        ->check(CLI::IsMember(kFrameFormats))
        ->capture_default_str();
    addDisplayEncodingOptions(c.scene, c.sceneOptions.bitDepth, c.sceneOptions.jpegQuality);
    c.scene->add_flag("--force-ldr", c.sceneOptions.forceLdr, "run the LDR (RGBA8) path");
    c.scene
        ->add_option("--every", c.sceneOptions.every, "write every Nth frame (telemetry keeps every frame)")
        ->check(CLI::Range(1, 100000));
    c.scene->add_flag("--report-rss", c.sceneOptions.reportRss,
                      "print resident memory (VmRSS) after the first and the last frame");
    c.scene->add_option("--canvas", c.sceneOptions.canvasColor, "canvas scene: the painting's colour image");
    c.scene->add_option("--material", c.sceneOptions.canvasMaterial,
                        "canvas scene: material PNG (RGBA: normal x, y; shininess; glitter mask)");
    c.scene->add_option("--motion", c.sceneOptions.motion,
                        "canvas scene: device motion CSV, header time_s,pitch,roll,yaw: seconds, then "
                        "radians (examples/canvas-motion/tilt.csv)");
    c.scene->add_option("--model", c.sceneOptions.model,
                        "orbit scene: a glTF 2.0 model (.gltf or .glb) in place of the ship (= --set "
                        "orbit.model=FILE)");
    c.scene->add_option("--env", c.sceneOptions.env,
                        "orbit scene: an equirectangular HDR image (.exr, .hdr) for the image-based light "
                        "(= --set orbit.env=FILE)");
    c.scene->add_option("--truth", c.sceneOptions.truth,
                        "testbed scene: write the CPU ray tracer's KIND (" +
                            joined(testbed::allTruthKinds() | std::views::transform(testbed::truthKindName)) +
                            ", or all) for the frames instead of rendering");
    c.scene->add_option("--start", c.sceneOptions.start, "first frame index (--truth)")
        ->check(CLI::Range(0, 10000000));
    addSettingsOptions(c.scene, c.sceneOptions.settings, "the scene's own look (realtime)");
    c.scene->footer("Examples:\n"
                    "  photopic scene --list\n"
                    "  photopic scene canvas -o out/canvas --frames 60 --size 960x540 --motion "
                    "examples/canvas-motion/tilt.csv\n"
                    "  photopic scene testbed -o out/testbed --frames 48 --tonemap agx --debug normals\n"
                    "  photopic scene orbit -o out/orbit --model data/gltf/2CylinderEngine.glb --set "
                    "orbit.post=raw");
}

void addDemoCommand(CLI::App& app, Cli& c) {
    c.demo = app.add_subcommand(
        "demo", "the main demo: the tabletop walk (eye adaptation) into out/demo (or -o DIR)");
    c.demo->add_option("-o,--output", c.walk.output, "output folder")->check(kOutputPath);
    c.demo->add_option("--size", c.demoSize, "WIDTHxHEIGHT")->capture_default_str();
    c.demo->add_option("--fps", c.walk.fps, "frame rate")
        ->check(CLI::Range(1.0f, 240.0f))
        ->capture_default_str();
    c.demo->add_option("--seconds", c.demoSeconds, "length (default: the walk 22, orbit 12)")
        ->check(CLI::Range(0.1f, 600.0f));
    c.demo
        ->add_option("--scene", c.demoScene,
                     "tabletop (default): the walk; orbit: the spacecraft's pass through the planet's "
                     "shadow")
        ->check(CLI::IsMember({"tabletop", "orbit"}))
        ->capture_default_str();
    c.demo->add_option("--every", c.walk.frameEvery, "write every Nth frame as PNG")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    c.demo->add_flag("--no-video", c.noVideo, "do not encode demo.mp4 even when ffmpeg is present");
    c.demo->add_flag("--images", c.demoImages,
                     "the former demo instead: every HDR image in --data through three tone curves");
    c.demo->add_option("--data", c.demoData,
                       "folder of HDR images for --images (default: $PHOTOPIC_DATA_DIR, else the installed "
                       "share/photopic/data, else the checkout's data/)");
    c.demo->add_option("--preset", c.walk.preset, presetHelp("realtime (the tabletop scene's look)"));
    addMaxPixelsOption(c.demo, c.demoMaxPixels);
    c.demo->footer("Examples:\n"
                   "  photopic demo                                  the walk at 320x180 into out/demo\n"
                   "  photopic demo --size 960x540 --fps 60 -o out/big\n"
                   "  photopic demo --scene orbit                    the orbit pass into out/demo-orbit\n"
                   "  photopic demo --images --data data/            the contact sheet of every HDR image");
}

void addBenchCommand(CLI::App& app, Cli& c) {
    c.bench = app.add_subcommand("bench", "per-pass GPU timings (median ms, bytes moved, GB/s) over N "
                                          "frames of a synthetic HDR frame or --input FILE, or the canvas "
                                          "scene's shading paths (--scene canvas)");
    c.bench
        ->add_option("--size", c.benchOptions.size,
                     "WxH of the synthetic frame; with --input, the image is mirrored (repeated, every other "
                     "copy flipped) or cropped to this size, for natural content at any size")
        ->each([&c](const std::string&) { c.benchOptions.sizeGiven = true; })
        ->capture_default_str();
    c.bench->add_option("--frames", c.benchOptions.frames, "timed frames after the warm-up")
        ->check(CLI::Range(1, 100000))
        ->capture_default_str();
    c.bench->add_option("--warmup", c.benchOptions.warmup, "untimed frames first")
        ->check(CLI::Range(0, 1000));
    c.bench
        ->add_option("--input", c.benchOptions.input,
                     "an HDR image (EXR, HDR) instead of the synthetic frame")
        ->check(CLI::ExistingFile);
    c.bench
        ->add_option("--input-format", c.benchOptions.inputFormat,
                     "the input texture's format: rgba32f, or rgba16f (a renderer's usual scene colour, half "
                     "the bytes for the first passes to read); the bandwidth reference copies this format")
        ->check(CLI::IsMember({"rgba32f", "rgba16f"}))
        ->capture_default_str();
    c.bench->add_option("--json", c.benchOptions.json, "also write the table as JSON to FILE (atomically)")
        ->check(kOutputPath);
    c.bench->add_flag("--force-ldr", c.benchOptions.forceLdr, "run the LDR (RGBA8) path");
    CLI::Option* sync = c.bench->add_flag(
        "--sync", c.benchOptions.sync,
        "debug: glFinish() around every pass and report its wall time too (stalls each pass; for drivers "
        "whose timer queries miss deferred work, e.g. llvmpipe)");
    c.bench
        ->add_flag("--queue-ahead", c.benchOptions.queueAhead,
                   "keep the GPU busy with untimed work while the CPU submits each timed frame, so the "
                   "timestamps hold the GPU's own work and not its waits for the CPU (a GPU's figure)")
        ->excludes(sync);
    c.bench->add_option("--scene", c.benchOptions.scene,
                        "canvas (the only one): time the canvas scene's tiled and full-screen shading paths "
                        "instead (--set canvas.KEY=VALUE, e.g. canvas.occupancy=0.3, the default)");
    addSettingsOptions(c.bench, c.benchOptions.settings, "the defaults (realtime)");
    addMaxPixelsOption(c.bench, c.benchOptions.maxPixels);
    c.bench->footer("Examples:\n"
                    "  photopic bench --size 1920x1080 --frames 100\n"
                    "  photopic bench --input data/Desk.exr --json timings.json\n"
                    "  photopic bench --input data/GoldenGate.exr --size 3840x2160 --queue-ahead\n"
                    "  photopic bench --scene canvas --set canvas.occupancy=0.3");
}

/// The inputs of a sequence: files or patterns, --frames, --start-number (as `photopic image` takes them).
void addSequenceInputs(CLI::App* cmd, ImageOptions& o) {
    cmd->add_option("inputs", o.inputs,
                    "input images, or frame-numbered patterns when no such file exists (f%04d.exr, "
                    "f.####.exr, f@.exr), as photopic image takes them")
        ->required();
    auto* frames = cmd->add_option("--frames", o.frames, "frames A-B of a pattern input, inclusive");
    cmd->add_option("--start-number", o.startNumber, "a pattern input's first frame")
        ->check(CLI::NonNegativeNumber)
        ->excludes(frames);
}

void addMeterCommand(CLI::App& app, Cli& c) {
    c.meter =
        app.add_subcommand("meter", "meter each frame of a sequence for photopic expose: one CSV row "
                                    "per frame (the reading, the histogram's bins); chunks of a sequence "
                                    "metered apart merge into the whole sequence's metering");
    addSequenceInputs(c.meter, c.meterOptions);
    c.meter->add_option("-o,--output", c.meterOptions.output, "the meter CSV")
        ->check(kOutputPath)
        ->required();
    c.meter->add_option("--fps", c.meterOptions.fps, "frame rate (exposure.mode physical: the shutter angle)")
        ->check(CLI::Range(0.001f, 10000.0f));
    c.meter
        ->add_option("--camera", c.meterOptions.camera,
                     "camera JSON or track for EXR inputs without camera attributes")
        ->check(CLI::ExistingFile);
    addChannelOptions(c.meter, c.meterOptions.aovPreset, c.meterOptions.layer, c.meterOptions.aovs);
    c.meter->add_flag("--force-ldr", c.meterOptions.forceLdr, "run the LDR (RGBA8) path");
    addSettingsOptions(c.meter, c.meterOptions.settings, "stills (as photopic image)");
    addMaxPixelsOption(c.meter, c.meterOptions.maxPixels);
    c.meter->footer(
        "Examples:\n"
        "  photopic meter shot/f%04d.exr --frames 1001-1100 --settings look.json -o meter-1001.csv\n"
        "  photopic meter shot/f%04d.exr --set autoExposure.metering=histogram -o meter.csv");
}

void addExposeCommand(CLI::App& app, Cli& c) {
    c.expose =
        app.add_subcommand("expose", "plan a sequence's auto exposure from its meter CSVs: the exposure "
                                     "controller over every frame in order, one row per frame, for "
                                     "photopic image --exposure-track");
    c.expose->add_option("meter", c.exposeOptions.meterFiles, "meter CSVs (photopic meter), in any order")
        ->required()
        ->check(CLI::ExistingFile);
    c.expose->add_option("-o,--output", c.exposeOptions.output, "the exposure track CSV")
        ->check(kOutputPath)
        ->required();
    c.expose->add_option("--fps", c.exposeOptions.fps, "frame rate: one frame is 1/fps seconds of adaptation")
        ->check(CLI::Range(0.001f, 10000.0f))
        ->capture_default_str();
    c.expose
        ->add_option("--cut", c.exposeOptions.cuts,
                     "a frame where exposure snaps to its target (a camera cut; photopic image "
                     "--exposure-track restarts the histories there too); repeatable")
        ->take_all()
        ->allow_extra_args(false);
    c.expose->add_flag(
        "--allow-gaps", c.exposeOptions.allowGaps,
        "plan over frames missing from the meter files as photopic image runs over a pattern's "
        "gaps (one frame time apart); without it a missing frame is an error");
    addSettingsOptions(c.expose, c.exposeOptions.settings, "stills (as photopic image)");
    c.expose->footer(
        "Examples:\n"
        "  photopic expose meter-*.csv --fps 24 --settings look.json -o exposure.csv\n"
        "  photopic expose meter.csv --fps 24 --cut 1040 --set autoExposure.enabled=true -o e.csv");
}

void addFarmCommand(CLI::App& app, Cli& c) {
    FarmOptions& o = c.farmOptions;
    c.farm =
        app.add_subcommand("farm", "write a sequence's meter, expose and render stages as a Slurm job set "
                                   "(job arrays with afterok dependencies), and submit it with --submit");
    c.farm->add_option("input", o.input, "the sequence: a frame-numbered pattern (shot/f%04d.exr)")
        ->required();
    c.farm->add_option("-o,--output", o.output, "the output pattern (out/f%04d.png)")
        ->check(kOutputPath)
        ->required();
    c.farm->add_option("--jobs", o.jobDir, "folder for the job scripts, settings, meter files and logs")
        ->check(kOutputPath)
        ->required();
    c.farm->add_option("--frames", o.frames, "frames A-B (default: every frame of the pattern)");
    c.farm->add_option("--chunk", o.chunk, "frames per meter and render job")
        ->check(CLI::Range(1, 1000000))
        ->capture_default_str();
    c.farm
        ->add_option("--preroll", o.preroll,
                     "frames each render job processes before its chunk (default " +
                         std::to_string(kDefaultFarmPreroll) + ")")
        ->check(CLI::Range(0, 1000));
    c.farm->add_option("--fps", o.fps, "frame rate")
        ->check(CLI::Range(0.001f, 10000.0f))
        ->capture_default_str();
    c.farm
        ->add_option("--cut", o.cuts,
                     "a camera cut: exposure snaps and the histories (TAA, SSR, motion blur) restart there, "
                     "and no preroll reaches back past it; repeatable")
        ->take_all()
        ->allow_extra_args(false);
    c.farm->add_option(
        "--photopic", o.photopic,
        "the photopic command the jobs run (default: this program's path, which the nodes must "
        "see)");
    c.farm
        ->add_option("--sbatch-option", o.sbatchOptions,
                     "an #SBATCH line for every job, e.g. --sbatch-option=--partition=render; repeatable")
        ->take_all()
        ->allow_extra_args(false);
    c.farm
        ->add_option("--image-option", o.imageOptions,
                     "an option for each render's photopic image, e.g. --image-option=--bit-depth "
                     "--image-option=16; repeatable")
        ->take_all()
        ->allow_extra_args(false);
    c.farm->add_flag("--submit", o.submit, "submit the job set with sbatch now (else print the commands)");
    addSettingsOptions(c.farm, o.settings, "stills (as photopic image)");
    c.farm->footer(
        "Examples:\n"
        "  photopic farm shot/f%04d.exr -o out/f%04d.png --jobs farm/ --chunk 100 --fps 24 "
        "--settings look.json --submit\n"
        "  photopic farm shot/f%04d.exr -o out/f%04d.png --jobs farm/ --sbatch-option=--partition=gpu");
}

/// Runs the subcommand that was parsed; throws the errors main() turns into exit codes.
int runCommand(Cli& c) {
    if (*c.info) {
        return runInfo(c.forceLdr, c.infoSettings);
    }
    if (*c.image) {
        return runImage(c.imageOptions);
    }
    if (*c.settings) {
        if (c.markdown) {
            if (!c.settingsPreset.empty()) {
                throw InputError("settings: --markdown lists every preset; --preset does not apply");
            }
            std::fputs(settingsReferenceMarkdown().c_str(), stdout);
            return kOk;
        }
        if (!c.defaults && c.checkFile.empty()) {
            throw InputError("settings: --defaults, --check FILE or --markdown is required");
        }
        return c.defaults ? runSettingsDefaults(c.settingsPreset)
                          : runSettingsCheck(c.checkFile, c.settingsPreset);
    }
    if (*c.scene) {
        if (c.listScenes) {
            for (const auto& s : builtInScenes()) {
                std::printf("%-10s %s\n", s.name.c_str(), s.description.c_str());
            }
            return kOk;
        }
        if (c.sceneOptions.name.empty()) {
            throw InputError("scene: a scene name is required (photopic scene --list)");
        }
        return runScene(c.sceneOptions);
    }
    if (*c.bench) {
        return runBench(c.benchOptions);
    }
    if (*c.meter) {
        return MeterCommand(c.meterOptions).run();
    }
    if (*c.expose) {
        return ExposeCommand(c.exposeOptions).run();
    }
    if (*c.farm) {
        return FarmCommand(c.farmOptions).run();
    }
    if (*c.demo) {
        if (c.demoImages) {
            const Settings look = c.walk.preset.empty() ? Settings{} : presetLook(c.walk.preset);
            return runDemo(findDataDir(c.demoData), c.walk.output, c.demoMaxPixels, look);
        }
        const Extent size = parseSize(c.demoSize);
        if (c.demoScene == "orbit") {
            OrbitDemoOptions orbit;
            if (c.demo->count("--output") > 0) {
                orbit.output = c.walk.output;
            }
            orbit.width = size.width;
            orbit.height = size.height;
            orbit.fps = c.walk.fps;
            orbit.seconds = c.demoSeconds.value_or(orbit.seconds);
            orbit.frameEvery = c.walk.frameEvery;
            orbit.video = !c.noVideo;
            orbit.preset = c.walk.preset;
            return runOrbitDemo(orbit);
        }
        c.walk.seconds = c.demoSeconds.value_or(c.walk.seconds);
        c.walk.width = size.width;
        c.walk.height = size.height;
        c.walk.video = !c.noVideo;
        return runTabletopWalk(c.walk);
    }
    return kFailure;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"Photopic: HDR post-processing and eye adaptation on OpenGL 4.5"};
    app.set_version_flag("--version", std::string("photopic ") + PHOTOPIC_VERSION);
    app.require_subcommand(1);
    Cli c;
    addInfoCommand(app, c);
    addImageCommand(app, c);
    addSettingsCommand(app, c);
    addSceneCommand(app, c);
    addDemoCommand(app, c);
    addBenchCommand(app, c);
    addMeterCommand(app, c);
    addExposeCommand(app, c);
    addFarmCommand(app, c);
    // -q, -v and --log-level read the same before or after the subcommand's name.
    addVerbosityOptions(app, c.verbosity);
    for (CLI::App* sub : {c.info, c.image, c.settings, c.scene, c.demo, c.bench, c.meter, c.expose, c.farm}) {
        addVerbosityOptions(*sub, c.verbosity);
    }
    // A KHR_debug context costs CPU time in every GL call on some drivers: only when asked for.
    const auto addGlDebug = [&c](CLI::App& a) {
        a.add_flag("--gl-debug", c.glDebug,
                   "a KHR_debug context whose driver messages (errors, performance warnings) reach the log; "
                   "also PHOTOPIC_GL_DEBUG=1");
    };
    addGlDebug(app);
    for (CLI::App* sub : {c.info, c.image, c.scene, c.demo, c.bench, c.meter}) {
        addGlDebug(*sub);
    }
    app.footer("Examples:\n"
               "  photopic image in.exr -o out.png --tonemap agx\n"
               "  photopic scene canvas -o out/canvas --motion examples/canvas-motion/tilt.csv\n"
               "  photopic demo -q\n"
               "photopic COMMAND --help: each command's options and examples");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? kOk : kBadInput;
    }
    applyVerbosity(c.verbosity);
    setStatusLines(!c.verbosity.quiet &&
                   (c.verbosity.verbose || (c.verbosity.level != "warning" && c.verbosity.level != "error")));
    setGlDebug(c.glDebug);
    Progress::setEnabled(!c.verbosity.quiet);
    try {
        return runCommand(c);
    } catch (const Interrupted& e) {
        // The outputs were taken back on the way here (RunOutputs), as after any failure.
        std::fprintf(stderr, "photopic: interrupted by %s; the run's outputs were taken back\n",
                     signalName(e.signal));
        return 128 + e.signal;
    } catch (const InputError& e) {
        std::fprintf(stderr, "photopic: %s\n", e.what());
        return kBadInput;
    } catch (const SettingsError& e) {
        std::fprintf(stderr, "photopic: %s", e.what());
        return kBadInput;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "photopic: %s\n", e.what());
        return kFailure;
    }
}
