#include "passes/metering/MeteringPass.h"

#include "core/Log.h"
#include "gl/Capabilities.h"
#include "gl/TextureIo.h"
#include "io/ImageIO.h"
#include "passes/Bindings.h"

#include <cstdint>
#include <string>

namespace photopic {

namespace {

int meteringModeIndex(MeteringPass::Weights w) {
    switch (w) {
    case MeteringPass::Weights::Average:
        return int(MeteringMode::Average);
    case MeteringPass::Weights::Center:
        return int(MeteringMode::Center);
    case MeteringPass::Weights::Mask:
        return int(MeteringMode::Mask);
    case MeteringPass::Weights::Spot:
    case MeteringPass::Weights::None:
        break;
    }
    return -1; // the metering dispatch computes no partials
}

/// The rows program's variant index for a weighting index (meteringModeIndex).
std::size_t rowsVariant(int weights) {
    switch (weights) {
    case int(MeteringMode::Average):
        return 1;
    case int(MeteringMode::Center):
        return 2;
    case int(MeteringMode::Mask):
        return 3;
    default:
        return 0;
    }
}

Program rowsProgram(int weights) {
    return makeComputeProgram("passes/metering/metering_rows.comp.glsl",
                              bindingDefines({{"WEIGHTS", std::to_string(weights)}}));
}

/// The header every frame's metering starts from (an empty min/max), copied on the GPU into the working
/// buffer: a working buffer the CPU rewrites every frame is one a driver may move to host memory.
Buffer meteringResetBuffer() {
    GpuMeteringHeader header;
    header.minBits = 0xffffffffu;
    return Buffer(
        {.size = sizeof(header), .flags = 0, .data = &header, .debugName = "metering header reset"});
}

} // namespace

MeteringPass::MeteringPass()
    : mMeter(makeComputeProgram("passes/metering/metering.comp.glsl", bindingDefines()))
    , mMeterRows{rowsProgram(-1), rowsProgram(int(MeteringMode::Average)),
                 rowsProgram(int(MeteringMode::Center)), rowsProgram(int(MeteringMode::Mask))}
    , mMeterHistogram(makeComputeProgram("passes/metering/metering_histogram.comp.glsl",
                                         bindingDefines({{"RUN", std::to_string(kHistogramRun)}})))
    , mReduce(makeComputeProgram("passes/metering/metering_reduce.comp.glsl", bindingDefines()))
    , mMeterParameters("metering parameters")
    , mReduceParameters("metering reduce parameters")
    , mHistogram({.size = kGpuHistogramBytes, .flags = 0, .data = nullptr, .debugName = "histogram bins"})
    , mMeteringReset(meteringResetBuffer())
    , mRowsWithoutHistogram(isSoftwareRenderer()) {}

std::span<const ResourceUse> MeteringPass::uses() const {
    static constexpr ResourceUse kUses[] = {{Resource::SceneColor, Access::Read},
                                            {Resource::Histogram, Access::Write},
                                            {Resource::Metering, Access::Write},
                                            {Resource::MeteringMask, Access::Write}};
    return kUses;
}

void MeteringPass::configure(const Settings& settings) {
    const std::string& path = settings.autoExposure.mask.path;
    if (path == mMaskPath) {
        return;
    }
    // Set-up boundary: an unreadable mask throws IoError naming the file.
    mMask = path.empty() ? Texture() : makeTexture(readImage(path), "metering mask");
    mMaskPath = path;
}

bool MeteringPass::histogramWanted(const Settings& s, bool forTelemetry) noexcept {
    const AutoExposureSettings& ae = s.autoExposure;
    const DebugView view = s.debug.view;
    return (metered(s, forTelemetry) && ae.metering == MeteringMode::Histogram) ||
           view == DebugView::Histogram ||
           (view == DebugView::Metering && ae.metering == MeteringMode::Histogram);
}

MeteringPass::Weights MeteringPass::weightsFor(const AutoExposureSettings& ae, bool metered,
                                               bool haveMask) noexcept {
    if (!metered) {
        return Weights::None;
    }
    switch (ae.metering) {
    case MeteringMode::Average:
        return Weights::Average;
    case MeteringMode::Histogram:
        return Weights::None;
    case MeteringMode::Spot:
        return Weights::Spot;
    case MeteringMode::Center:
        return Weights::Center;
    case MeteringMode::Subject:
        return Weights::None; // the probe pass writes the reading
    case MeteringMode::Mask:
        if (!haveMask) {
            try {
                warnOnce(
                    "metering.mask.missing",
                    "autoExposure.metering is \"mask\" but no mask image is loaded; metering the average");
            } catch (...) { // logging must not take the frame down
            }
            return Weights::Average;
        }
        return Weights::Mask;
    }
    return Weights::Average;
}

void MeteringPass::execute(FrameContext& ctx, FrameResources& resources) {
    const AutoExposureSettings& ae = ctx.settings.autoExposure;
    const Texture* mask = mMask.valid() ? &mMask : nullptr;
    const Outputs out =
        execute({.scene = resources.texture(Resource::SceneColor),
                 .mask = mask,
                 .settings = &ae,
                 .histogram = histogramWanted(ctx.settings, mMeterForTelemetry),
                 .weights = weightsFor(ae, metered(ctx.settings, mMeterForTelemetry), mask != nullptr),
                 .metered = metered(ctx.settings, mMeterForTelemetry),
                 .timers = ctx.timers});
    resources.bind(Resource::Histogram, *out.histogram);
    resources.bind(Resource::Metering, *out.metering);
    if (mask) {
        resources.bind(Resource::MeteringMask, *mask);
    }
}

void MeteringPass::resize(Extent extent) {
    if (mMetering.valid() && mExtent == extent) {
        return;
    }
    mExtent = extent;
    mCleared = false; // the new partials buffer holds nothing defined
    mGroupsX = (extent.width + kGroupSize - 1) / kGroupSize;
    mGroupsY = (extent.height + kGroupSize - 1) / kGroupSize;
    const std::size_t bytes = sizeof(GpuMeteringHeader) + std::size_t(mGroupsX) * std::size_t(mGroupsY) *
                                                              std::size_t(kGroupSize) * 2 * sizeof(float);
    mMetering = Buffer({.size = bytes, .flags = 0, .data = nullptr, .debugName = "metering partials"});
}

void MeteringPass::clear(bool idle) {
    if (!(idle && mCleared)) {
        const std::uint32_t zero = 0;
        glClearNamedBufferData(mHistogram.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
        glCopyNamedBufferSubData(mMeteringReset.id(), mMetering.id(), 0, 0, sizeof(GpuMeteringHeader));
    }
    mCleared = idle;
}

int MeteringPass::meter(const Inputs& in, int weightsIndex) {
    const Extent e = mExtent;
    const AutoExposureSettings& s = *in.settings;
    mMeterParameters.update({.buildHistogram = in.histogram ? 1 : 0,
                             .weights = weightsIndex,
                             .log2Min = s.histogramLog2Min,
                             .log2Max = s.histogramLog2Max});
    mMeterParameters.bind(kBindingParameters);
    // A histogram without partial sums takes the run-length kernel alone. Where the row shader is wanted (a
    // software renderer), a histogram with a mean takes both, two reads of the image instead of the block
    // shader's barriers; elsewhere the block shader builds both in one read.
    const bool histogramOnly = in.histogram && weightsIndex < 0;
    const bool rows = mRowsWithoutHistogram && !histogramOnly;
    if (in.histogram && (histogramOnly || rows)) {
        mMeterHistogram.use();
        const int span = kGroupSize * kHistogramRun; // a group is kHistogramRun times as wide
        dispatch(mMeterHistogram, Groups{GLuint((e.width + span - 1) / span), GLuint(mGroupsY), 1},
                 Barrier::None);
    }
    if (!histogramOnly) {
        const Program& program = rows ? mMeterRows[rowsVariant(weightsIndex)] : mMeter;
        program.use();
        dispatch(program, Groups{GLuint(mGroupsX), GLuint(mGroupsY), 1}, Barrier::None);
    }
    return rows ? kGroupSize : 1;
}

void MeteringPass::reduce(const Inputs& in, int rowsPerGroup) {
    const AutoExposureSettings& s = *in.settings;
    memoryBarrier(Barrier::Storage);
    mReduceParameters.update({.spot = in.weights == Weights::Spot ? 1 : 0,
                              .groups = mGroupsX * mGroupsY,
                              .spotUv = {s.spot.u, s.spot.v},
                              .spotRadius = s.spot.radius,
                              .spotTaps = s.spot.taps,
                              .rowsPerGroup = rowsPerGroup});
    mReduceParameters.bind(kBindingParameters);
    mReduce.use();
    dispatch(mReduce, Groups{}, Barrier::None);
}

MeteringPass::Outputs MeteringPass::execute(const Inputs& in) noexcept {
    const Extent e = mExtent;
    const bool weighted = in.weights != Weights::None && in.weights != Weights::Spot;
    // One read of the image, when anything is metered; otherwise the frame only clears the bins.
    const bool meters = in.histogram || in.weights != Weights::None;
    const double bytes = meters ? double(e.width) * e.height * bytesPerTexel(in.scene->format()) : 0.0;
    DebugGroup group("metering");
    ScopedGpuTimer timer(in.timers, "metering", bytes);

    // Every frame starts from empty bins (nothing carries over between frames) and an empty min/max, which a
    // frame that writes nothing into them finds there if the frame before wrote nothing either.
    clear(!meters && !in.metered);
    if (!meters) {
        return outputs(); // nothing is metered: the bins stay empty
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingHistogram, mHistogram.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingMetering, mMetering.id());
    bind(mScene, *in.scene);
    bind(mMaskSlot, in.weights == Weights::Mask && in.mask ? *in.mask : *in.scene);
    const Weights weights = in.weights == Weights::Mask && !in.mask ? Weights::Average : in.weights;
    const int rowsPerGroup = meter(in, weighted ? meteringModeIndex(weights) : -1);
    if (in.weights != Weights::None) {
        reduce(in, rowsPerGroup);
    }
    memoryBarrier(Barrier::StorageReadback);
    return outputs();
}

} // namespace photopic
