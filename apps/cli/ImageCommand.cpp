// `photopic image`: inputs (files, patterns, layers, cameras), outputs planned and checked before the first
// frame, the settings, the pipeline and the streamed sequence (decode, GPU, encode in flight together).
#include "Commands.h"

#include "Bench.h"
#include "Interrupt.h"
#include "Progress.h"

#include "FrameStream.h"
#include "ImageInputs.h"
#include "InputSequence.h"
#include "Outputs.h"
#include "TelemetryCsv.h"

#include "common/ExposureTrack.h"
#include "common/SequencePattern.h"
#include "core/Environment.h"
#include "core/Log.h"
#include "core/settings/SettingsJson.h"
#include "gl/Context.h"
#include "gl/Gl.h"
#include "gl/TextureReadback.h"
#include "io/ImageIO.h"
#include "pipeline/Pipeline.h"

#include <fmt/format.h>

#include <algorithm>
#include <bitset>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <tuple>

namespace photopic::cli {

namespace fs = std::filesystem;

namespace {

std::string lowerExtension(const fs::path& p) {
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

} // namespace

// A JPEG holds 8 bits per channel: a 16-bit display image bound for one is refused rather than narrowed
// without a word.
void requireBitDepthFits(const std::vector<fs::path>& outputs, int bitDepth, std::string_view source) {
    for (const fs::path& out : outputs) {
        const std::optional<DisplayFileFormat> format = displayFileFormatFor(out);
        if (format && !holdsBitDepth(*format, bitDepth)) {
            throw InputError(fmt::format("output {}: {} holds 8 bits per channel only, but {} is {}: write "
                                         ".png or .tif for 16 bits, or use 8",
                                         out.string(), displayFileFormatName(*format), source, bitDepth));
        }
    }
}

ImageF readInput(const fs::path& path, std::int64_t maxPixels) {
    try {
        return readImage(path, {.maxPixels = maxPixels});
    } catch (const IoError& e) {
        throw InputError(e.what());
    }
}

void requireTextureFits(const fs::path& path, int width, int height) {
    GLint limit = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &limit);
    if (width > limit || height > limit) {
        throw InputError(fmt::format("\"{}\": image is {}x{}, larger than this GPU's largest texture ({}x{}, "
                                     "GL_MAX_TEXTURE_SIZE); scale it down first",
                                     path.string(), width, height, limit, limit));
    }
}

namespace {

/// The same file, whether or not it exists yet (links and relative paths resolved).
bool sameFile(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    if (fs::equivalent(a, b, ec)) {
        return true;
    }
    const fs::path ca = fs::weakly_canonical(a, ec);
    return !ec && ca == fs::weakly_canonical(b, ec) && !ec;
}

/// Refuses outputs that would destroy an input or each other: an output that is one of the inputs, and two
/// inputs whose results would land on the same file.
void requireDistinctOutputs(const std::vector<fs::path>& inputs, const std::vector<fs::path>& outputs) {
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        for (const fs::path& in : inputs) {
            if (sameFile(outputs[i], in)) {
                throw InputError(fmt::format("output {} is also an input; it would be overwritten: choose "
                                             "another output",
                                             outputs[i].string()));
            }
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (sameFile(outputs[i], outputs[j])) {
                throw InputError(fmt::format("inputs {} and {} would both be written to {}: give them "
                                             "different names or process them separately",
                                             inputs[j].string(), inputs[i].string(), outputs[i].string()));
            }
        }
    }
}

/// `-o -`, a device or a pipe: one image, as PNG (or EXR into a pipe named .exr), written as it is encoded.
fs::path streamOutput(const ImageOptions& options, std::size_t inputCount) {
    const fs::path& out = options.output;
    if (inputCount > 1) {
        throw InputError(
            fmt::format("output {} is a stream (standard output, a device or a pipe) and holds one "
                        "image, not {}: name a folder (-o out/) or a pattern (-o out/f%04d.png)",
                        out.string(), inputCount));
    }
    if (options.format != "png" && lowerExtension(out) != "." + options.format) {
        throw InputError(fmt::format("output {}: a stream carries the display image as PNG; --format {} "
                                     "needs a file or folder",
                                     out.string(), options.format));
    }
    return out;
}

void requireExtension(const fs::path& out) {
    const std::string ext = lowerExtension(out);
    if (!displayFileFormatFor(out) && ext != ".exr") {
        throw InputError(
            fmt::format("output {}: unsupported extension '{}' (use .png, .tif, .tiff, .jpg or .jpeg for the "
                        "display image, or .exr for the scene-referred image)",
                        out.string(), ext));
    }
}

/// The frame-number pattern of an output's file name (out/f%04d.png), if it holds one. A name with a '%' that
/// is no frame number ("50%.png") is an ordinary name, as it was before patterns.
std::optional<FramePattern> outputPattern(const fs::path& out) {
    try {
        return parseFramePattern(out.filename().string());
    } catch (const std::invalid_argument&) {
        return std::nullopt;
    }
}

/// `-n`: every output must be new.
void requireNew(const std::vector<fs::path>& paths) {
    for (const fs::path& path : paths) {
        std::error_code ec;
        if (fs::exists(fs::symlink_status(path, ec))) {
            throw InputError(fmt::format("output {} exists already (-n: never overwrite); remove it, choose "
                                         "another output, or leave out -n",
                                         path.string()));
        }
    }
}

/// Where runImage writes each input's result, every path checked before any work. The rules of -o: "-", a
/// device or a pipe is a stream; a name with a frame number (out/f%04d.png) is a pattern; an extension
/// means a file; a trailing '/', an existing folder, no extension or several inputs mean a folder. Several
/// inputs and the name of an image file (out.png, not an existing folder) are refused.
std::vector<fs::path> plannedOutputs(const ImageOptions& options, const std::vector<InputFile>& files,
                                     RunOutputs& outputs) {
    const fs::path& out = options.output;
    if (isStreamOutput(out)) {
        return {streamOutput(options, files.size())};
    }
    std::vector<fs::path> inputs;
    for (const InputFile& f : files) {
        inputs.push_back(f.path);
    }
    std::vector<fs::path> paths;
    fs::path folder; // made before the outputs are checked; empty: none
    if (const std::optional<FramePattern> pattern = outputPattern(out)) {
        requireExtension(out);
        for (const std::int64_t n : outputFrameNumbers(files)) {
            paths.push_back(out.parent_path() / pattern->name(n));
        }
        folder = out.parent_path();
    } else if (inputs.size() > 1 && !fs::is_directory(out) &&
               (displayFileFormatFor(out) || lowerExtension(out) == ".exr")) {
        // A name like out.png is one image; a folder of that name, made silently, is not what it asked for.
        throw InputError(fmt::format("output {} names one image file, and there are {} inputs: name a folder "
                                     "(-o out/) or a pattern (-o out/f%04d.png)",
                                     out.string(), inputs.size()));
    } else if (inputs.size() > 1 || fs::is_directory(out) || lowerExtension(out).empty()) {
        for (const fs::path& in : inputs) {
            paths.push_back(out / (in.stem().string() + "." + options.format));
        }
        folder = out;
    } else {
        requireExtension(out);
        paths.push_back(out);
    }
    requireDistinctOutputs(inputs, paths);
    if (options.noOverwrite) {
        requireNew(paths);
    }
    if (!folder.empty()) {
        outputs.makeFolder(folder);
    }
    for (const fs::path& path : paths) {
        RunOutputs::requireFile(path);
    }
    return paths;
}

} // namespace

