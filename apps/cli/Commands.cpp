#include "Commands.h"

#include "ImageInputs.h"

#include "core/settings/SettingsJson.h"
#include "gl/Context.h"
#include "gl/TextureIo.h"
#include "io/ImageIO.h"
#include "pipeline/Pipeline.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>

namespace photopic::cli {

std::string exposureTelemetryHeader() {
    return "measured_luma,target_log2,applied_log2,exposure,manual_ev,metered_luma,min_luma,max_luma,"
           "histogram_count,histogram_low_log2,histogram_high_log2,histogram_average_log2";
}

std::string exposureTelemetryRow(const ExposureTelemetry& t) {
    return fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{},{:.9g},{:.9g},{:.9g}",
                       t.frameLuminance, t.targetLog2, t.appliedLog2, t.exposure, t.manualEV,
                       t.meteredLuminance, t.minLuminance, t.maxLuminance, t.histogramCount,
                       t.histogramLowLog2, t.histogramHighLog2, t.histogramAverageLog2);
}

std::string telemetryCsv(const std::vector<ExposureTelemetry>& rows, float dt,
                         const std::vector<std::string>& sceneColumns,
                         const std::vector<std::vector<double>>& sceneValues) {
    std::string csv = "frame,time_s";
    for (const auto& c : sceneColumns) {
        csv += "," + c;
    }
    csv += "," + exposureTelemetryHeader() + "\n";
    for (const ExposureTelemetry& t : rows) {
        csv += fmt::format("{},{:.6f}", t.frame, double(t.frame) * double(dt));
        for (std::size_t c = 0; c < sceneColumns.size(); ++c) {
            const auto& values = t.frame < sceneValues.size() ? sceneValues[t.frame] : std::vector<double>{};
            csv += fmt::format(",{:.9g}", c < values.size() ? values[c] : 0.0);
        }
        csv += "," + exposureTelemetryRow(t) + "\n";
    }
    return csv;
}

namespace fs = std::filesystem;

Settings resolveSettings(const SettingsSources& sources, Settings base) {
    Settings settings = std::move(base);
    if (!sources.file.empty()) {
        settings = loadSettingsFile(sources.file, std::move(settings));
    }
    if (!sources.tonemap.empty()) {
        applySettingsOverride(settings, "tonemapping.mode=" + sources.tonemap);
    }
    if (sources.exposure) {
        applySettingsOverride(settings, fmt::format("tonemapping.exposure={}", *sources.exposure));
    }
    if (!sources.debugView.empty()) {
        applySettingsOverride(settings, "debug.view=" + sources.debugView);
    }
    for (const auto& o : sources.overrides) {
        applySettingsOverride(settings, o);
    }
    return settings;
}

int runInfo(bool forceLdr, const SettingsSources& sources) {
    const Settings settings = resolveSettings(sources);
    HeadlessContext context;
    const ContextInfo& info = context.info();
    const Capabilities caps = detectCapabilities(forceLdr);
    std::printf("GL vendor:    %s\n", info.vendor.c_str());
    std::printf("GL renderer:  %s\n", info.renderer.c_str());
    std::printf("GL version:   %s\n", info.version.c_str());
    std::printf("GLSL version: %s\n", info.glslVersion.c_str());
    std::printf("platform:     %s\n", info.platform.c_str());
    std::printf("colour path:  %s (%s)\n", caps.path == ColorPath::Hdr ? "HDR, RGBA16F" : "LDR, RGBA8",
                caps.pathReason.c_str());
    std::printf("RGBA16F renderable: %s, RGBA32F renderable: %s, compute: %s, timer queries: %s\n",
                caps.rgba16fRenderable ? "yes" : "no", caps.rgba32fRenderable ? "yes" : "no",
                caps.computeShaders ? "yes" : "no", caps.timerQueries ? "yes" : "no");
    const Pipeline pipeline({.settings = settings, .forceLdr = forceLdr});
    const PipelineStatus t = pipeline.status();
    std::printf("quality:      %s -> %s path (%s)\n",
                std::string(qualityNames()[std::size_t(settings.quality)]).c_str(),
                t.path == ColorPath::Hdr ? "HDR" : "LDR, RGBA8", t.pathReason.c_str());
    return kOk;
}

