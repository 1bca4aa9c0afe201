// `photopic meter` (MeterCommand.h).
#include "MeterCommand.h"

#include "CommandOptions.h"
#include "SequenceCommands.h"

#include "FrameStream.h"
#include "ImageInputs.h"
#include "ImageSettings.h"
#include "InputSequence.h"
#include "Interrupt.h"
#include "Outputs.h"
#include "Progress.h"

#include "common/ExposureTrack.h"
#include "core/Log.h"
#include "core/PhysicalExposure.h"
#include "gl/Context.h"
#include "io/ImageIO.h"

#include <fmt/format.h>

#include <cstdio>
#include <map>

namespace photopic::cli {

namespace fs = std::filesystem;

namespace {

/// The run's settings with what comes after metering in the frame order turned off (it cannot change a
/// reading) and TAA off: every frame is metered on its own, as the first frame of a shot, so a chunk's
/// readings are the whole sequence's. What comes before metering (ambient occlusion, reflections,
/// volumetric light, the outline) stays as the render will have it.
Settings meteringSettings(Settings s) {
    s.aa.mode = AntiAliasing::None;
    s.taa.enabled = false;
    s.fxaa.enabled = false;
    s.bloom.enabled = false;
    s.dof.enabled = false;
    s.motionBlur.enabled = false;
    s.lensFlare.enabled = false;
    s.debug.view = DebugView::None;
    return s;
}

/// One frame's row of the meter file from the pipeline's telemetry of it.
std::string meterRow(const ExposureTelemetry& t, const AutoExposureSettings& ae, float cameraLog2) {
    MeterRecord r{.frame = std::int64_t(t.frame),
                  .reading = t.frameLuminance,
                  .cameraLog2 = cameraLog2,
                  .minLuminance = t.minLuminance,
                  .maxLuminance = t.maxLuminance,
                  .histogram = std::nullopt};
    if (ae.metering == MeteringMode::Histogram) {
        r.histogram =
            Histogram{.bins = t.histogram, .log2Min = ae.histogramLog2Min, .log2Max = ae.histogramLog2Max};
    }
    return meterCsvRow(r, t.histogramLowLog2, t.histogramHighLog2, t.histogramAverageLog2);
}

} // namespace

MeterCommand::MeterCommand(CLI::App& parent)
    : Command(parent.add_subcommand("meter",
                                    "meter each frame of a sequence for photopic expose: one CSV row "
                                    "per frame (the reading, the histogram's bins); chunks of a "
                                    "sequence metered apart merge into the whole sequence's metering")) {
    CLI::App* cmd = &app();
    ImageOptions& o = mOptions;
    addSequenceInputs(cmd, o);
    cmd->add_option("-o,--output", o.output, "the meter CSV")->check(kOutputPath)->required();
    cmd->add_option("--fps", o.fps, "frame rate (exposure.mode physical: the shutter angle)")
        ->check(CLI::Range(0.001f, 10000.0f));
    cmd->add_option("--camera", o.camera, "camera JSON or track for EXR inputs without camera attributes")
        ->check(CLI::ExistingFile);
    addChannelOptions(cmd, o.aovPreset, o.layer, o.aovs);
    cmd->add_flag("--force-ldr", o.forceLdr, "run the LDR (RGBA8) path");
    addSettingsOptions(cmd, o.settings, "stills (as photopic image)");
    addMaxPixelsOption(cmd, o.maxPixels);
    cmd->footer("Examples:\n"
                "  photopic meter shot/f%04d.exr --frames 1001-1100 --settings look.json -o meter-1001.csv\n"
                "  photopic meter shot/f%04d.exr --set autoExposure.metering=histogram -o meter.csv");
}

int MeterCommand::run() {
    if (mOptions.output.empty()) {
        throw InputError("meter: an output is required (-o meter.csv)");
    }
    const std::vector<InputFile> files = expandInputs(mOptions);
    const Settings settings = meteringSettings(imageSettings(mOptions));
    const AutoExposureSettings& ae = settings.autoExposure;
    RunOutputs outputs; // a replaced meter file comes back, and a signal unwinds, if the run fails
    AtomicFileWriter file = openCommandOutput("meter", mOptions.output);
    file.write(meterCsvHeader(meteringDescription(ae), ae.metering == MeteringMode::Histogram));
    meterFrames(files, settings, file);
    file.commit();
    outputs.commit();
    if (statusLines())
        std::printf("meter -> %s (%zu frames, %s metering)\n", mOptions.output.string().c_str(), files.size(),
                    std::string(meteringModeNames()[std::size_t(ae.metering)]).c_str());
    return kOk;
}

void MeterCommand::meterFrames(const std::vector<InputFile>& files, const Settings& settings,
                               AtomicFileWriter& file) const {
    std::vector<fs::path> inputs;
    for (const InputFile& f : files) {
        inputs.push_back(f.path);
    }
    const std::vector<std::int64_t> numbers = outputFrameNumbers(files);
    const AutoExposureSettings& ae = settings.autoExposure;
    const bool physical = settings.exposure.mode == ExposureMode::Physical;
    const float dt = 1.0f / mOptions.fps;
    InputDecoder decoder(
        mOptions.camera.empty() ? std::nullopt : std::optional<CameraTrack>(loadCameraTrack(mOptions.camera)),
        0, mOptions.maxPixels);
    decoder.setFrameNumbers(inputFrameNumbers(files));
    decoder.setAovs(aovRequest(mOptions.aovPreset, mOptions.layer, mOptions.aovs));
    setExrThreads(mOptions.decodeThreads >= 0 ? mOptions.decodeThreads : 0);
    FrameReader reader(decoder, inputs, 1);
    const DecodedFrame& first = reader.next();
    HeadlessContext context(commandContext());
    requireTextureFits(inputs.front(), first.width(), first.height());
    const std::unique_ptr<Pipeline> pipeline = makeImagePipeline(
        {.settings = settings, .forceLdr = mOptions.forceLdr, .keepTelemetryHistory = true});
    readOnlyLayersRead(decoder, *pipeline, first);
    reader.decodeAhead();
    const bool hdrPath = pipeline->status().path == ColorPath::Hdr;
    InputTextures textures;
    Progress progress("meter", inputs.size());
    std::map<std::uint64_t, float> cameraLog2; // frame -> the camera's exposure, physical mode only
    std::uint64_t rows = 0;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        throwIfInterrupted();
        const DecodedFrame& frame = reader.next();
        requireTextureFits(inputs[i], frame.width(), frame.height());
        const FrameTime time{.dt = dt, .frameIndex = std::uint64_t(numbers[i])};
        if (physical && frame.camera) {
            cameraLog2[time.frameIndex] = cameraExposureLog2(frame.camera->lens, dt);
        }
        const FrameInputs frameInputs = textures.upload(frame, hdrPath);
        reader.release();
        pipeline->reset(); // each frame metered as the first of a shot: no history reaches its reading
        (void)pipeline->execute(frameInputs, time);
        if ((i + 1) % 64 == 0 || i + 1 == inputs.size()) {
            rows += writeRows(*pipeline, ae, cameraLog2, file);
        }
        progress.advance();
    }
    progress.clear();
    if (rows != inputs.size()) {
        throw std::runtime_error(fmt::format("meter: {} of {} frames came back ({} dropped)", rows,
                                             inputs.size(), pipeline->droppedTelemetry()));
    }
}

std::uint64_t MeterCommand::writeRows(Pipeline& pipeline, const AutoExposureSettings& ae,
                                      std::map<std::uint64_t, float>& cameraLog2, AtomicFileWriter& file) {
    std::string text;
    std::uint64_t rows = 0;
    for (const ExposureTelemetry& t : pipeline.drainTelemetry()) {
        text += meterRow(t, ae, cameraLog2[t.frame]);
        cameraLog2.erase(t.frame);
        ++rows;
    }
    file.write(text);
    return rows;
}

} // namespace photopic::cli