std::unique_ptr<Pipeline> makeImagePipeline(const PipelineCreateInfo& createInfo) {
    try {
        return std::make_unique<Pipeline>(createInfo);
    } catch (const IoError& e) { // the metering mask named in the settings
        throw InputError(fmt::format("autoExposure.mask.path: {}", e.what()));
    }
}

Settings imageSettings(const ImageOptions& options) {
    // Photographs get the stills look unless --preset or the settings file names another. An image has no
    // lighting stage to hand ambient occlusion to, so it multiplies the scene colour unless the settings
    // say otherwise: no look sets ssao.apply (Settings::applyLook), so lighting over this base is the user's.
    Settings base = Settings::stills();
    base.ssao.apply = AoApply::Multiply;
    Settings settings = resolveSettings(options.settings, base);
    const bool lightingAsked = settings.ssao.apply == AoApply::Lighting;
    if (options.bitDepth) {
        settings.output.bitDepth = *options.bitDepth;
    }
    // Said in the CLI's words; the keys are the pipeline's own, so its host-API wording stays unsaid.
    if (settings.ssao.enabled && lightingAsked) {
        warnOnce("ssao.no-lighting",
                 "ssao.apply=lighting: an image has no lighting stage to hand ambient occlusion to, so none "
                 "is applied; ssao.apply=multiply (photopic image's default) multiplies the colour by it");
    }
    if (settings.contactShadows.enabled) {
        warnOnce("contactShadows.no-lighting",
                 "contactShadows.enabled: contact shadows darken a renderer's sun term as it lights the "
                 "scene, and an image's sun is already in its colour, so photopic image cannot apply them");
    }
    return settings;
}

