// `photopic bench` (BenchCommand.h): its options, and which benchmark they choose.
#include "BenchCommand.h"

#include "CommandOptions.h"
#include "Outputs.h"
#include "PipelineBench.h"

#include <fmt/format.h>

namespace photopic::cli {

BenchCommand::BenchCommand(CLI::App& parent)
    : Command(parent.add_subcommand("bench", "per-pass GPU timings (median ms, bytes moved, GB/s) over N "
                                             "frames of a synthetic HDR frame or --input FILE, or the canvas "
                                             "scene's shading paths (--scene canvas)")) {
    CLI::App& cmd = app();
    BenchOptions& o = mOptions;
    cmd.add_option("--size", o.size,
                   "WxH of the synthetic frame; with --input, the image is mirrored (repeated, every other "
                   "copy flipped) or cropped to this size, for natural content at any size")
        ->each([&o](const std::string&) { o.sizeGiven = true; })
        ->capture_default_str();
    cmd.add_option("--frames", o.frames, "timed frames after the warm-up")
        ->check(CLI::Range(1, 100000))
        ->capture_default_str();
    cmd.add_option("--warmup", o.warmup, "untimed frames first")->check(CLI::Range(0, 1000));
    cmd.add_option("--input", o.input, "an HDR image (EXR, HDR) instead of the synthetic frame")
        ->check(CLI::ExistingFile);
    cmd.add_option("--input-format", o.inputFormat,
                   "the input texture's format: rgba32f, or rgba16f (a renderer's usual scene colour, half "
                   "the bytes for the first passes to read); the bandwidth reference copies this format")
        ->check(CLI::IsMember({"rgba32f", "rgba16f"}))
        ->capture_default_str();
    cmd.add_option("--json", o.json, "also write the table as JSON to FILE (atomically)")->check(kOutputPath);
    cmd.add_flag("--force-ldr", o.forceLdr, "run the LDR (RGBA8) path");
    CLI::Option* sync = cmd.add_flag(
        "--sync", o.sync,
        "debug: glFinish() around every pass and report its wall time too (stalls each pass; for drivers "
        "whose timer queries miss deferred work, e.g. llvmpipe)");
    cmd.add_flag("--queue-ahead", o.queueAhead,
                 "keep the GPU busy with untimed work while the CPU submits each timed frame, so the "
                 "timestamps hold the GPU's own work and not its waits for the CPU (a GPU's figure)")
        ->excludes(sync);
    cmd.add_option("--scene", o.scene,
                   "canvas (the only one): time the canvas scene's tiled and full-screen shading paths "
                   "instead (--set canvas.KEY=VALUE, e.g. canvas.occupancy=0.3, the default)");
    cmd.add_option(
           "--motion", o.motion,
           "PX: the 3D frame's motion vectors move every pixel PX pixels a frame to the right (0, the "
           "default: a still frame, on which motion blur's gather runs on no tile)")
        ->check(CLI::Range(0.0, 256.0))
        ->capture_default_str();
    cmd.add_flag("--floor", o.floor,
                 "the 3D frame's lower part is a floor meeting the wall (about a third of the image at 60 "
                 "degrees' field of view): screen-space reflections from it cross the screen, where the "
                 "wall's leave it within a few pixels");
    cmd.add_option("--camera", o.camera,
                   "camera JSON for an EXR --input whose 3D layers (depth, normals, motion) have no camera "
                   "attributes: one camera or a track by frame number, as `photopic image --camera` takes")
        ->check(CLI::ExistingFile);
    addSettingsOptions(&cmd, o.settings, "the defaults (realtime)");
    addMaxPixelsOption(&cmd, o.maxPixels);
    cmd.footer("Examples:\n"
               "  photopic bench --size 1920x1080 --frames 100\n"
               "  photopic bench --input data/Desk.exr --json timings.json\n"
               "  photopic bench --input data/GoldenGate.exr --size 3840x2160 --queue-ahead\n"
               "  photopic bench --size 1920x1080 --motion 8 --set motionBlur.enabled=true\n"
               "  photopic bench --input render/frame_0003.exr --camera track.json --set ssao.enabled=true\n"
               "  photopic bench --scene canvas --set canvas.occupancy=0.3");
}

int BenchCommand::run() {
    if (!mOptions.json.empty()) {
        RunOutputs::requireFile(mOptions.json); // before the minutes of timing, not after
    }
    if (!mOptions.scene.empty()) {
        return runCanvas();
    }
    return PipelineBench(mOptions).run();
}

int BenchCommand::runCanvas() const {
    if (mOptions.queueAhead) {
        throw InputError("bench --scene canvas: --queue-ahead times the pipeline's chain only");
    }
    if (mOptions.motion != 0.0f || mOptions.floor) {
        throw InputError("bench --scene canvas: --motion and --floor change the pipeline's 3D frame only");
    }
    if (mOptions.scene != "canvas") {
        throw InputError(
            fmt::format("bench --scene {}: the only scene with a benchmark is 'canvas'", mOptions.scene));
    }
    return runCanvasBench(mOptions);
}

} // namespace photopic::cli
