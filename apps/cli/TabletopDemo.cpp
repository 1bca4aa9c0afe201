// Phase 1 of the tabletop demo: exposure driven by a CPU probe under the player token (the GPU probe and
// subject metering replace it after issue 3's merge). Seed 000's eye lag, made visible.

#include "TabletopDemo.h"

#include "Commands.h"

#include "core/ExposureController.h"
#include "core/Subjects.h"
#include "gl/Context.h"
#include "gl/TextureIo.h"
#include "io/ImageIO.h"
#include "io/Raster.h"
#include "scenes/tabletop/TabletopScene.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace photopic::cli {

namespace fs = std::filesystem;

Image8 plotExposureTelemetry(const std::vector<TelemetrySample>& samples, int width, int height) {
    PlotSeries luma{"measured luma (log2)", {120, 120, 120, 255}, {}, {}};
    PlotSeries target{"target EV", {30, 110, 220, 255}, {}, {}};
    PlotSeries applied{"applied EV", {220, 60, 30, 255}, {}, {}};
    PlotSeries outdoors{"outdoors (0..1)", {40, 160, 60, 255}, {}, {}};
    for (const TelemetrySample& s : samples) {
        for (PlotSeries* p : {&luma, &target, &applied, &outdoors}) {
            p->x.push_back(s.timeS);
        }
        luma.y.push_back(s.measuredLuma > 0.0f ? std::log2(s.measuredLuma)
                                               : std::numeric_limits<float>::quiet_NaN());
        target.y.push_back(s.targetLog2);
        applied.y.push_back(s.appliedLog2);
        outdoors.y.push_back(s.outdoors);
    }
    return plotLines({luma, target, applied, outdoors}, width, height,
                     "Tabletop walk: light under the token and the eye's exposure", "time (s)");
}

std::vector<std::size_t> keyFrameIndices(const std::vector<Transition>& transitions, std::size_t frameCount) {
    std::vector<std::size_t> frames;
    for (const Transition& t : transitions) {
        frames.push_back(t.crossingIndex > 0 ? t.crossingIndex - 1 : 0);
        frames.push_back(t.startIndex);
        if (t.settled) {
            frames.push_back(t.settledIndex);
        }
    }
    std::erase_if(frames, [&](std::size_t f) { return f >= frameCount; });
    std::sort(frames.begin(), frames.end());
    frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
    return frames;
}

int runTabletopWalk(const TabletopWalkOptions& options) {
    std::error_code ec;
    fs::create_directories(options.output, ec);
    if (ec) {
        throw std::runtime_error(fmt::format("cannot create {}: {}", options.output.string(), ec.message()));
    }
    HeadlessContext context;
    TabletopScene scene;
    Settings settings = scene.defaultSettings();
    AutoExposureSettings ae = settings.autoExposure;
    ae.enabled = true; // seed 000's defaults otherwise: key 0.18, -2..+2 EV, tauBrighten 1 s, tauDarken 0.3 s
    Pipeline pipeline({.settings = settings});
    scene.resize({options.width, options.height});
    SubjectTracker tracker(settings.subjects);
    tracker.setOutdoorsMask(&scene.outdoorsMask());
    ExposureController controller(ae);

    const float dt = 1.0f / options.fps;
    const int frames = std::max(1, int(std::lround(options.seconds * options.fps)));
    std::vector<TelemetrySample> samples;
    std::vector<Image8> displayFrames;
    std::string csv = "frame,time_s";
    for (const auto& c : scene.telemetryColumns()) {
        csv += "," + c;
    }
    csv += ",measured_luma,target_log2,applied_log2,exposure\n";
    std::vector<double> values;
    for (int i = 0; i < frames; ++i) {
        const FrameTime time{.dt = dt, .frameIndex = std::uint64_t(i)};
        const Texture& colour = scene.render(time, pipeline, values);
        // Phase 1: a blocking read of the HDR frame for the CPU probe (the GPU probe makes this a 1-texel
        // non-blocking readback).
        const ImageF hdr = readTextureF(colour);
        tracker.beginFrame(dt);
        for (const Subject& s : scene.subjects()) {
            tracker.addSubject(s);
        }
        for (const ProbeRequest& p : tracker.scheduleProbes()) {
            tracker.recordProbe(
                p.id,
                probeImage(hdr, p.screenUv, settings.subjects.probe.taps, settings.subjects.probe.radius),
                tracker.time());
        }
        const SubjectContext* subject = tracker.subjectContext();
        const ExposureState& state = controller.update(subject ? subject->measuredLuma : 0.0f, dt);
        tracker.updateExposure(ae, state.appliedLog2);
        settings.tonemapping.exposure = state.appliedLog2;
        pipeline.setSettings(settings);
        Image8 display = readTexture8(pipeline.execute({.color = &colour}, time));
        writePng(options.output / fmt::format("frame_{:04d}.png", i), display);
        displayFrames.push_back(std::move(display));
        const float outdoors = subject ? subject->outdoors : 0.0f;
        samples.push_back({float(i) * dt, subject ? subject->measuredLuma : 0.0f, state.targetLog2,
                           state.appliedLog2, outdoors});
        csv += fmt::format("{},{:.6f}", i, double(i) * double(dt));
        for (double v : values) {
            csv += fmt::format(",{:.6g}", v);
        }
        csv += fmt::format(",{:.6g},{:.6g},{:.6g},{:.6g}\n", double(samples.back().measuredLuma),
                           double(state.targetLog2), double(state.appliedLog2), double(state.exposure));
    }
    writeTextFile(options.output / "telemetry.csv", csv);

    const std::vector<Transition> transitions = analyzeTransitions(samples, ae);
    writePng(options.output / "exposure_plot.png", plotExposureTelemetry(samples, 960, 420));
    std::vector<std::pair<std::string, Image8>> tiles;
    for (std::size_t f : keyFrameIndices(transitions, displayFrames.size())) {
        tiles.emplace_back(fmt::format("t={:.2f}s {:+.2f} EV (target {:+.2f})", samples[f].timeS,
                                       samples[f].appliedLog2, samples[f].targetLog2),
                           displayFrames[f]);
    }
    if (!tiles.empty()) {
        writePng(options.output / "contact_sheet.png", makeContactSheet(tiles, 3, 320));
    }
    std::printf("tabletop walk: %d frames at %dx%d, %.3g fps -> %s\n", frames, options.width, options.height,
                double(options.fps), options.output.string().c_str());
    for (const Transition& t : transitions) {
        std::printf("  %s\n", describeTransition(t).c_str());
    }
    return kOk;
}

} // namespace photopic::cli