namespace {

/// The setting that turns on the effect a data view shows, for the error of a view that could not be made.
const char* debugViewSwitch(DebugView view) {
    switch (view) {
    case DebugView::Ao:
        return "ssao.enabled=true";
    case DebugView::Coc:
        return "dof.enabled=true";
    case DebugView::Ssr:
        return "ssr.enabled=true";
    case DebugView::VelocityTiles:
        return "motionBlur.enabled=true";
    case DebugView::VolumetricLight:
        return "volumetricLight.enabled=true";
    case DebugView::TaaHistoryWeight:
    case DebugView::Disocclusion:
        return "aa.mode=taa";
    case DebugView::ContactShadows:
    case DebugView::ContactShadowSteps:
        return "a host's lighting stage (photopic scene; an image has none)";
    default:
        return nullptr;
    }
}

/// A debug view the frame cannot make is an error naming what it lacks, not the plain image the pipeline
/// would show instead.
void requireDebugViewMade(const Pipeline& pipeline, const Settings& settings, const fs::path& input) {
    if (settings.debug.view == DebugView::None)
        return;
    for (const SkippedPass& skipped : pipeline.status().skipped) {
        if (skipped.pass != "debug view")
            continue;
        std::string missing;
        for (const std::string& name : skipped.missing)
            missing += (missing.empty() ? "" : ", ") + name;
        const char* effect = debugViewSwitch(settings.debug.view);
        throw InputError(fmt::format(
            "--debug {}: {} gives the view no {}{}", debugViewNames()[std::size_t(settings.debug.view)],
            input.string(), missing, effect ? fmt::format(" (it shows what {} makes)", effect) : ""));
    }
}

/// The OpenColorIO display/view transform when --ocio-* asks for it, its config and names checked before
/// any output exists. It makes display images, so every output must be one (PNG, TIFF, JPEG).
std::optional<OcioDisplay> ocioDisplayFor(const ImageOptions& options) {
    if (!options.ocio.requested()) {
        return std::nullopt;
    }
    if (lowerExtension(options.output) == ".exr" || options.format == "exr") {
        throw InputError(
            fmt::format("output {}: --ocio-display/--ocio-view make the display image (PNG, TIFF, JPEG); "
                        "an EXR output holds the scene-referred image, which they do not change",
                        options.output.string()));
    }
    OcioDisplay ocio(options.ocio);
    logInfo("display image: {}", ocio.description());
    return ocio;
}

/// Starts reading back what `out` takes from the frame just processed (gl/TextureReadback.h): the
/// scene-referred colour for an EXR output or an OCIO display, else the display image at `bitDepth`.
void startReadBack(TextureReadback& readback, Pipeline& pipeline, const Texture& display, const fs::path& out,
                   int bitDepth, const OcioDisplay* ocio) {
    if (lowerExtension(out) == ".exr" || ocio != nullptr) {
        readback.start(pipeline.sceneReferred(), GL_FLOAT);
    } else {
        readback.start(display, bitDepth == 16 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_BYTE);
    }
}

/// Finishes the read startReadBack began for `out` into `image`, through the OCIO display when there is one.
void finishReadBack(TextureReadback& readback, const fs::path& out, int bitDepth, const OcioDisplay* ocio,
                    FrameImage& image) {
    if (lowerExtension(out) == ".exr") {
        readback.finish(image.scene);
    } else if (ocio != nullptr) {
        readback.finish(image.scene);
        if (bitDepth == 16) {
            image.display16 = ocio->apply16(image.scene);
        } else {
            image.display = ocio->apply(image.scene);
        }
    } else if (bitDepth == 16) {
        readback.finish(image.display16);
    } else {
        readback.finish(image.display);
    }
}

/// Prints "IN -> OUT (WxH, ms since the frame started)" once the frame is on disk, the progress line taken
/// off the terminal first and counted on after.
std::function<void()> writtenLine(const fs::path& in, const fs::path& out, Extent size,
                                  std::chrono::steady_clock::time_point start, Progress& progress,
                                  std::FILE* console) {
    return [&in, &out, size, start, &progress, console] {
        progress.clear();
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (statusLines()) {
            std::fprintf(console, "%s -> %s (%dx%d, %.1f ms)\n", in.string().c_str(), out.string().c_str(),
                         size.width, size.height, ms);
            std::fflush(console);
        }
        progress.advance();
    };
}

/// Frames in flight between the decode of one and the write of another: 1 is serial, else
/// framesDecodedAhead are decoded ahead and the rest (at least one) are being written behind the one on the
/// GPU.
std::size_t pendingWrites(int inFlight) {
    inFlight = inFlight > 0 ? inFlight : defaultFramesInFlight();
    return inFlight <= 1 ? 0 : std::size_t(std::max(inFlight - 1 - framesDecodedAhead(inFlight), 1));
}

/// Where the lines a run prints go: standard error when the image or the telemetry goes to standard output
/// (both there would interleave, and are refused).
std::FILE* consoleFor(const ImageOptions& options) {
    const bool imageToStdout = namesStandardOutput(options.output);
    const bool telemetryToStdout = !options.telemetry.empty() && namesStandardOutput(options.telemetry);
    if (imageToStdout && telemetryToStdout) {
        throw InputError(
            "the image and the telemetry cannot both go to standard output: name a file for one");
    }
    return imageToStdout || telemetryToStdout ? stderr : stdout;
}

/// `-n`: the telemetry CSV and the --write-aux files must be new too.
void requireNewSideOutputs(const ImageOptions& options, const std::vector<fs::path>& inputs) {
    std::vector<fs::path> paths;
    if (!options.telemetry.empty()) {
        paths.push_back(options.telemetry);
    }
    for (const fs::path& in : inputs) {
        if (!options.writeAux.empty()) {
            paths.push_back(options.writeAux / (in.stem().string() + ".aux.exr"));
        }
    }
    requireNew(paths);
}

/// The anti-aliasing an image run cannot do, turned off with one warning that says why and what runs
/// instead (SMAA under taa+smaa, else FXAA when its switch is on, else nothing): TAA gathers each pixel over
/// earlier frames, and a single image has none; SSAA renders each frame several times, which only the
/// renderer that made the image could.
void dropUnavailableAa(Settings& settings, std::size_t inputCount) {
    const AntiAliasing asked = settings.antiAliasing();
    std::string why;
    if (asked == AntiAliasing::Ssaa) {
        why = "SSAA renders each frame several times, which only the renderer that made an image can do, so "
              "it is off for images";
    } else if (settings.temporalAntiAliasing() && inputCount == 1) {
        why = "a single image has no earlier frames for TAA to gather, so TAA is off for it";
    } else {
        return;
    }
    settings.aa.mode = asked == AntiAliasing::TaaSmaa ? AntiAliasing::Smaa : AntiAliasing::None;
    settings.taa.enabled = false;
    const AntiAliasing now = settings.antiAliasing();
    logWarning("aa.mode {}: {}; {}", antiAliasingNames()[std::size_t(asked)], why,
               now == AntiAliasing::None
                   ? std::string("no anti-aliasing runs (aa.mode smaa or fxaa anti-alias images)")
                   : fmt::format("{} runs", antiAliasingNames()[std::size_t(now)]));
}

/// Where a sequence run's main thread spends each frame, and how long each frame's decode took on the thread
/// that decoded it, printed at the debug level (-v) once the run ends: the medians tell a user (and the
/// CLI's throughput work) whether decode, the upload, the GPU, the read-back or the PNG encode bounds the
/// rate.
class StageClock {
public:
    enum Stage { DecodeWait, Upload, Process, ReadBack, WriteWait, Decode, kStages };

