#pragma once
// What the photopic CLI's commands share: the exit codes, the settings sources, the image and scene
// options, the GL context they open. Each command is a class of its own (Command.h); its run() returns the
// process exit code: 0 ok, 2 bad usage or input, 1 other failure.

#include "InputError.h"
#include "OcioDisplay.h"

#include "core/Settings.h"
#include "gl/Context.h"
#include "io/DisplayImageIO.h"
#include "io/ImageIO.h"
#include "pipeline/Pipeline.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace photopic::cli {

enum ExitCode : int { kOk = 0, kFailure = 1, kBadInput = 2 };

/// Settings from `base` with the preset's look (--preset NAME, else the file's "preset", else the command's
/// own), then --settings FILE's other keys over it, then the shorthand flags, then each --set in order.
struct SettingsSources {
    std::string preset; ///< --preset NAME (presetNames()); empty: the file's, else none
    std::filesystem::path file;
    std::string tonemap;
    std::optional<float> exposure;
    std::string debugView; ///< same as --set debug.view=NAME
    std::vector<std::string> overrides;
};
Settings resolveSettings(const SettingsSources& sources, Settings base = {});

/// Whether the status lines (each frame written, a command's summary) are printed: not under -q or
/// --log-level warning/error, which print errors (and warnings) only, as ffmpeg's -loglevel does. What a
/// command was asked to print (--info, settings, bench tables) is printed whatever the level. Set once
/// from the command line (main), true until then.
[[nodiscard]] bool statusLines();
void setStatusLines(bool on);

struct ImageOptions {
    /// Files, or frame-numbered patterns (f%04d.exr, f.####.exr, f@.exr) expanded from their folder; a
    /// name that exists as a file is a file.
    std::vector<std::filesystem::path> inputs;
    std::string frames; ///< --frames A-B: every frame of the range, inclusive; empty: none
    std::optional<std::int64_t> startNumber; ///< --start-number N: a pattern's frames from N on
    /// A file (.png, .tif, .tiff, .jpg, .jpeg: the display image; .exr: scene-referred), a folder (a trailing
    /// '/', no extension, or several inputs), a pattern (out/f%04d.png) or a stream ("-", a device, a pipe:
    /// one input, PNG).
    std::filesystem::path output;
    bool noOverwrite = false;   ///< -n: an output that exists already is refused before any work
    std::string format = "png"; ///< for folder outputs: png, tif, tiff, jpg, jpeg or exr
    /// --bit-depth 8|16: output.bitDepth, the display image's bits per channel (and its PNG/TIFF files');
    /// unset: the settings' value.
    std::optional<int> bitDepth;
    int jpegQuality = kDefaultJpegQuality; ///< --jpeg-quality, [1, 100], default 95
    SettingsSources settings;
    bool forceLdr = false;
    float fps = 30.0f;
    std::filesystem::path telemetry; ///< CSV, one row per frame; empty: none
    bool info = false; ///< list each input's channels and attributes and what they feed; no rendering
    std::filesystem::path camera; ///< camera JSON for EXR files without camera attributes; empty: none
    /// --aovs NAME, --layer NAME, --aov KIND=CHANNELS[:CONVENTIONS] (repeatable): which channels of an EXR
    /// feed what (io/ExrChannels.h, docs/interop.md); empty: the file's own preset and only layer.
    std::string aovPreset;
    std::string layer;
    std::vector<std::string> aovs;
    std::string
        lens; ///< --lens fNumber=..,focus=..,shutter=..: replaces each frame's lens values; empty: none
    std::filesystem::path writeAux; ///< folder for the decoded depth/normals/motion; empty: none
    std::string jitter =
        "attribute"; ///< attribute: the EXR `jitter` attribute when present; halton: Photopic's
    std::int64_t maxPixels = kDefaultMaxPixels; ///< larger inputs are refused before they are decoded
    /// --ocio-config/--ocio-display/--ocio-view: the display image from an OpenColorIO display/view transform
    /// of the scene-referred image instead of Photopic's tone curve and sRGB output.
    OcioOptions ocio;
    /// Frames between decode and write at once, [1, 16]: 1 runs each frame's decode, GPU work and write one
    /// after another; more decode one frame ahead and write up to N - 2 (at least one) behind on other
    /// threads. 0: defaultFramesInFlight().
    int inFlight = 0;
    /// Threads of OpenEXR's pool that decode a frame's chunks, [0, 256]: 0 decodes on the thread that reads
    /// the frame. -1: every core, or 0 with one frame in flight.
    int decodeThreads = -1;
    /// --exposure-track FILE: each frame's auto exposure from a plan of the whole sequence (`photopic
    /// expose`) instead of this run's adaptation; empty: none.
    std::filesystem::path exposureTrack;
    /// --preroll N: the N frames before the first of --frames are processed first, not written, so the
    /// histories (TAA, SSR, volumetric light, motion, exposure) are warm at a chunk's border.
    int preroll = 0;
};

