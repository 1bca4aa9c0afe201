// `photopic bench` on the pipeline (PipelineBench.h).
//
// Reading the numbers on Mesa llvmpipe (software GL): a draw is binned and rasterised when its scene is
// flushed (a framebuffer change, a glFinish), so its work can land after the pass's end timestamp and be
// counted in whichever later pass's bracket holds the flush. The timer query is the figure on a GPU; on
// llvmpipe the --sync wall time is the one that holds a pass's own work.

#include "PipelineBench.h"

#include "CameraJson.h"
#include "InputSequence.h"

#include "core/HalfFloat.h"
#include "gl/Capabilities.h"
#include "gl/TextureIo.h"
#include "io/ImageIO.h"
#include "scenes/SyntheticHdr.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <stdexcept>

namespace photopic::cli {

namespace {

/// The image the pipeline benchmark processes: --input, or a synthetic HDR frame of --size.
ImageF benchInput(const BenchOptions& options) {
    if (options.input.empty()) {
        const auto [w, h] = parseSize(options.size, 8);
        return makeSyntheticHdr(w, h);
    }
    if (options.sizeGiven) {
        const auto [w, h] = parseSize(options.size, 8); // before the decode: a bad size fails at once
        return mirroredTo(readInput(options.input, options.maxPixels), w, h);
    }
    return readInput(options.input, options.maxPixels);
}

/// An EXR --input at its own size, decoded as `photopic image` decodes it (channels by the file's layout,
/// the camera from its attributes or --camera's track): its 3D layers feed the 3D effects when it has depth
/// and a camera. Nothing for another input, or one mirrored to --size.
std::optional<DecodedFrame> decodeRendererFrame(const BenchOptions& o) {
    if (o.input.empty() || o.sizeGiven || !isExr(o.input)) {
        if (!o.camera.empty()) {
            throw InputError(
                "bench --camera: the camera of an EXR --input's 3D layers, which run at the file's "
                "own size (without --size)");
        }
        return std::nullopt;
    }
    InputDecoder decoder(o.camera.empty() ? std::nullopt
                                          : std::optional<CameraTrack>(loadCameraTrack(o.camera)),
                         0, o.maxPixels);
    decoder.setFrameNumbers(inputFrameNumbers({InputFile{.path = o.input, .frame = std::nullopt}}));
    return decoder.decode(o.input);
}

/// The frame's colour as floats (an EXR of half channels decodes to halves), a copy: the frame keeps its
/// own for the upload of its 3D layers.
ImageF colourOf(const DecodedFrame& frame) {
    if (!frame.halfColor()) {
        return frame.color;
    }
    ImageF image;
    image.width = frame.colorHalves.width;
    image.height = frame.colorHalves.height;
    image.rgba.resize(frame.colorHalves.rgba.size());
    halfToFloat(frame.colorHalves.rgba.data(), image.rgba.data(), image.rgba.size());
    return image;
}

} // namespace

int PipelineBench::run() {
    prepare();
    warmUp();
    timePasses();
    timeWholeFrame();
    printSetup();
    measureReferences();
    printReferences();
    printTimings();
    if (!mOptions.json.empty()) {
        writeJson();
    }
    return kOk;
}

void PipelineBench::prepare() {
    mSettings = resolveSettings(mOptions.settings);
    if (mOptions.frames < 1) {
        throw InputError("--frames must be at least 1");
    }
    // An EXR --input with depth and a camera, whose 3D layers are uploaded once the context exists.
    std::optional<DecodedFrame> file3d;
    if (std::optional<DecodedFrame> file = decodeRendererFrame(mOptions)) {
        mImage = colourOf(*file);
        if (!file->depth.empty() && file->camera) {
            if (mOptions.motion != 0.0f || mOptions.floor) {
                throw InputError(fmt::format("bench: --motion and --floor shape the synthetic 3D frame; {} "
                                             "brings its own depth, normals and camera",
                                             mOptions.input.string()));
            }
            file3d = std::move(file);
        }
    } else {
        mImage = benchInput(mOptions);
    }
    mContext.emplace(commandContext());
    if (!mOptions.input.empty()) {
        requireTextureFits(mOptions.input, mImage.width, mImage.height);
    }
    mPipeline =
        std::make_unique<Pipeline>(PipelineCreateInfo{.settings = mSettings, .forceLdr = mOptions.forceLdr});
    if (!mPipeline->capabilities().timerQueries) {
        throw std::runtime_error("this GL implementation has no timer queries; nothing to measure");
    }
    mPipeline->timers().setSynchronous(mOptions.sync);
    mInput.emplace(
        makeTexture(mImage, "bench input", mOptions.inputFormat == "rgba16f" ? GL_RGBA16F : GL_RGBA32F));
    // 3D inputs for the passes that need them (TAA; contact shadows in the lighting stage): a wall 10 units
    // away seen by a still camera, still unless --motion moves it. The sequencer runs nothing on them unless
    // such a pass is on, so the 2D chain's figures are unchanged. Volumetric light alone: its worst case.
    // With contact shadows too, theirs (the sun behind the camera, where volumetric light does no work).
    if (file3d) {
        // A renderer's frame: its depth, normals, motion, camera and sun (no shadow map), the colour as the
        // bench uploaded it.
        mFileTextures.emplace();
        mInputs = mFileTextures->upload(*file3d);
        mInputs.color = &*mInput;
    } else {
        mInputs3d.emplace(mImage.width, mImage.height,
                          mSettings.volumetricLight.enabled && !mSettings.contactShadows.enabled,
                          mOptions.motion, mOptions.floor);
        mInputs = mInputs3d->frame(*mInput);
    }
    // The line is drawn between frames, never inside a timed pass or the whole-frame pair of timestamps.
    mProgress.emplace("bench", std::size_t(mOptions.warmup) + 2 * std::size_t(mOptions.frames));
}

double PipelineBench::submitFrame() {
    const auto start = std::chrono::steady_clock::now();
    mPipeline->beginFrame({.frameIndex = mFrame});
    mPipeline->renderLighting(mInputs, {.frameIndex = mFrame});
    mPipeline->execute(mInputs, {.frameIndex = mFrame++});
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void PipelineBench::warmUp() {
    for (int i = 0; i < mOptions.warmup; ++i) {
        mWarmupSubmitMs.push_back(submitFrame());
        mPipeline->timers().drain();
        mProgress->advance();
    }
    // Four times what a warm frame took the CPU to submit, at least half a millisecond.
    if (mOptions.queueAhead) {
        mAhead = std::make_unique<QueueAhead>();
        mAhead->calibrate(std::max(0.5, 4.0 * median(mWarmupSubmitMs)));
    }
}

void PipelineBench::timePasses() {
    for (int i = 0; i < mOptions.frames; ++i) {
        timedRun(
            mAhead.get(), [&] { mSubmitMs.push_back(submitFrame()); },
            [&] { mSamples.add(mPipeline->timers().drain()); });
        mProgress->advance();
    }
}

void PipelineBench::timeWholeFrame() {
    // The whole frame between one pair of timestamps, with the passes' own timers off: the chain as a frame
    // loop runs it, gaps between passes included and no per-pass timestamps.
    mPipeline->timers().setEnabled(false);
    mWholeFrameMs = medianTimed(
        mOptions, mAhead.get(), [&] { submitFrame(); }, [&] { mProgress->advance(); });
    // With the queue kept ahead, the frame as a host submits it to an idle GPU too, beside it.
    mAsSubmittedMs = mAhead ? medianTimed(
                                  mOptions, nullptr, [&] { submitFrame(); }, [] {})
                            : mWholeFrameMs;
    mPipeline->timers().setEnabled(true);
}

std::string PipelineBench::inputName() const {
    return mOptions.input.empty() ? std::string("synthetic") : mOptions.input.string();
}

void PipelineBench::printSetup() const {
    const PipelineStatus t = mPipeline->status();
    const ContextInfo& info = mContext->info();
    std::printf("photopic bench: %dx%d %s input (%s%s), %d frames after %d warm-up, %s\n", mImage.width,
                mImage.height, imageFormatName(mInput->format()).c_str(), inputName().c_str(),
                mirrored() ? ", mirrored to this size" : "", mOptions.frames, mOptions.warmup,
                info.renderer.c_str());
    if (mFileTextures) {
        std::printf("3D inputs: the file's (depth%s%s, camera%s)\n", mInputs.normals ? ", normals" : "",
                    mInputs.motion ? ", motion" : "", mInputs.sunDirection ? ", sun" : "; no sun");
    } else {
        std::printf("3D inputs: synthetic (a wall%s, %s)\n", mOptions.floor ? " and a floor" : "",
                    mOptions.motion != 0.0f ? fmt::format("moving {} px a frame", mOptions.motion).c_str()
                                            : "still");
    }
    std::printf("colour path: %s (%s), quality %s, bloom levels %d\n",
                t.path == ColorPath::Hdr ? "HDR" : "LDR", t.pathReason.c_str(),
                std::string(qualityNames()[std::size_t(t.quality)]).c_str(), t.bloomLevels);
    if (mOptions.sync) {
        std::printf("--sync: glFinish() around every pass; 'wall ms' holds the pass's own work and nothing "
                    "else\n");
    } else if (isSoftwareRenderer()) {
        std::printf("note: %s runs a draw when its scene is flushed, which can fall outside the pass's "
                    "timestamps and into a later pass's: run with --sync for per-pass wall times\n",
                    info.renderer.c_str());
    }
}

void PipelineBench::measureReferences() {
    // The one-value copy first: on llvmpipe whichever copy runs first reads up to 20% slower.
    mConstantCopy =
        measureCopy(constantTexture(mInput->extent(), mInput->format()), "constant", mOptions, mAhead.get());
    mCopy = measureCopy(*mInput, "frame", mOptions, mAhead.get());
    mReduction = measureReduction(*mInput, mOptions, mAhead.get());
}

void PipelineBench::printReferences() const {
    const CopyReference& copy = mCopy;
    const CopyReference& reduction = mReduction;
    std::printf("bandwidth reference: %s copy of the frame %dx%d, %.3f ms, %.2f MB, %.2f GB/s (%s); of a "
                "texture of one value: %.3f ms, %.2f GB/s\n",
                copy.format.c_str(), mImage.width, mImage.height, copy.medianMs, copy.bytes / 1e6,
                copy.gbPerSecond(), mOptions.sync ? "wall ms with glFinish" : "GPU timestamps",
                mConstantCopy.medianMs, mConstantCopy.gbPerSecond());
    std::printf(
        "reduction reference: 2x2 box means of the frame into RGBA16F at half size, %.3f ms, %.2f MB, "
        "%.2f GB/s, %.0f%% of the copy's (what a pass that reads a frame and writes a quarter of it "
        "can reach)\n",
        reduction.medianMs, reduction.bytes / 1e6, reduction.gbPerSecond(),
        copy.gbPerSecond() > 0 ? 100.0 * reduction.gbPerSecond() / copy.gbPerSecond() : 0.0);
}

void PipelineBench::printTimings() {
    std::printf("CPU: %.3f ms to submit a frame (median, beginFrame to execute's return)\n",
                median(mSubmitMs));
    if (mAhead) {
        std::printf(
            "--queue-ahead: %.3f ms of untimed GPU work before each timed frame and copy; the GPU was "
            "still on it when the CPU had submitted the frame on %d of %d%s\n",
            mAhead->busyMs(), mAhead->held(), mAhead->timed(),
            mAhead->held() < mAhead->timed()
                ? " (on the others the timestamps also hold time the GPU waited for the CPU)"
                : "");
    }
    mTable = printPassTable(mOptions, mSamples, mCopy);
    std::printf("%-36s %12.3f   (one timestamp pair around each frame, the passes' timers off)\n",
                "whole frame", mWholeFrameMs);
    if (mAhead) {
        std::printf("%-36s %12.3f   (the same, each frame submitted to an idle GPU)\n",
                    "whole frame, as submitted", mAsSubmittedMs);
    }
}

void PipelineBench::writeJson() const {
    const PipelineStatus t = mPipeline->status();
    const ContextInfo& info = mContext->info();
    nlohmann::json doc = {
        {"width", mImage.width},
        {"height", mImage.height},
        {"frames", mOptions.frames},
        {"warmup", mOptions.warmup},
        {"renderer", info.renderer},
        {"vendor", info.vendor},
        {"driver", info.version},
        {"platform", info.platform},
        {"inputFormat", imageFormatName(mInput->format())},
        {"input", inputName()},
        {"inputMirrored", mirrored()},
        {"copyReference", mCopy.json()},
        {"constantCopy", mConstantCopy.json()},
        {"reduceReference", mReduction.json()},
        {"colourPath", t.path == ColorPath::Hdr ? "hdr" : "ldr"},
        {"colourPathReason", t.pathReason},
        {"quality", std::string(qualityNames()[std::size_t(t.quality)])},
        {"bloomLevels", t.bloomLevels},
        {"passes", mTable.passes},
        {"totalMedianGpuMs", mTable.totalMs},
        {"frameMedianGpuMs", mWholeFrameMs},
        {"totalBytesMoved", mTable.totalBytes},
        {"sync", mOptions.sync},
        {"motionPixels", mOptions.motion},
        {"floor", mOptions.floor},
        {"inputs3d", inputs3dName()},
        {"cpuSubmitMedianMs", median(mSubmitMs)},
    };
    if (mAhead) {
        doc["queueAhead"] = {{"busyMs", mAhead->busyMs()},
                             {"framesHeld", mAhead->held()},
                             {"framesTimed", mAhead->timed()},
                             {"frameAsSubmittedMedianGpuMs", mAsSubmittedMs}};
    }
    if (mOptions.sync) {
        doc["totalMedianWallMs"] = mTable.totalWallMs;
    }
    writeJsonAtomically(mOptions.json, doc);
    std::printf("wrote %s\n", mOptions.json.string().c_str());
}

} // namespace photopic::cli