    StageClock()
        : mLast(std::chrono::steady_clock::now())
        , mBegin(mLast) {}

    /// Charges the time since the last mark to `stage`.
    void mark(Stage stage) {
        const auto now = std::chrono::steady_clock::now();
        mSamples[stage].push_back(std::chrono::duration<double, std::milli>(now - mLast).count());
        mLast = now;
    }

    /// A time measured elsewhere (`Decode`: on the thread that decoded the frame).
    void add(Stage stage, double ms) { mSamples[stage].push_back(ms); }

    /// Restarts the clock without charging anything (the set-up before the first frame).
    void restart(const char* what) {
        const auto now = std::chrono::steady_clock::now();
        logDebug("image: {} {:.1f} ms", what, std::chrono::duration<double, std::milli>(now - mLast).count());
        mLast = now;
        mBegin = now;
    }

    void report(std::size_t frames) const {
        static constexpr const char* kNames[kStages] = {
            "waiting for decode", "upload", "process", "read-back", "waiting for encode", "decode"};
        std::string line;
        for (int s = 0; s < kStages; ++s) {
            if (mSamples[s].empty()) {
                continue;
            }
            // The decode is timed on the thread that decodes (the main thread only in a serial run).
            line += fmt::format("{}{} {:.2f}",
                                line.empty()  ? ""
                                : s == Decode ? "; "
                                              : ", ",
                                kNames[s], median(mSamples[s]));
        }
        const double total =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - mBegin).count();
        logDebug("image: {} frames in {:.1f} ms ({:.2f} ms a frame, the last encodes included); medians per "
                 "frame, ms: {} (on the decoding thread)",
                 frames, total, frames > 0 ? total / double(frames) : 0.0, line);
    }

private:
    std::chrono::steady_clock::time_point mLast;
    std::chrono::steady_clock::time_point mBegin;
    std::vector<double> mSamples[kStages];
};