struct SceneOptions {
    std::string name;
    std::filesystem::path output; ///< folder; default out/scene-NAME
    int frames = 60;
    float fps = 30.0f;
    std::string size = "640x360"; ///< WxH
    std::string format = "png";   ///< frames as png, tif, tiff, jpg, jpeg (display) or exr (scene-referred)
    std::optional<int> bitDepth;  ///< --bit-depth 8|16: output.bitDepth; unset: the settings' value
    int jpegQuality = kDefaultJpegQuality; ///< --jpeg-quality, [1, 100], default 95
    SettingsSources settings; ///< --set NAME.key=value goes to the scene, other paths to the post settings
    bool forceLdr = false;
    std::string canvasColor;    ///< --canvas FILE: canvas scene only, = --set canvas.colour=FILE
    std::string canvasMaterial; ///< --material FILE: canvas scene only, = --set canvas.material=FILE
    std::string motion;         ///< --motion FILE.csv: canvas scene only, = --set canvas.motion=FILE
    std::string model;          ///< --model FILE: orbit scene only, = --set orbit.model=FILE
    std::string env;            ///< --env FILE: orbit scene only, = --set orbit.env=FILE
    std::string truth;          ///< --truth KIND|all: testbed scene only, write ray-traced references instead
    int start = 0;              ///< --start N: the first frame index (--truth)
    int every = 1;              ///< write every Nth frame (frame_0000 is frame 0, frame_0001 frame N, ...)
    bool reportRss = false;     ///< print resident memory after the first and the last frame (soak test)
};

/// "1920x1080" -> {1920, 1080} with each side in [minSide, 16384]; throws InputError naming the text.
Extent parseSize(const std::string& text, int minSide = 1);

/// Telemetry CSV: frame,time_s, then the scene's own columns (if any), then the exposure columns, whose first
/// four are measured_luma,target_log2,applied_log2,exposure. One row per record; `sceneValues[frame]` holds
/// the scene's values of that frame.
std::string telemetryCsv(const std::vector<ExposureTelemetry>& rows, float dt,
                         const std::vector<std::string>& sceneColumns,
                         const std::vector<std::vector<double>>& sceneValues);

/// One row of that CSV, newline included.
std::string telemetryCsvRow(const ExposureTelemetry& t, float dt, std::size_t sceneColumns,
                            const std::vector<double>& sceneValues);

/// The look of preset `name` (presetNames()); throws InputError listing the presets when there is none.
Settings presetLook(const std::string& name);
/// `demo --images`: every HDR image in `dataDir` through three tone curves, with `look`'s look.
int runDemo(const std::filesystem::path& dataDir, const std::filesystem::path& outDir,
            std::int64_t maxPixels = kDefaultMaxPixels, const Settings& look = {});

/// Throws InputError (exit 2) naming the first of `outputs` whose format cannot hold `bitDepth` bits per
/// channel (a JPEG at 16), before any work; `source` names where the depth came from ("--bit-depth").
void requireBitDepthFits(const std::vector<std::filesystem::path>& outputs, int bitDepth,
                         std::string_view source);

/// Reads an input image, as bad input (InputError, exit 2) when it cannot be.
ImageF readInput(const std::filesystem::path& path, std::int64_t maxPixels);
/// Throws InputError naming `path` and the limit when the image is larger than the GPU's GL_MAX_TEXTURE_SIZE
/// (needs a current context; creates no GL object). Such an image is refused, not split into tiles: bloom
/// and metering are whole-image operations.
void requireTextureFits(const std::filesystem::path& path, int width, int height);

/// The headless context every command makes: a production context, or with --gl-debug (or
/// PHOTOPIC_GL_DEBUG=1 in the environment) a KHR_debug context whose driver messages reach the log.
HeadlessContextCreateInfo commandContext();
/// --gl-debug, before a command runs.
void setGlDebug(bool on);

/// Frames in flight when `--frames-in-flight` is not given: 3 with up to 4 cores, else half the cores, at
/// most 8: PNG encodes side by side pay until then, and more frames cost memory for little
/// (docs/bench/LOG.md).
int defaultFramesInFlight();

} // namespace photopic::cli
