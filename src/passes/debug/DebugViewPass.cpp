#include "passes/debug/DebugViewPass.h"

#include "core/Log.h"
#include "passes/Bindings.h"

#include <algorithm>

namespace photopic {

namespace {
/// Histogram panel: margin and largest size in pixels; it shrinks with small images.
constexpr int kPanelMargin = 8;
constexpr int kPanelMaxWidth = 512;
constexpr int kPanelMaxHeight = 160;

constexpr ResourceUse kSceneViewUses[] = {{Resource::SceneColor, Access::Read},
                                          {Resource::ExposureState, Access::Read},
                                          {Resource::Histogram, Access::Read},
                                          {Resource::Bloom, Access::ReadOptional},
                                          {Resource::MeteringMask, Access::ReadOptional},
                                          {Resource::DebugColor, Access::Write}};
constexpr ResourceUse kDepthViewUses[] = {{Resource::LinearDepth, Access::Read},
                                          {Resource::Camera, Access::Read},
                                          {Resource::DebugColor, Access::Write}};
constexpr ResourceUse kNormalsViewUses[] = {{Resource::Normals, Access::Read},
                                            {Resource::DebugColor, Access::Write}};
constexpr ResourceUse kMotionViewUses[] = {{Resource::Motion, Access::Read},
                                           {Resource::DebugColor, Access::Write}};
constexpr ResourceUse kTaaViewUses[] = {{Resource::TaaDebug, Access::Read},
                                        {Resource::DebugColor, Access::Write}};
constexpr ResourceUse kContactShadowViewUses[] = {{Resource::ContactShadows, Access::Read},
                                                  {Resource::DebugColor, Access::Write}};
constexpr ResourceUse kContactShadowStepsViewUses[] = {{Resource::ContactShadowSteps, Access::Read},
                                                       {Resource::DebugColor, Access::Write}};
constexpr ResourceUse kCocViewUses[] = {{Resource::DofCoc, Access::Read},
                                        {Resource::DebugColor, Access::Write}};
constexpr ResourceUse kSsrViewUses[] = {{Resource::Reflections, Access::Read},
                                        {Resource::DebugColor, Access::Write}};
constexpr ResourceUse kVelocityTilesViewUses[] = {{Resource::VelocityTiles, Access::Read},
                                                  {Resource::DebugColor, Access::Write}};
constexpr ResourceUse kVolumetricLightViewUses[] = {{Resource::VolumetricLight, Access::Read},
                                                    {Resource::DebugColor, Access::Write}};
constexpr ResourceUse kAoViewUses[] = {{Resource::AmbientOcclusion, Access::Read},
                                       {Resource::DebugColor, Access::Write}};

/// Views of data rather than of the image: written to EXR, they keep their values.
bool isDataView(DebugView view) {
    return view == DebugView::ContactShadows || view == DebugView::ContactShadowSteps ||
           view == DebugView::Coc || view == DebugView::Ssr || view == DebugView::VelocityTiles ||
           view == DebugView::VolumetricLight || view == DebugView::Gtao;
}

bool isInputView(DebugView view) {
    return view == DebugView::Depth || view == DebugView::Normals || view == DebugView::Motion ||
           view == DebugView::TaaHistoryWeight || view == DebugView::Disocclusion || isDataView(view);
}
} // namespace

DebugViewPass::DebugViewPass()
    : mSceneProgram("passes/debug/debug_view.comp.glsl", {})
    , mInputProgram("passes/debug/debug_inputs.comp.glsl", {})
    , mInputRawProgram("passes/debug/debug_inputs.comp.glsl", {{"RAW", "1"}})
    , mSceneParameters("debug scene view parameters")
    , mInputParameters("debug input view parameters") {}

std::span<const ResourceUse> DebugViewPass::uses() const {
    switch (mView) {
    case DebugView::Depth:
        return kDepthViewUses;
    case DebugView::Normals:
        return kNormalsViewUses;
    case DebugView::Motion:
        return kMotionViewUses;
    case DebugView::TaaHistoryWeight:
    case DebugView::Disocclusion:
        return kTaaViewUses;
    case DebugView::ContactShadows:
        return kContactShadowViewUses;
    case DebugView::ContactShadowSteps:
        return kContactShadowStepsViewUses;
    case DebugView::Coc:
        return kCocViewUses;
    case DebugView::Ssr:
        return kSsrViewUses;
    case DebugView::VelocityTiles:
        return kVelocityTilesViewUses;
    case DebugView::VolumetricLight:
        return kVolumetricLightViewUses;
    case DebugView::Gtao:
        return kAoViewUses;
    default:
        return kSceneViewUses;
    }
}

void DebugViewPass::configure(const Settings& settings) {
    mView = settings.debug.view;
    if (!isSceneView(mView)) {
        return;
    }
    const int bitDepth = settings.output.bitDepth;
    if (!isInputView(mView)) {
        mSceneProgram.prepare(bitDepth);
    } else {
        (isDataView(mView) ? mInputRawProgram : mInputProgram).prepare(bitDepth);
    }
}

void DebugViewPass::execute(FrameContext& ctx, FrameResources& resources) {
    const int bitDepth = ctx.settings.output.bitDepth;
    const GLenum format = displayFormat(bitDepth);
    PooledTexture& out =
        resources.pool().acquire({.extent = ctx.extent, .format = format, .debugName = "debug view"});
    const Extent e = ctx.extent;
    const bool raw = isDataView(mView);
    // One read of the source and a display write, plus the RGBA32F copy of a data view's values.
    const double bytes = (raw ? 32 : 8) + bytesPerTexel(format);
    ScopedGpuTimer timer(ctx.timers, "debug view", double(e.width) * e.height * bytes);
    mRaw = nullptr;
    if (raw) {
        // The same values unclamped: what an EXR of the view holds (sceneReferred()).
        mRaw = &resources.pool()
                    .acquire(
                        {.extent = ctx.extent, .format = GL_RGBA32F, .debugName = "debug view (raw values)"})
                    .texture();
    }
    const Program& program = isInputView(mView) ? bindInputView(ctx, resources, bitDepth, out.texture(), mRaw)
                                                : bindSceneView(ctx, resources, bitDepth, out.texture());
    dispatch(program, e, Barrier::ImageWrite);
    resources.bind(Resource::DebugColor, out.texture());
}

const Program& DebugViewPass::bindSceneView(const FrameContext& ctx, const FrameResources& resources,
                                            int bitDepth, const Texture& out) {
    const AutoExposureSettings& ae = ctx.settings.autoExposure;
    const Texture* scene = resources.texture(Resource::SceneColor);
    const Texture* bloom = resources.texture(Resource::Bloom);
    const Texture* mask = resources.texture(Resource::MeteringMask);
    if (mView == DebugView::Bloom && !bloom) {
        try {
            warnOnce("debug.bloom.missing",
                     "debug.view is \"bloom\" but the pipeline has no bloom; showing black");
        } catch (...) { // logging must not take the frame down
        }
    }
    const Program& p = mSceneProgram.at(bitDepth);
    mSceneParameters.update({.view = int(mView),
                             .hasBloom = bloom ? 1 : 0,
                             .hasMask = mask ? 1 : 0,
                             .meteringMode = int(ae.metering),
                             .log2Min = ae.histogramLog2Min,
                             .log2Max = ae.histogramLog2Max,
                             .spotUv = {ae.spot.u, ae.spot.v},
                             .spotRadius = ae.spot.radius});
    mSceneParameters.bind(kBindingParameters);
    p.use();
    bindExposureStateForReading(*resources.buffer(Resource::ExposureState));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingHistogram,
                     resources.buffer(Resource::Histogram)->id());
    bind(mScene, *scene);
    bind(mMask, mask ? *mask : *scene);
    bind(mBloom, bloom ? *bloom : *scene);
    bind(mSceneOutput, out, ImageAccess::Write);
    return p;
}

