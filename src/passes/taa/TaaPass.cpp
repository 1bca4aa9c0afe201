#include "passes/taa/TaaPass.h"

#include "core/Log.h"
#include "passes/Bindings.h"

#include <fmt/format.h>

#include <iterator>

namespace photopic {

namespace {
/// Motion, in pixels per frame, from which the history is clipped fully to the neighbourhood box; where the
/// neighbourhood moves slower it is clipped in proportion (see taa_resolve.comp.glsl).
constexpr float kStillPixels = 0.25f;

} // namespace

TaaPass::TaaPass()
    : mParameters("taa parameters")
    , mNoDebug({.extent = {1, 1}, .format = GL_RG8, .debugName = "taa debug (unused)"}) {}

std::span<const ResourceUse> TaaPass::uses() const {
    static constexpr ResourceUse kUses[] = {
        {Resource::SceneColor, Access::Read},     {Resource::Motion, Access::Read},
        {Resource::ExposureState, Access::Read},  {Resource::LinearDepth, Access::ReadOptional},
        {Resource::Camera, Access::ReadOptional}, {Resource::SceneColor, Access::Write},
        {Resource::TaaDebug, Access::Write}};
    return kUses;
}

bool TaaPass::enabled(const FrameContext& ctx) const {
    return ctx.hdr && ctx.settings.temporalAntiAliasing(); // on the HDR path when aa.mode selects it
}

const Texture* TaaPass::debugTarget(const FrameContext& ctx, FrameResources& resources) {
    const DebugView view = ctx.settings.debug.view;
    if (view != DebugView::TaaHistoryWeight && view != DebugView::Disocclusion) {
        return nullptr;
    }
    return &resources.pool().acquireNearest(ctx.extent, GL_RG8, "taa debug");
}

TaaParameters TaaPass::parameters(const FrameContext& ctx, const FrameResources& resources,
                                  bool debug) const {
    const TaaSettings& s = ctx.settings.taa;
    // null when validation dropped it
    const Camera* camera = resources.has(Resource::Camera) ? ctx.inputs.camera : nullptr;
    return {.invProjection = camera ? glm::inverse(camera->projection) : glm::mat4(1.0f),
            .viewToPreviousClip =
                camera ? camera->prevViewProjection * glm::inverse(camera->view) : glm::mat4(1.0f),
            .blend = s.blendFactor,
            .gamma = s.varianceGamma,
            .feedbackMin = s.feedbackMin,
            .feedbackMax = s.feedbackMax,
            .stillPixels = kStillPixels,
            .hasHistory = mHistory.valid() && !ctx.resetHistory ? 1 : 0,
            .hasDepth = resources.texture(Resource::LinearDepth) ? 1 : 0,
            .hasCamera = camera ? 1 : 0,
            .writeDebug = debug ? 1 : 0,
            .adaptive = s.adaptiveFeedback ? 1 : 0,
            .bilinearHistory = s.historyFilter == HistoryFilter::Bilinear ? 1 : 0,
            .padding = 0};
}

const TaaPass::ResolveProgram& TaaPass::resolveProgram(const TaaParameters& p, GLenum motionFormat) {
    const std::size_t format = formatIndex(motionFormat, kMotionFormats);
    if (format == std::size(kMotionFormats)) { // the pipeline's input validation refuses any other
        throw GlError(
            fmt::format("taa: motion in {}, not a format the pipeline accepts", formatName(motionFormat)));
    }
    return mPrograms.get(std::size_t(p.bilinearHistory != 0) | (std::size_t(p.hasDepth != 0) << 1) |
                             (std::size_t(p.hasCamera != 0) << 2) | (format << 3),
                         {{"TAA_BILINEAR", std::to_string(p.bilinearHistory)},
                          {"TAA_DEPTH", std::to_string(p.hasDepth)},
                          {"TAA_CAMERA", std::to_string(p.hasCamera)},
                          {"TAA_SHARED_TILE", mSharedTile ? "1" : "0"},
                          imageFormatDefine("TAA_MOTION_FORMAT", motionFormat)});
}

void TaaPass::bindInputs(const ResolveProgram& program, const FrameResources& resources,
                         const Texture* debugTarget) const {
    const Texture* depth = resources.texture(Resource::LinearDepth);
    const Texture& motion = *resources.texture(Resource::Motion);
    bindExposureStateForReading(*resources.buffer(Resource::ExposureState));
    // The scene colour is the sanitised copy (or a 3D pass's output over it), RGBA16F like them all.
    bind(program.current, *resources.texture(Resource::SceneColor), ImageAccess::Read);
    // Without a history the shader reads none; a bound texture keeps every sampler complete.
    bind(program.history, mHistory.previous() ? *mHistory.previous() : mHistory.current());
    bind(program.motion, motion, ImageAccess::Read);
    if (depth) {
        bind(program.depth, *depth, ImageAccess::Read); // without depth the program declares none
    }
    bind(program.historyAux, mHistoryAux.previous() ? *mHistoryAux.previous() : mHistoryAux.current(),
         ImageAccess::Read);
    bind(program.outputAux, mHistoryAux.current(), ImageAccess::Write);
    bind(program.output, mHistory.current(), ImageAccess::Write);
    bind(program.debug, debugTarget ? *debugTarget : mNoDebug, ImageAccess::Write);
}

void TaaPass::execute(FrameContext& ctx, FrameResources& resources) {
    // Made on the first frame TAA runs at a size (a pipeline with TAA off holds no history); a new size
    // remakes them and the history starts over.
    mHistory.ensure(ctx.extent, GL_RGBA16F, "taa history");
    mHistoryAux.ensure(ctx.extent, GL_RG16F, "taa history depth and stability");
    const Extent e = ctx.extent;
    const Texture* depth = resources.texture(Resource::LinearDepth);
    const Texture* debug = debugTarget(ctx, resources);
    const double bytes =
        double(e.width) * e.height *
        (8.0 /*current*/ + 12.0 /*history*/ + 4.0 /*motion*/ + (depth ? 4.0 : 0.0) + 12.0 /*output*/);
    ScopedGpuTimer timer(ctx.timers, "taa", bytes);
    const TaaParameters p = parameters(ctx, resources, debug != nullptr);
    mParameters.update(p);
    mParameters.bind(kBindingParameters);
    const ResolveProgram& program = resolveProgram(p, resources.texture(Resource::Motion)->format());
    program.program.use();
    bindInputs(program, resources, debug);
    dispatch(program.program, e, Barrier::None);
    resources.bind(Resource::SceneColor, mHistory.current());
    if (debug) {
        resources.bind(Resource::TaaDebug, *debug);
    }
    mHistory.advance();
    mHistoryAux.advance();
}

} // namespace photopic
