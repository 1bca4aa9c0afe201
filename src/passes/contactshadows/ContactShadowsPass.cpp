#include "passes/contactshadows/ContactShadowsPass.h"

#include "passes/Bindings.h"

#include <algorithm>

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
    : mSurface(
          makeComputeProgram("passes/contactshadows/contact_shadows_surface.comp.glsl", bindingDefines()))
    , mMarch(makeComputeProgram("passes/contactshadows/contact_shadows_march.comp.glsl", bindingDefines()))
    , mResolve(
          makeComputeProgram("passes/contactshadows/contact_shadows_resolve.comp.glsl", bindingDefines()))
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

void ContactShadowsPass::execute(FrameContext& ctx, FrameResources& resources) {
    const ContactShadowSettings& s = ctx.settings.contactShadows;
    const Camera& camera = *ctx.inputs.camera;
    const Extent e = ctx.extent;
    mHistory.ensure(e, GL_R16F, "contact shadows");
    const Texture& surface = resources.pool()
                                 .acquire({.extent = e,
                                           .format = GL_RGBA32F,
                                           .minFilter = GL_NEAREST,
                                           .magFilter = GL_NEAREST,
                                           .debugName = "contact shadow surfaces"})
                                 .texture();
    const Texture& raw = resources.pool()
                             .acquire({.extent = e,
                                       .format = GL_R16F,
                                       .minFilter = GL_NEAREST,
                                       .magFilter = GL_NEAREST,
                                       .debugName = "contact shadows (this frame)"})
                             .texture();
    const bool writeSteps = ctx.settings.debug.view == DebugView::ContactShadowSteps;
    const Texture* steps = nullptr;
    if (writeSteps) {
        steps = &resources.pool()
                     .acquire({.extent = e,
                               .format = GL_R8,
                               .minFilter = GL_NEAREST,
                               .magFilter = GL_NEAREST,
                               .debugName = "contact shadow steps"})
                     .texture();
    }
    const Texture* normals = resources.texture(Resource::Normals);
    const Texture* motion = resources.texture(Resource::Motion);
    const Texture* objectId = mMasked ? resources.texture(Resource::ObjectId) : nullptr;
    const bool hasHistory = mHistory.valid() && !ctx.resetHistory;
    mRestarted = ctx.resetHistory;

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
    p.steps = s.steps;
    p.frame = std::uint32_t(ctx.time.frameIndex % 1024u);
    p.normals = normals == nullptr ? 0 : ctx.inputs.normalEncoding == NormalEncoding::Octahedral ? 2 : 1;
    p.maskCount = objectId ? int(std::min(s.mask.size(), kMaxContactShadowMaskIds)) : 0;
    for (int i = 0; i < p.maskCount; ++i) {
        p.mask[i / 4][i % 4] = s.mask[std::size_t(i)];
    }
    p.writeSteps = writeSteps ? 1 : 0;
    p.hasHistory = hasHistory ? 1 : 0;
    p.hasMotion = motion ? 1 : 0;
    p.edgeFade = edgeFadePixels(e);
    p.historyWeight = kHistoryWeight;

    const double texels = double(e.width) * e.height;
    mParameters.update(p);
    mParameters.bind(kBindingParameters);
    const Texture& depth = *resources.texture(Resource::LinearDepth);
    glBindTextureUnit(0, depth.id());
    glBindTextureUnit(1, normals ? normals->id() : depth.id());
    glBindTextureUnit(2, objectId ? objectId->id() : mNoObjectIds.id());
    glBindSampler(2, objectId ? mObjectIdSampler.id() : 0);
    {
        // Depth and the host's normal (or four more depths), the mask's id, one RGBA32F texel out.
        ScopedGpuTimer timer(ctx.timers, "contact shadow surfaces",
                             texels * (4.0 + (normals ? 8.0 : 16.0) + (objectId ? 4.0 : 0.0) + 16.0));
        mSurface.use();
        glBindImageTexture(0, surface.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
        dispatchPixels(e);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glBindSampler(2, 0);
    {
        // The surfaces read once from memory (a short march stays in the cache), the result written (and the
        // steps view).
        ScopedGpuTimer timer(ctx.timers, "contact shadows", texels * (16.0 + 2.0 + (steps ? 1.0 : 0.0)));
        mMarch.use();
        glBindTextureUnit(3, surface.id());
        glBindImageTexture(0, raw.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R16F);
        glBindImageTexture(1, steps ? steps->id() : mNoSteps.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8);
        dispatchPixels(e);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    {
        // This frame's values (a tile with its border in shared memory), depth, motion, the history and the
        // output.
        ScopedGpuTimer timer(ctx.timers, "contact shadows resolve", texels * (2.0 + 4.0 + 4.0 + 2.0 + 2.0));
        mResolve.use();
        glBindTextureUnit(3, raw.id());
        glBindTextureUnit(4, mHistory.previous() ? mHistory.previous()->id() : raw.id());
        glBindTextureUnit(5, motion ? motion->id() : depth.id());
        glBindImageTexture(0, mHistory.current().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R16F);
        dispatchPixels(e);
    }
    resources.bind(Resource::ContactShadows, mHistory.current());
    if (steps) {
        resources.bind(Resource::ContactShadowSteps, *steps);
    }
    mHistory.advance();
}

} // namespace photopic