/// The frames a run processes: --preroll's (processed, not written), then the ones it writes, each with its
/// frame number, which is its time (FrameTime::frameIndex, the telemetry's frame column): a frame renders the
/// same whichever chunk of its sequence it is run in.
struct RunFrames {
    std::vector<fs::path> inputs;
    std::vector<std::int64_t> numbers;
    std::size_t prerolled = 0;    ///< the first `prerolled` inputs are not written
    std::uint64_t firstIndex = 0; ///< the first input's place in its sequence (Halton jitter)
    /// Each input's own frame number, preroll included (inputFrameNumbers): what a camera track is keyed by.
    std::map<fs::path, std::int64_t> frameNumbers;
};

RunFrames runFrames(const ImageOptions& options, const std::vector<InputFile>& written) {
    std::vector<InputFile> all = prerollInputs(options, written, options.preroll);
    RunFrames run;
    run.prerolled = all.size();
    all.insert(all.end(), written.begin(), written.end());
    for (const InputFile& f : all) {
        run.inputs.push_back(f.path);
    }
    run.numbers = outputFrameNumbers(all);
    run.frameNumbers = inputFrameNumbers(all);
    if (const std::optional<std::int64_t> start = sequenceStart(options); start && all.front().frame) {
        run.firstIndex = std::uint64_t(*all.front().frame - *start);
    }
    return run;
}

/// --exposure-track: the track, checked to hold every frame the run processes before any work.
std::optional<ExposureTrack> exposureTrackFor(const ImageOptions& options, const RunFrames& run) {
    if (options.exposureTrack.empty()) {
        return std::nullopt;
    }
    ExposureTrack track;
    try {
        track = readExposureTrack(options.exposureTrack);
    } catch (const std::invalid_argument& e) {
        throw InputError(fmt::format("--exposure-track: {}", e.what()));
    }
    for (const std::int64_t n : run.numbers) {
        if (track.find(n) == nullptr) {
            throw InputError(fmt::format("--exposure-track {}: frame {} is not in the track (it holds frames "
                                         "{} to {}): plan the whole sequence with photopic expose",
                                         options.exposureTrack.string(), n, track.frames.front().frame,
                                         track.frames.back().frame));
        }
    }
    if (std::abs(track.fps - options.fps) > 1e-3f * options.fps) {
        logWarning(
            "--exposure-track {} was planned at {} fps and this run is at {} fps (--fps): the exposures "
            "are the track's, but motion blur and the time column follow --fps",
            options.exposureTrack.string(), track.fps, options.fps);
    }
    return track;
}

/// A preroll never reaches back past a cut of the track: the histories start again at the cut, so the frames
/// before it would change nothing that is written.
void trimPrerollAtCut(RunFrames& run, const ExposureTrack& track) {
    std::size_t from = 0;
    for (std::size_t k = 1; k <= run.prerolled && k < run.numbers.size(); ++k) {
        if (track.find(run.numbers[k])->cut) {
            from = k;
        }
    }
    run.inputs.erase(run.inputs.begin(), run.inputs.begin() + std::ptrdiff_t(from));
    run.numbers.erase(run.numbers.begin(), run.numbers.begin() + std::ptrdiff_t(from));
    run.prerolled -= from;
    run.firstIndex += from;
}

} // namespace