const Program& DebugViewPass::bindInputView(const FrameContext& ctx, const FrameResources& resources,
                                            int bitDepth, const Texture& out, const Texture* raw) {
    const Resource source = mView == DebugView::Depth                ? Resource::LinearDepth
                            : mView == DebugView::Normals            ? Resource::Normals
                            : mView == DebugView::Motion             ? Resource::Motion
                            : mView == DebugView::ContactShadows     ? Resource::ContactShadows
                            : mView == DebugView::ContactShadowSteps ? Resource::ContactShadowSteps
                            : mView == DebugView::Coc                ? Resource::DofCoc
                            : mView == DebugView::Ssr                ? Resource::Reflections
                            : mView == DebugView::VelocityTiles      ? Resource::VelocityTiles
                            : mView == DebugView::VolumetricLight    ? Resource::VolumetricLight
                            : mView == DebugView::Gtao                 ? Resource::AmbientOcclusion
                                                                     : Resource::TaaDebug;
    const Program& p = (raw ? mInputRawProgram : mInputProgram).at(bitDepth);
    const Camera* camera = ctx.inputs.camera;
    mInputParameters.update({.view = int(mView),
                             .octahedral = ctx.inputs.normalEncoding == NormalEncoding::Octahedral ? 1 : 0,
                             .nearPlane = camera ? camera->nearPlane : 0.1f,
                             .farPlane = camera ? camera->farPlane : 1000.0f,
                             .maxCoc = ctx.settings.dof.maxCocRadius});
    mInputParameters.bind(kBindingParameters);
    p.use();
    bind(mInput, *resources.texture(source));
    bind(mInputOutput, out, ImageAccess::Write);
    if (raw) {
        bind(mRawOutput, *raw, ImageAccess::Write);
    }
    return p;
}

