#include "passes/taa/TaaPass.h"

#include "core/Log.h"
#include "passes/Bindings.h"

namespace photopic {

namespace {
/// Motion, in pixels per frame, from which the history is clipped fully to the neighbourhood box; where the
/// neighbourhood moves slower it is clipped in proportion (see taa_resolve.comp.glsl).
constexpr float kStillPixels = 0.25f;

} // namespace

TaaPass::TaaPass()
    : mProgram(makeComputeProgram("passes/taa/taa_resolve.comp.glsl", bindingDefines()))
    , mParameters("taa parameters")
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

void TaaPass::execute(FrameContext& ctx, FrameResources& resources) {
    // Made on the first frame TAA runs at a size (a pipeline with TAA off holds no history); a new size
    // remakes them and the history starts over.
    mHistory.ensure(ctx.extent, GL_RGBA16F, "taa history");
    mHistoryAux.ensure(ctx.extent, GL_RG16F, "taa history depth and stability");
    const Extent e = ctx.extent;
    const TaaSettings& s = ctx.settings.taa;
    const Texture* depth = resources.texture(Resource::LinearDepth);
    const bool hasCamera = resources.has(Resource::Camera);
    const DebugView view = ctx.settings.debug.view;
    const bool debug = view == DebugView::TaaHistoryWeight || view == DebugView::Disocclusion;
    const Texture* debugTarget = nullptr;
    if (debug) {
        debugTarget = &resources.pool()
                           .acquire({.extent = e,
                                     .format = GL_RG8,
                                     .minFilter = GL_NEAREST,
                                     .magFilter = GL_NEAREST,
                                     .debugName = "taa debug"})
                           .texture();
    }
    const double bytes =
        double(e.width) * e.height *
        (8.0 /*current*/ + 12.0 /*history*/ + 4.0 /*motion*/ + (depth ? 4.0 : 0.0) + 12.0 /*output*/);
    ScopedGpuTimer timer(ctx.timers, "taa", bytes);
    const Camera* camera = hasCamera ? ctx.inputs.camera : nullptr; // null when validation dropped it
    mParameters.update({.invProjection = camera ? glm::inverse(camera->projection) : glm::mat4(1.0f),
                        .invView = camera ? glm::inverse(camera->view) : glm::mat4(1.0f),
                        .prevViewProjection = camera ? camera->prevViewProjection : glm::mat4(1.0f),
                        .blend = s.blendFactor,
                        .gamma = s.varianceGamma,
                        .feedbackMin = s.feedbackMin,
                        .feedbackMax = s.feedbackMax,
                        .stillPixels = kStillPixels,
                        .hasHistory = mHistory.valid() && !ctx.resetHistory ? 1 : 0,
                        .hasDepth = depth ? 1 : 0,
                        .hasCamera = camera ? 1 : 0,
                        .writeDebug = debug ? 1 : 0,
                        .adaptive = s.adaptiveFeedback ? 1 : 0,
                        .bilinearHistory = s.historyFilter == HistoryFilter::Bilinear ? 1 : 0,
                        .padding = 0});
    mParameters.bind(kBindingParameters);
    mProgram.use();
    bindExposureStateForReading(*resources.buffer(Resource::ExposureState));
    glBindTextureUnit(0, resources.texture(Resource::SceneColor)->id());
    // Without a history the shader reads none; a bound texture keeps every sampler complete.
    glBindTextureUnit(1, mHistory.previous() ? mHistory.previous()->id() : mHistory.current().id());
    glBindTextureUnit(2, resources.texture(Resource::Motion)->id());
    glBindTextureUnit(3, depth ? depth->id() : resources.texture(Resource::Motion)->id());
    glBindTextureUnit(4, mHistoryAux.previous() ? mHistoryAux.previous()->id() : mHistoryAux.current().id());
    glBindImageTexture(2, mHistoryAux.current().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG16F);
    glBindImageTexture(0, mHistory.current().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glBindImageTexture(1, debugTarget ? debugTarget->id() : mNoDebug.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                       GL_RG8);
    glDispatchCompute(GLuint((e.width + 7) / 8), GLuint((e.height + 7) / 8), 1);
    resources.bind(Resource::SceneColor, mHistory.current());
    if (debugTarget) {
        resources.bind(Resource::TaaDebug, *debugTarget);
    }
    mHistory.advance();
    mHistoryAux.advance();
}

} // namespace photopic
