#include "passes/contactshadows/ContactShadowsPass.h"

#include "passes/Bindings.h"

#include <algorithm>
#include <string>

namespace photopic {

namespace {

constexpr ResourceUse kUses[] = {
    {Resource::LinearDepth, Access::Read},        {Resource::Camera, Access::Read},
    {Resource::SunDirection, Access::Read},       {Resource::Normals, Access::ReadOptional},
    {Resource::Motion, Access::ReadOptional},     {Resource::ContactShadows, Access::Write},
    {Resource::ContactShadowSteps, Access::Write}};
constexpr ResourceUse kMaskedUses[] = {
    {Resource::LinearDepth, Access::Read},     {Resource::Camera, Access::Read},
    {Resource::SunDirection, Access::Read},    {Resource::ObjectId, Access::Read},
    {Resource::Normals, Access::ReadOptional}, {Resource::Motion, Access::ReadOptional},
    {Resource::ContactShadows, Access::Write}, {Resource::ContactShadowSteps, Access::Write}};

/// Edge fade width: 2% of the image height (at least 2 px), where an occluder may be partly off screen.
float edgeFadePixels(Extent e) {
    return std::max(2.0f, 0.02f * float(e.height));
}

} // namespace

ContactShadowsPass::ContactShadowsPass()
    : mResolve{ResolveProgram(makeComputeProgram("passes/contactshadows/contact_shadows_resolve.comp.glsl",
                                                 bindingDefines({{"CONTACT_SHADOWS_MOTION", "0"}}))),
               ResolveProgram(makeComputeProgram("passes/contactshadows/contact_shadows_resolve.comp.glsl",
                                                 bindingDefines({{"CONTACT_SHADOWS_MOTION", "1"}})))}
    , mParameters("contact shadow parameters")
    , mNoSteps({.extent = {1, 1}, .format = GL_R8, .debugName = "contact shadow steps (unused)"})
    , mNoObjectIds({.extent = {1, 1},
                    .format = GL_R32UI,
                    .minFilter = GL_NEAREST,
                    .magFilter = GL_NEAREST,
                    .debugName = "contact shadow object ids (unused)"})
    , mObjectIdSampler(Sampler::nearest("contact shadow object ids")) {}

std::span<const ResourceUse> ContactShadowsPass::uses() const {
    if (mMasked) {
        return kMaskedUses;
    }
    return kUses;
}

void ContactShadowsPass::configure(const Settings& settings) {
    mMasked = !settings.contactShadows.mask.empty();
}

void ContactShadowsPass::invalidateHistory() {
    if (!mRestarted) {
        mHistory.invalidate();
    }
    mRestarted = false;
}

ContactShadowsPass::Targets ContactShadowsPass::acquireTargets(const FrameContext& ctx,
                                                               FrameResources& resources) {
    const Extent e = ctx.extent;
    TexturePool& pool = resources.pool();
    Targets t;
    t.surface = &pool.acquireNearest(e, GL_RGBA32F, "contact shadow surfaces");
    t.raw = &pool.acquireNearest(e, GL_R16F, "contact shadows (this frame)");
    if (ctx.settings.debug.view == DebugView::ContactShadowSteps) {
        t.steps = &pool.acquireNearest(e, GL_R8, "contact shadow steps");
    }
    return t;
}

ContactShadowParameters ContactShadowsPass::parameters(const FrameContext& ctx,
                                                       const FrameResources& resources, bool writeSteps,
                                                       bool hasHistory) const {
    const ContactShadowsSettings& s = ctx.settings.contactShadows;
    const Camera& camera = *ctx.inputs.camera;
    const Extent e = ctx.extent;
    const Texture* objectId = mMasked ? resources.texture(Resource::ObjectId) : nullptr;
    ContactShadowParameters p{};
    p.projection = camera.projection;
    p.reprojection = camera.prevViewProjection * glm::inverse(camera.view);
    viewRays(camera.projection, p.rayNear, p.rayFar);
    const glm::vec3 sun = glm::normalize(glm::mat3(camera.view) * glm::normalize(*ctx.inputs.sunDirection));
    p.sunView = glm::vec4(sun, 0.0f);
    p.fullSize = glm::vec2(float(e.width), float(e.height));
    p.distance = s.distance;
    p.thickness = s.thickness;
    p.strength = s.strength;
    p.steps = s.stepCount();
    p.frame = std::uint32_t(ctx.time.frameIndex % 1024u);
    p.maskCount = objectId ? int(std::min(s.mask.size(), kMaxContactShadowMaskIds)) : 0;
    for (int i = 0; i < p.maskCount; ++i) {
        p.mask[i / 4][i % 4] = s.mask[std::size_t(i)];
    }
    p.writeSteps = writeSteps ? 1 : 0;
    p.hasHistory = hasHistory ? 1 : 0;
    p.hasMotion = resources.texture(Resource::Motion) ? 1 : 0;
    p.edgeFade = edgeFadePixels(e);
    p.historyWeight = kHistoryWeight;
    return p;
}

void ContactShadowsPass::surfaces(const FrameContext& ctx, const FrameResources& resources,
                                  const Targets& t) {
    const Extent e = ctx.extent;
    const Texture& depth = *resources.texture(Resource::LinearDepth);
    const Texture* normals = resources.texture(Resource::Normals);
    const Texture* objectId = mMasked ? resources.texture(Resource::ObjectId) : nullptr;
    const int kind = normalsSource(ctx, resources);
    const SurfaceProgram& s =
        mSurface.get(std::size_t(kind), {{"CONTACT_SHADOWS_NORMALS", std::to_string(kind)}});
    s.program.use();
    bind(s.depth, depth, ImageAccess::Read);
    bind(s.normals, normals ? *normals : depth);
    bind(s.objectId, objectId ? *objectId : mNoObjectIds);
    bindSampler(s.objectId, objectId ? &mObjectIdSampler : nullptr);
    {
        // Depth and the host's normal (or four more depths), the mask's id, one RGBA32F texel out.
        ScopedGpuTimer timer(ctx.timers, "contact shadow surfaces",
                             double(e.width) * e.height *
                                 (4.0 + (normals ? 8.0 : 16.0) + (objectId ? 4.0 : 0.0) + 16.0));
        bind(s.out, *t.surface, ImageAccess::Write);
        dispatch(s.program, e, Barrier::None);
    }
    memoryBarrier(Barrier::ComputeRead);
    bindSampler(s.objectId, nullptr);
}

void ContactShadowsPass::march(const FrameContext& ctx, const FrameResources& resources, const Targets& t) {
    const Extent e = ctx.extent;
    const bool perspective = isPerspective(ctx.inputs.camera->projection);
    const MarchProgram& m =
        mMarch.get(perspective ? 1u : 0u, {{"CONTACT_SHADOWS_PERSPECTIVE", perspective ? "1" : "0"}});
    // The surfaces read once from memory (a short march stays in the cache), the result written (and the
    // steps view).
    ScopedGpuTimer timer(ctx.timers, "contact shadows",
                         double(e.width) * e.height * (16.0 + 2.0 + (t.steps ? 1.0 : 0.0)));
    m.program.use();
    bind(m.depth, *resources.texture(Resource::LinearDepth), ImageAccess::Read);
    bind(m.surface, *t.surface, ImageAccess::Read);
    bind(m.raw, *t.raw, ImageAccess::Write);
    bind(m.steps, t.steps ? *t.steps : mNoSteps, ImageAccess::Write);
    dispatch(m.program, e, Barrier::None);
}

void ContactShadowsPass::resolve(const FrameContext& ctx, const FrameResources& resources, const Targets& t) {
    const Extent e = ctx.extent;
    const Texture& depth = *resources.texture(Resource::LinearDepth);
    const Texture* motion = resources.texture(Resource::Motion);
    // This frame's values (a tile with its border in shared memory), depth, motion, the history and the
    // output.
    ScopedGpuTimer timer(ctx.timers, "contact shadows resolve",
                         double(e.width) * e.height * (2.0 + 4.0 + 4.0 + 2.0 + 2.0));
    const ResolveProgram& r = mResolve[motion ? 1 : 0];
    r.program.use();
    bind(r.depth, depth, ImageAccess::Read);
    bind(r.raw, *t.raw, ImageAccess::Read);
    bind(r.history, mHistory.previous() ? *mHistory.previous() : *t.raw);
    bind(r.motion, motion ? *motion : depth);
    bind(r.out, mHistory.current(), ImageAccess::Write);
    dispatch(r.program, e, Barrier::None);
}

void ContactShadowsPass::execute(FrameContext& ctx, FrameResources& resources) {
    mHistory.ensure(ctx.extent, GL_R16F, "contact shadows");
    const Targets t = acquireTargets(ctx, resources);
    const bool hasHistory = mHistory.valid() && !ctx.resetHistory;
    mRestarted = ctx.resetHistory;
    mParameters.update(parameters(ctx, resources, t.steps != nullptr, hasHistory));
    mParameters.bind(kBindingParameters);
    surfaces(ctx, resources, t);
    march(ctx, resources, t);
    memoryBarrier(Barrier::ComputeRead);
    resolve(ctx, resources, t);
    resources.bind(Resource::ContactShadows, mHistory.current());
    if (t.steps) {
        resources.bind(Resource::ContactShadowSteps, *t.steps);
    }
    mHistory.advance();
}

} // namespace photopic