HistogramOverlayPass::HistogramOverlayPass()
    : mProgram("passes/debug/debug_histogram.comp.glsl", {})
    , mParameters("histogram overlay parameters") {}

std::span<const ResourceUse> HistogramOverlayPass::uses() const {
    static constexpr ResourceUse kUses[] = {{Resource::DisplayColor, Access::Read},
                                            {Resource::Histogram, Access::Read},
                                            {Resource::ExposureState, Access::Read},
                                            {Resource::DisplayColor, Access::Write}};
    return kUses;
}

void HistogramOverlayPass::configure(const Settings& settings) {
    if (settings.debug.view == DebugView::Histogram) {
        mProgram.prepare(settings.output.bitDepth);
    }
}

void HistogramOverlayPass::execute(FrameContext& ctx, FrameResources& resources) {
    const int bitDepth = ctx.settings.output.bitDepth;
    const GLenum format = displayFormat(bitDepth);
    PooledTexture& out =
        resources.pool().acquire({.extent = ctx.extent, .format = format, .debugName = "histogram overlay"});
    const Extent e = ctx.extent;
    const AutoExposureSettings& ae = ctx.settings.autoExposure;
    // The display image read and written once; the histogram is 1 KB.
    ScopedGpuTimer timer(ctx.timers, "histogram overlay",
                         double(e.width) * e.height * 2 * bytesPerTexel(format));
    bindExposureStateForReading(*resources.buffer(Resource::ExposureState));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingHistogram,
                     resources.buffer(Resource::Histogram)->id());
    const Program& p = mProgram.at(bitDepth);
    const int width = std::min(kPanelMaxWidth, std::max(e.width - 2 * kPanelMargin, 1));
    const int height = std::min(kPanelMaxHeight, std::max(e.height / 3, 1));
    mParameters.update({.panel = {float(kPanelMargin), float(kPanelMargin), float(width), float(height)},
                        .log2Min = ae.histogramLog2Min,
                        .log2Max = ae.histogramLog2Max,
                        .keyValue = ae.keyValue});
    mParameters.bind(kBindingParameters);
    p.use();
    bind(mDisplay, *resources.texture(Resource::DisplayColor));
    bind(mOutput, out.texture(), ImageAccess::Write);
    dispatch(p, e, Barrier::ImageWrite);
    resources.bind(Resource::DisplayColor, out.texture());
}

} // namespace photopic