int runImage(const ImageOptions& options) {
    const std::vector<InputFile> files = expandInputs(options);
    const AovRequest aovs = aovRequest(options.aovPreset, options.layer, options.aovs);
    const LensOverride lens = options.lens.empty() ? LensOverride{} : parseLensOverride(options.lens);
    if (options.info) {
        std::vector<fs::path> inputs;
        for (const InputFile& f : files) {
            inputs.push_back(f.path);
        }
        return runImageInfo(inputs, options.camera, aovs, inputFrameNumbers(files));
    }
    if (options.output.empty()) {
        throw InputError("image: an output is required (-o FILE, FOLDER/, PATTERN or -), or --info");
    }
    RunFrames run = runFrames(options, files);
    // A camera track covers every frame the run reads, preroll included, or nothing runs.
    const std::optional<CameraTrack> cameras =
        options.camera.empty() ? std::nullopt : std::optional<CameraTrack>(loadCameraTrack(options.camera));
    if (cameras) {
        for (const fs::path& input : run.inputs)
            (void)cameras->at(frameNumberOf(run.frameNumbers, input), input);
    }
    const std::optional<ExposureTrack> track = exposureTrackFor(options, run);
    if (track) {
        trimPrerollAtCut(run, *track);
    }
    const std::vector<fs::path>& inputs = run.inputs;
    Settings settings = imageSettings(options);
    const std::optional<OcioDisplay> ocio = ocioDisplayFor(options);
    std::FILE* const console = consoleFor(options);
    // Every output is checked before any work; a run that fails takes back what it wrote, the frames it
    // had already written included.
    RunOutputs outputs;
    const std::vector<fs::path> outPaths = plannedOutputs(options, files, outputs);
    requireBitDepthFits(outPaths, settings.output.bitDepth,
                        options.bitDepth ? "--bit-depth" : "the settings' output.bitDepth");
    const std::vector<fs::path> written(inputs.begin() + std::ptrdiff_t(run.prerolled), inputs.end());
    if (options.noOverwrite) {
        requireNewSideOutputs(options, written);
    }
    if (!options.writeAux.empty()) {
        outputs.makeFolder(options.writeAux);
    }
    dropUnavailableAa(settings, inputs.size()); // warned once the outputs are known to be fine
    const float dt = 1.0f / options.fps;
    std::optional<TelemetryCsv> telemetry;
    if (!options.telemetry.empty()) {
        telemetry.emplace(options.telemetry, dt, std::vector<std::string>{});
        telemetry->skipFramesBefore(std::uint64_t(run.numbers[run.prerolled]));
    }
    const int inFlight = options.inFlight > 0 ? options.inFlight : defaultFramesInFlight();
    const int allCores = int(std::max(std::thread::hardware_concurrency(), 1u));
    setExrThreads(options.decodeThreads >= 0 ? options.decodeThreads : inFlight > 1 ? allCores : 0);
    InputDecoder decoder(cameras, options.jitter == "halton" ? settings.temporal.jitterCycle : 0,
                         options.maxPixels);
    decoder.setFrameNumbers(run.frameNumbers);
    decoder.setLens(lens);
    decoder.setFirstIndex(run.firstIndex);
    decoder.setAovs(aovs);
    StageClock clock;
    FrameReader reader(decoder, inputs, framesDecodedAhead(inFlight));
    const DecodedFrame& first = reader.next(); // a bad first input fails before a GL context is made
    clock.restart("first decode");

    HeadlessContext context(commandContext());
    requireTextureFits(inputs.front(), first.width(), first.height()); // before any GL object
    const std::unique_ptr<Pipeline> pipeline = makeImagePipeline(
        {.settings = settings, .forceLdr = options.forceLdr, .keepTelemetryHistory = telemetry.has_value()});
    if (options.writeAux.empty()) { // which writes every layer
        readOnlyLayersRead(decoder, *pipeline, first);
    }
    reader.decodeAhead();
    InputTextures textures; // created for the first frame, re-uploaded for the others
    // On the HDR path the colour input is read only by the sanitize pass's texel fetches, so a half EXR's
    // colour can stay half on the GPU (16 MB less at 1080p, same values).
    const bool hdrPath = pipeline->status().path == ColorPath::Hdr;
    Progress progress("image", files.size());
    FrameWriter writer(outputs, pendingWrites(inFlight),
                       {.bitDepth = settings.output.bitDepth, .jpegQuality = options.jpegQuality});
    // Each frame's output is read back one frame late: its read starts once it is processed and finishes
    // once the next frame is uploaded, so the GPU ends the frame and copies it out while the CPU waits for
    // the next decode and fills the upload buffer.
    TextureReadback readback(1, "cli.output");
    struct Processed {
        std::size_t index; ///< of the outputs
        std::chrono::steady_clock::time_point start;
        Extent size;
    };
    std::optional<Processed> processed;
    const auto writeProcessed = [&] {
        const fs::path& out = outPaths[processed->index];
        FrameImage image = writer.storage();
        finishReadBack(readback, out, settings.output.bitDepth, ocio ? &*ocio : nullptr, image);
        clock.mark(StageClock::ReadBack);
        writer.write(out, std::move(image),
                     writtenLine(written[processed->index], out, processed->size, processed->start, progress,
                                 console));
        clock.mark(StageClock::WriteWait);
        processed.reset();
    };
    clock.restart("GL context and pipeline");
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        throwIfInterrupted();
        const DecodedFrame& frame = reader.next();
        clock.mark(StageClock::DecodeWait);
        clock.add(StageClock::Decode, reader.decodeMs());
        const auto start = std::chrono::steady_clock::now();
        const int width = frame.width();
        const int height = frame.height();
        requireTextureFits(inputs[i], width, height);
        const FrameTime time{.dt = dt, .frameIndex = std::uint64_t(run.numbers[i])};
        if (track) {
            const TrackFrame& planned = *track->find(run.numbers[i]);
            if (planned.cut && i > 0) {
                pipeline->reset(); // a cut of the plan: the histories start again there, as exposure did
            }
            pipeline->setExposureOverride(planned.appliedLog2);
        }
        if (frame.jittered) {
            pipeline->beginFrame(time); // the renderer jittered this frame, as a two-stage host would
        } else if (settings.temporalAntiAliasing() &&
                   (!frame.motion.empty() || (!frame.depth.empty() && frame.camera))) {
            // (Without motion, or depth and a camera to derive it, the pipeline skips TAA and says so.)
            // Said in the CLI's words; the key is the pipeline's own, so its host-API wording stays unsaid.
            warnOnce("taa.no-jitter",
                     fmt::format("aa.mode {}: {} carries no `jitter` attribute and --jitter halton was not "
                                 "given: its frames are taken as not jittered, so TAA filters the sequence "
                                 "over time and cannot anti-alias its edges",
                                 antiAliasingNames()[std::size_t(settings.antiAliasing())],
                                 inputs[i].string()));
        }
        const bool writes = i >= run.prerolled;
        const FrameInputs frameInputs = textures.upload(frame, hdrPath);
        if (writes && !options.writeAux.empty()) {
            outputs.wrote(writeAux(options.writeAux, inputs[i], frame));
        }
        reader.release(); // uploaded: the next frame decodes into its storage while this one is processed
        clock.mark(StageClock::Upload);
        if (processed) {
            writeProcessed();
        }
        const Texture& display = pipeline->execute(frameInputs, time);
        requireDebugViewMade(*pipeline, settings, inputs[i]);
        if (telemetry) {
            telemetry->take(*pipeline, i, i + 1 == inputs.size());
        }
        if (writes) {
            const std::size_t o = i - run.prerolled;
            startReadBack(readback, *pipeline, display, outPaths[o], settings.output.bitDepth,
                          ocio ? &*ocio : nullptr);
            processed = Processed{o, start, {width, height}};
        }
        clock.mark(StageClock::Process);
    }
    if (processed) {
        writeProcessed();
    }
    writer.finish();
    clock.report(inputs.size());
    progress.clear();
    if (telemetry) {
        telemetry->commit(files.size(), pipeline->droppedTelemetry());
        outputs.wrote(options.telemetry);
        if (statusLines())
            std::fprintf(console, "telemetry -> %s (%zu frames)\n", options.telemetry.string().c_str(),
                         files.size());
    }
    outputs.commit();
    return kOk;
}

} // namespace photopic::cli
