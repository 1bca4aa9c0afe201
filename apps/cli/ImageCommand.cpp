// `photopic image` (ImageCommand.h): its options, then run()'s steps, from the inputs to the streamed
// sequence (decode, GPU, encode in flight together).
#include "ImageCommand.h"

#include "CommandOptions.h"
#include "FrameStream.h"
#include "ImageInputs.h"
#include "ImageSettings.h"
#include "InputSequence.h"
#include "Interrupt.h"
#include "Outputs.h"
#include "PlannedOutputs.h"
#include "Progress.h"
#include "RunFrames.h"
#include "StageClock.h"
#include "TelemetryCsv.h"

#include "common/ExposureTrack.h"
#include "core/Log.h"
#include "core/settings/SettingsJson.h"
#include "gl/Context.h"
#include "gl/Gl.h"
#include "gl/TextureReadback.h"
#include "io/ImageIO.h"
#include "pipeline/Pipeline.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>

namespace photopic::cli {

namespace fs = std::filesystem;

namespace {

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

} // namespace

/// What one run holds, in the order it is made (and released in reverse: the writes and the GL objects
/// before the context, the outputs taken back last unless committed).
struct ImageCommand::Run {
    std::vector<InputFile> files;
    AovRequest aovs;
    LensOverride lens;
    RunFrames frames;
    std::optional<CameraTrack> cameras;
    std::optional<ExposureTrack> track;
    Settings settings;
    std::optional<OcioDisplay> ocio;
    std::FILE* console = stdout;
    /// Every output is checked before any work; a run that fails takes back what it wrote, the frames it
    /// had already written included.
    std::optional<RunOutputs> outputs;
    std::vector<fs::path> outPaths;
    std::vector<fs::path> written; ///< the inputs whose results are written (the preroll's are not)
    float dt = 0;
    std::optional<TelemetryCsv> telemetry;
    int inFlight = 0;
    std::optional<InputDecoder> decoder;
    StageClock clock;
    std::optional<FrameReader> reader;
    std::optional<HeadlessContext> context;
    std::unique_ptr<Pipeline> pipeline;
    std::optional<InputTextures> textures; ///< created for the first frame, re-uploaded for the others
    bool hdrPath = false;
    std::optional<Progress> progress;
    std::optional<FrameWriter> writer;
    /// Each frame's output is read back one frame late: its read starts once it is processed and finishes
    /// once the next frame is uploaded, so the GPU ends the frame and copies it out while the CPU waits for
    /// the next decode and fills the upload buffer.
    std::optional<TextureReadback> readback;
    struct Processed {
        std::size_t index; ///< of the outputs
        std::chrono::steady_clock::time_point start;
        Extent size;
    };
    std::optional<Processed> processed;
};

ImageCommand::ImageCommand(CLI::App& parent)
    : Command(parent.add_subcommand("image", "process HDR images (EXR, HDR, PNG) into PNG, TIFF or JPEG "
                                             "(display) or EXR (scene-referred, before tone mapping)")) {
    addFileOptions();
    addFormatOptions();
    addRendererOptions();
    addSequenceOptions();
}

ImageCommand::~ImageCommand() = default;

/// The inputs, -o and whether it may overwrite, --frames and --start-number.
void ImageCommand::addFileOptions() {
    CLI::App* cmd = &app();
    ImageOptions& o = mOptions;
    cmd->add_option(
           "inputs", o.inputs,
           "input images, or frame-numbered patterns when no such file exists: f%04d.exr (zero padded, "
           "as ffmpeg), f.####.exr (one # a digit), f@.exr (unpadded); several are frames of a sequence, "
           "in natural order (f9 before f10)")
        ->required();
    cmd->add_option(
           "-o,--output", o.output,
           "where results go, required unless --info: an extension means a file (.png, .tif, .tiff, "
           ".jpg, .jpeg: the display image; .exr: scene-referred); a trailing '/', an existing folder or "
           "no extension means a folder (NAME.png, --format), and several inputs need one (or a pattern); "
           "a frame number means a pattern (out/f%04d.png: each input's frame number, or 0, 1, ... when "
           "the inputs carry none); '-', a device or a pipe is streamed (one input, PNG). An output that "
           "is an input, or that two inputs would share, is refused. Existing files are replaced "
           "(atomically) unless -n")
        ->check(kOutputPath);
    auto* noOverwrite = cmd->add_flag("-n,--no-overwrite", o.noOverwrite,
                                      "never overwrite: an output that exists is refused (exit 2) "
                                      "before any work, like ffmpeg -n");
    cmd->add_flag_callback(
           "-y,--overwrite", [] {}, "replace existing outputs (the default; like ffmpeg -y)")
        ->excludes(noOverwrite);
    auto* frames = cmd->add_option("--frames", o.frames,
                                   "frames A-B of a pattern input, inclusive, each of which must exist "
                                   "(1001-1100)");
    cmd->add_option("--start-number", o.startNumber,
                    "a pattern input's first frame (like ffmpeg -start_number); default: the lowest "
                    "that exists. Every frame from it on that exists is taken")
        ->check(CLI::NonNegativeNumber)
        ->excludes(frames);
}

/// What the outputs are written as, the frame rate, the telemetry, --info.
void ImageCommand::addFormatOptions() {
    CLI::App* cmd = &app();
    ImageOptions& o = mOptions;
    cmd->add_option("--format", o.format, "file type written into an output folder")
        ->check(CLI::IsMember(kFrameFormats))
        ->capture_default_str();
    addDisplayEncodingOptions(cmd, o.bitDepth, o.jpegQuality);
    cmd->add_option("--fps", o.fps, "frame rate of a sequence")->check(CLI::Range(0.001f, 10000.0f));
    cmd->add_flag("--force-ldr", o.forceLdr, "run the LDR (RGBA8) path");
    cmd->add_option("--telemetry", o.telemetry,
                    "write exposure telemetry as CSV, one row per frame (frame,time_s,measured_luma,"
                    "target_log2,applied_log2,exposure,...)")
        ->check(kOutputPath);
    cmd->add_flag("--info", o.info,
                  "list each input's channels and attributes and what each feeds (depth, normals, motion, "
                  "camera); no rendering");
}

/// Cameras, lens, auxiliary outputs, jitter, channels, settings, OpenColorIO and --max-pixels.
void ImageCommand::addRendererOptions() {
    CLI::App* cmd = &app();
    ImageOptions& o = mOptions;
    cmd->add_option("--camera", o.camera,
                    "camera JSON for inputs without worldToCamera/worldToNDC: one camera, or a track of one "
                    "per frame number ({\"frames\": {\"1001\": {...}}}, as tools/blender/photopic_camera.py "
                    "writes it); a frame the track lacks is an error (docs/camera-json.md)")
        ->check(CLI::ExistingFile);
    cmd->add_option("--lens", o.lens,
                    "lens values that replace the file's or the camera's: fNumber=N,focus=D,shutter=DEG "
                    "(any of them), e.g. --lens fNumber=2.8,focus=3.5");
    cmd->add_option("--write-aux", o.writeAux,
                    "write each frame's decoded depth (linear view), normals (view space) and motion (UV, "
                    "y up) as DIR/NAME.aux.exr")
        ->check(kOutputPath);
    cmd->add_option("--jitter", o.jitter,
                    "how a sequence's frames were jittered, for TAA and the motion unjitter: attribute (the "
                    "EXR `jitter` attribute, pixels, x right, y down; none when absent) or halton "
                    "(Photopic's Halton(2,3) from index 1, as Pipeline::beginFrame hands it out)")
        ->check(CLI::IsMember({"attribute", "halton"}));
    addChannelOptions(cmd, o.aovPreset, o.layer, o.aovs);
    addSettingsOptions(cmd, o.settings, "stills");
    addOcioOptions(cmd, o.ocio);
    addMaxPixelsOption(cmd, o.maxPixels);
}

/// How a sequence streams (frames in flight, decode threads), --exposure-track and --preroll; the examples.
void ImageCommand::addSequenceOptions() {
    CLI::App* cmd = &app();
    ImageOptions& o = mOptions;
    cmd->add_option(
           "--frames-in-flight", o.inFlight,
           "frames of a sequence between decode and write at once: 1 decodes, processes and writes "
           "each frame before the next; more decode the next frame (from 4 on, the next two) and write "
           "earlier ones on other threads (same outputs, bounded memory); default 3 with up to 4 cores, "
           "else half the cores, at most 8")
        ->check(CLI::Range(1, 16));
    cmd->add_option("--decode-threads", o.decodeThreads,
                    "threads that decode each EXR frame's chunks (OpenEXR's thread pool): 0 decodes on the "
                    "thread that reads the frame; default every core, or 0 with --frames-in-flight 1; the "
                    "pixels are the same whatever the count")
        ->check(CLI::Range(0, 256));
    cmd->add_option(
           "--exposure-track", o.exposureTrack,
           "each frame's auto exposure from a plan of the whole sequence (photopic expose) instead of "
           "this run's adaptation, so a chunk renders the single run's frames (docs/farm.md)")
        ->check(CLI::ExistingFile);
    cmd->add_option(
           "--preroll", o.preroll,
           "process the N frames before the first of --frames without writing them, so TAA, the "
           "reflections' and volumetric light's histories, the previous camera and exposure are warm "
           "at a chunk's first frame (never past a cut of --exposure-track)")
        ->check(CLI::Range(0, 1000));
    cmd->footer(
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

int ImageCommand::run() {
    mRun = std::make_unique<Run>();
    try {
        inputs();
        if (mOptions.info) {
            const int code = printInfo();
            mRun.reset();
            return code;
        }
        if (mOptions.output.empty()) {
            throw InputError("image: an output is required (-o FILE, FOLDER/, PATTERN or -), or --info");
        }
        frames();
        settings();
        outputs();
        pipeline();
        stream();
        finish();
    } catch (...) {
        mRun.reset(); // the outputs taken back before the error is reported
        throw;
    }
    mRun.reset();
    return kOk;
}

void ImageCommand::inputs() {
    Run& r = *mRun;
    r.files = expandInputs(mOptions);
    r.aovs = aovRequest(mOptions.aovPreset, mOptions.layer, mOptions.aovs);
    r.lens = mOptions.lens.empty() ? LensOverride{} : parseLensOverride(mOptions.lens);
}

int ImageCommand::printInfo() const {
    std::vector<fs::path> inputs;
    for (const InputFile& f : mRun->files) {
        inputs.push_back(f.path);
    }
    return runImageInfo(inputs, mOptions.camera, mRun->aovs, inputFrameNumbers(mRun->files));
}

void ImageCommand::frames() {
    Run& r = *mRun;
    r.frames = runFrames(mOptions, r.files);
    // A camera track covers every frame the run reads, preroll included, or nothing runs.
    if (!mOptions.camera.empty()) {
        r.cameras = loadCameraTrack(mOptions.camera);
        for (const fs::path& input : r.frames.inputs)
            (void)r.cameras->at(frameNumberOf(r.frames.frameNumbers, input), input);
    }
    loadExposureTrack();
    if (r.track) {
        trimPrerollAtCut(r.frames, *r.track);
    }
}

void ImageCommand::loadExposureTrack() {
    if (mOptions.exposureTrack.empty()) {
        return;
    }
    ExposureTrack track;
    try {
        track = readExposureTrack(mOptions.exposureTrack);
    } catch (const std::invalid_argument& e) {
        throw InputError(fmt::format("--exposure-track: {}", e.what()));
    }
    for (const std::int64_t n : mRun->frames.numbers) {
        if (track.find(n) == nullptr) {
            throw InputError(fmt::format("--exposure-track {}: frame {} is not in the track (it holds frames "
                                         "{} to {}): plan the whole sequence with photopic expose",
                                         mOptions.exposureTrack.string(), n, track.frames.front().frame,
                                         track.frames.back().frame));
        }
    }
    if (std::abs(track.fps - mOptions.fps) > 1e-3f * mOptions.fps) {
        logWarning(
            "--exposure-track {} was planned at {} fps and this run is at {} fps (--fps): the exposures "
            "are the track's, but motion blur and the time column follow --fps",
            mOptions.exposureTrack.string(), track.fps, mOptions.fps);
    }
    mRun->track = std::move(track);
}

void ImageCommand::settings() {
    Run& r = *mRun;
    r.settings = imageSettings(mOptions);
    r.ocio = ocioDisplayFor(mOptions);
    r.console = consoleFor(mOptions);
}

void ImageCommand::outputs() {
    Run& r = *mRun;
    r.outputs.emplace();
    r.outPaths = plannedOutputs(mOptions, r.files, *r.outputs);
    requireBitDepthFits(r.outPaths, r.settings.output.bitDepth,
                        mOptions.bitDepth ? "--bit-depth" : "the settings' output.bitDepth");
    const std::vector<fs::path>& inputs = r.frames.inputs;
    r.written.assign(inputs.begin() + std::ptrdiff_t(r.frames.prerolled), inputs.end());
    if (mOptions.noOverwrite) {
        requireNewSideOutputs(mOptions, r.written);
    }
    if (!mOptions.writeAux.empty()) {
        r.outputs->makeFolder(mOptions.writeAux);
    }
    dropUnavailableAa(r.settings, inputs.size()); // warned once the outputs are known to be fine
    r.dt = 1.0f / mOptions.fps;
    if (!mOptions.telemetry.empty()) {
        r.telemetry.emplace(mOptions.telemetry, r.dt, std::vector<std::string>{});
        r.telemetry->skipFramesBefore(std::uint64_t(r.frames.numbers[r.frames.prerolled]));
    }
}

void ImageCommand::pipeline() {
    Run& r = *mRun;
    r.inFlight = mOptions.inFlight > 0 ? mOptions.inFlight : defaultFramesInFlight();
    const int allCores = int(std::max(std::thread::hardware_concurrency(), 1u));
    setExrThreads(mOptions.decodeThreads >= 0 ? mOptions.decodeThreads : r.inFlight > 1 ? allCores : 0);
    r.decoder.emplace(r.cameras, mOptions.jitter == "halton" ? r.settings.temporal.jitterCycle : 0,
                      mOptions.maxPixels);
    r.decoder->setFrameNumbers(r.frames.frameNumbers);
    r.decoder->setLens(r.lens);
    r.decoder->setFirstIndex(r.frames.firstIndex);
    r.decoder->setAovs(r.aovs);
    r.clock = StageClock();
    r.reader.emplace(*r.decoder, r.frames.inputs, framesDecodedAhead(r.inFlight));
    const DecodedFrame& first = r.reader->next(); // a bad first input fails before a GL context is made
    r.clock.restart("first decode");

    r.context.emplace(commandContext());
    requireTextureFits(r.frames.inputs.front(), first.width(), first.height()); // before any GL object
    r.pipeline = makeImagePipeline({.settings = r.settings,
                                    .forceLdr = mOptions.forceLdr,
                                    .keepTelemetryHistory = r.telemetry.has_value()});
    if (mOptions.writeAux.empty()) { // which writes every layer
        readOnlyLayersRead(*r.decoder, *r.pipeline, first);
    }
    r.reader->decodeAhead();
}

void ImageCommand::stream() {
    Run& r = *mRun;
    const std::vector<fs::path>& inputs = r.frames.inputs;
    r.textures.emplace();
    // On the HDR path the colour input is read only by the sanitize pass's texel fetches, so a half EXR's
    // colour can stay half on the GPU (16 MB less at 1080p, same values).
    r.hdrPath = r.pipeline->status().path == ColorPath::Hdr;
    r.progress.emplace("image", r.files.size());
    r.writer.emplace(
        *r.outputs, pendingWrites(r.inFlight),
        DisplayEncoding{.bitDepth = r.settings.output.bitDepth, .jpegQuality = mOptions.jpegQuality});
    r.readback.emplace(1, "cli.output");
    r.clock.restart("GL context and pipeline");
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        throwIfInterrupted();
        const DecodedFrame& frame = r.reader->next();
        r.clock.mark(StageClock::DecodeWait);
        r.clock.add(StageClock::Decode, r.reader->decodeMs());
        const auto start = std::chrono::steady_clock::now();
        const int width = frame.width();
        const int height = frame.height();
        requireTextureFits(inputs[i], width, height);
        const FrameTime time{.dt = r.dt, .frameIndex = std::uint64_t(r.frames.numbers[i])};
        beginFrame(i, frame, time);
        const bool writes = i >= r.frames.prerolled;
        const FrameInputs frameInputs = r.textures->upload(frame, r.hdrPath);
        if (writes && !mOptions.writeAux.empty()) {
            r.outputs->wrote(writeAux(mOptions.writeAux, inputs[i], frame));
        }
        r.reader->release(); // uploaded: the next frame decodes into its storage while this one is processed
        r.clock.mark(StageClock::Upload);
        if (r.processed) {
            writeProcessed();
        }
        const Texture& display = r.pipeline->execute(frameInputs, time);
        requireDebugViewMade(*r.pipeline, r.settings, inputs[i]);
        if (r.telemetry) {
            r.telemetry->take(*r.pipeline, i, i + 1 == inputs.size());
        }
        if (writes) {
            const std::size_t o = i - r.frames.prerolled;
            startReadBack(*r.readback, *r.pipeline, display, r.outPaths[o], r.settings.output.bitDepth,
                          r.ocio ? &*r.ocio : nullptr);
            r.processed = Run::Processed{o, start, {width, height}};
        }
        r.clock.mark(StageClock::Process);
    }
}

void ImageCommand::beginFrame(std::size_t i, const DecodedFrame& frame, const FrameTime& time) {
    Run& r = *mRun;
    if (r.track) {
        const TrackFrame& planned = *r.track->find(r.frames.numbers[i]);
        if (planned.cut && i > 0) {
            r.pipeline->reset(); // a cut of the plan: the histories start again there, as exposure did
        }
        r.pipeline->setExposureOverride(planned.appliedLog2);
    }
    if (frame.jittered) {
        r.pipeline->beginFrame(time); // the renderer jittered this frame, as a two-stage host would
    } else if (r.settings.temporalAntiAliasing() &&
               (!frame.motion.empty() || (!frame.depth.empty() && frame.camera))) {
        // (Without motion, or depth and a camera to derive it, the pipeline skips TAA and says so.)
        // Said in the CLI's words; the key is the pipeline's own, so its host-API wording stays unsaid.
        warnOnce("taa.no-jitter",
                 fmt::format("aa.mode {}: {} carries no `jitter` attribute and --jitter halton was not "
                             "given: its frames are taken as not jittered, so TAA filters the sequence "
                             "over time and cannot anti-alias its edges",
                             antiAliasingNames()[std::size_t(r.settings.antiAliasing())],
                             r.frames.inputs[i].string()));
    }
}

void ImageCommand::writeProcessed() {
    Run& r = *mRun;
    const fs::path& out = r.outPaths[r.processed->index];
    FrameImage image = r.writer->storage();
    finishReadBack(*r.readback, out, r.settings.output.bitDepth, r.ocio ? &*r.ocio : nullptr, image);
    r.clock.mark(StageClock::ReadBack);
    r.writer->write(out, std::move(image),
                    writtenLine(r.written[r.processed->index], out, r.processed->size, r.processed->start,
                                *r.progress, r.console));
    r.clock.mark(StageClock::WriteWait);
    r.processed.reset();
}

void ImageCommand::finish() {
    Run& r = *mRun;
    if (r.processed) {
        writeProcessed();
    }
    r.writer->finish();
    r.clock.report(r.frames.inputs.size());
    r.progress->clear();
    if (r.telemetry) {
        r.telemetry->commit(r.files.size(), r.pipeline->droppedTelemetry());
        r.outputs->wrote(mOptions.telemetry);
        if (statusLines())
            std::fprintf(r.console, "telemetry -> %s (%zu frames)\n", mOptions.telemetry.string().c_str(),
                         r.files.size());
    }
    r.outputs->commit();
}

} // namespace photopic::cli