namespace {

std::string lowerExtension(const fs::path& p) {
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

} // namespace

int runImage(const ImageOptions& options) {
    std::vector<fs::path> inputs = options.inputs;
    std::sort(inputs.begin(), inputs.end());
    if (options.info) {
        return runImageInfo(inputs, options.camera);
    }
    if (options.output.empty()) {
        throw InputError("image: an output is required (-o FILE or FOLDER), or --info");
    }
    const Settings settings = resolveSettings(options.settings);
    const std::string outExt = lowerExtension(options.output);
    const bool toFolder = inputs.size() > 1 || fs::is_directory(options.output) || outExt.empty();
    if (!toFolder && outExt != ".png" && outExt != ".exr") {
        throw InputError(
            fmt::format("output {}: unsupported extension '{}' (use .png for the display image or "
                        ".exr for the scene-referred image)",
                        options.output.string(), outExt));
    }
    if (toFolder) {
        std::error_code ec;
        fs::create_directories(options.output, ec);
        if (ec) {
            throw std::runtime_error(
                fmt::format("cannot create output folder {}: {}", options.output.string(), ec.message()));
        }
    }
    // Read every input first: a bad input fails the run before any output is written.
    InputDecoder decoder(options.camera.empty() ? std::nullopt
                                                : std::optional<CameraJson>(loadCameraJson(options.camera)),
                         options.jitter == "halton" ? settings.temporal.jitterCycle : 0);
    std::vector<DecodedFrame> frames;
    frames.reserve(inputs.size());
    for (const auto& in : inputs) {
        frames.push_back(decoder.decode(in));
    }
    if (!options.writeAux.empty()) {
        std::error_code ec;
        fs::create_directories(options.writeAux, ec);
        if (ec) {
            throw std::runtime_error(
                fmt::format("cannot create aux folder {}: {}", options.writeAux.string(), ec.message()));
        }
    }

    HeadlessContext context;
    const PipelineCreateInfo createInfo{.settings = settings,
                                        .forceLdr = options.forceLdr,
                                        .keepTelemetryHistory = !options.telemetry.empty()};
    std::unique_ptr<Pipeline> pipelinePtr;
    try {
        pipelinePtr = std::make_unique<Pipeline>(createInfo);
    } catch (const IoError& e) { // the metering mask named in the settings
        throw InputError(fmt::format("autoExposure.mask.path: {}", e.what()));
    }
    Pipeline& pipeline = *pipelinePtr;
    const float dt = 1.0f / options.fps;
    InputTextures textures; // created for the first frame, re-uploaded for the others
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const auto start = std::chrono::steady_clock::now();
        const FrameTime time{.dt = dt, .frameIndex = i};
        if (frames[i].jittered) {
            pipeline.beginFrame(time); // the renderer jittered this frame, as a two-stage host would
        }
        const Texture& display = pipeline.execute(textures.upload(frames[i]), time);
        const std::string ext = toFolder ? "." + options.format : outExt;
        const fs::path out = toFolder ? options.output / (inputs[i].stem().string() + ext) : options.output;
        if (ext == ".exr") {
            writeExr(out, readTextureF(pipeline.sceneReferred()));
        } else {
            writePng(out, readTexture8(display));
        }
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        std::printf("%s -> %s (%dx%d, %.1f ms)\n", inputs[i].string().c_str(), out.string().c_str(),
                    frames[i].color.width, frames[i].color.height, ms);
        if (!options.writeAux.empty()) {
            writeAux(options.writeAux, inputs[i], frames[i]);
        }
    }
    if (!options.telemetry.empty()) {
        // Offline: drain the ring so every frame has its own row.
        const std::vector<ExposureTelemetry> rows = pipeline.drainTelemetry();
        if (rows.size() != inputs.size()) {
            throw std::runtime_error(fmt::format("telemetry: {} of {} frames came back ({} dropped)",
                                                 rows.size(), inputs.size(), pipeline.droppedTelemetry()));
        }
        writeTextFile(options.telemetry, telemetryCsv(rows, dt, {}, {}));
        std::printf("telemetry -> %s (%zu frames)\n", options.telemetry.string().c_str(), rows.size());
    }
    return kOk;
}

int runSettingsDefaults() {
    std::fputs(settingsToJson(Settings{}).c_str(), stdout);
    return kOk;
}

int runSettingsCheck(const fs::path& file) {
    const Settings settings = loadSettingsFile(file); // throws SettingsError listing every issue -> exit 2
    (void)settings;
    std::printf("%s: valid\n", file.string().c_str());
    return kOk;
}

} // namespace photopic::cli
