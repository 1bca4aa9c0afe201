#include "pipeline/Pipeline.h"

#include "core/Log.h"
#include "core/settings/SettingsJson.h"
#include "gl/StateScope.h"
#include "gl/TextureIo.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace photopic {

namespace {

constexpr Resource kLightingOutputs[] = {Resource::AmbientOcclusion, Resource::ContactShadows};

/// Whether a pass the settings turn on this frame reads the scene colour without sanitising what it reads
/// (the 3D passes, lens flare): then the sanitize pass makes a clean copy for all of them. Otherwise its
/// readers (metering, probes, bloom, tone mapping, the scene debug views) each sanitise what they read, and
/// a full-resolution read and write of the frame is saved.
bool readsRawScene(std::span<FramePass* const> passes, const FramePass& sanitize, const FrameContext& ctx) {
    for (const FramePass* pass : passes) {
        if (pass == &sanitize || pass->sanitizesSceneReads() || !pass->enabled(ctx)) {
            continue;
        }
        for (const ResourceUse& use : pass->uses()) {
            if (use.resource == Resource::SceneColor && use.access != Access::Write) {
                return true;
            }
        }
    }
    return false;
}
/// A scene-value debug view replaces the display image when its pass can run.
constexpr Resource kPostOutputs[] = {Resource::DebugColor, Resource::DisplayColor};
/// The host's inputs besides colour (FrameInputs), as plannedReads() takes them.
constexpr Resource kHostInputs[] = {Resource::Depth,    Resource::Normals,      Resource::Motion,
                                    Resource::Camera,   Resource::SunDirection, Resource::ObjectId,
                                    Resource::Material, Resource::SunShadowMap};

void warnAboutTier(const Capabilities& caps, Quality quality) {
    if (quality == Quality::Legacy && caps.path == ColorPath::Hdr) {
        warnOnce("quality-legacy",
                 "quality=legacy: running the LDR (RGBA8) path although the GPU renders "
                 "RGBA16F; the bloom chain is replaced by a single cheap glow, lens flare is "
                 "off and values above 1 clip before tone mapping");
    }
}

void checkSettings(const Settings& settings) {
    std::vector<SettingsIssue> issues = validateSettings(settings);
    if (!issues.empty()) {
        throw SettingsError("settings", std::move(issues));
    }
}

bool oneOf(GLenum format, std::span<const GLenum> formats) {
    return std::find(formats.begin(), formats.end(), format) != formats.end();
}

/// Why an optional texture input cannot be used this frame, or an empty string.
std::string textureProblem(const char* name, const Texture& t, Extent extent,
                           std::span<const GLenum> formats) {
    if (!t.valid()) {
        return fmt::format("{}: not a texture (id 0)", name);
    }
    if (t.extent() != extent) {
        return fmt::format("{}: {}x{} does not match colour's {}x{}", name, t.extent().width,
                           t.extent().height, extent.width, extent.height);
    }
    if (!oneOf(t.format(), formats)) {
        std::string accepted;
        for (const GLenum f : formats) {
            accepted += (accepted.empty() ? "" : ", ") + formatName(f);
        }
        return fmt::format("{}: format {} is not one the pipeline reads ({})", name, formatName(t.format()),
                           accepted);
    }
    return {};
}

/// Why the sun's shadow map cannot be used, or empty: a depth texture of any size, a finite invertible
/// matrix, a finite non-negative illuminance.
std::string sunShadowProblem(const SunShadowMap& shadow) {
    const Texture& t = *shadow.depth;
    if (!t.valid() || t.extent().empty()) {
        return "sunShadow.depth: not a texture (id 0) or empty";
    }
    if (!isDepthFormat(t.format())) {
        return fmt::format("sunShadow.depth: format {} is not a depth format", formatName(t.format()));
    }
    const glm::mat4& m = shadow.worldToClip;
    bool finite = true;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            finite = finite && std::isfinite(m[c][r]);
        }
    }
    const float det = finite ? glm::determinant(m) : 0.0f;
    if (!finite || !std::isfinite(det) || det == 0.0f) {
        return "sunShadow.worldToClip: not a finite, invertible matrix";
    }
    const glm::vec3 e = shadow.illuminance;
    if (!(std::isfinite(e.x) && std::isfinite(e.y) && std::isfinite(e.z)) || e.x < 0.0f || e.y < 0.0f ||
        e.z < 0.0f) {
        return "sunShadow.illuminance: not finite and non-negative";
    }
    return {};
}

} // namespace

Pipeline::Pipeline(const PipelineCreateInfo& info)
    : mConstructionScope(std::make_unique<GlStateScope>())
    , mSettings(info.settings)
    , mCaps(detectCapabilities(info.forceLdr))
    , mOrder(std::make_unique<FrameOrder>(mCaps, info.keepTelemetryHistory))
    , mInvalid({.extent = {1, 1}, .format = GL_RGBA8, .debugName = "no colour input"}) {
    checkSettings(mSettings);
    const std::uint8_t black[4] = {0, 0, 0, 255};
    glTextureSubImage2D(mInvalid.id(), 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, black);
    for (FramePass* pass : mOrder->all()) {
        pass->configure(mSettings);
    }
    warnAboutTier(mCaps, mSettings.quality);
    mConstructionScope.reset();
}

Pipeline::~Pipeline() {
    const GlStateScope hostState;
    mOrder.reset();
}

void Pipeline::setSettings(const Settings& settings) {
    const GlStateScope hostState;
    checkSettings(settings);
    for (FramePass* pass : mOrder->all()) {
        pass->configure(settings);
    }
    mSettings = settings;
    warnAboutTier(mCaps, mSettings.quality);
}

void Pipeline::reset() {
    mResetExposure = true;
    mResetHistory = true;
}

void Pipeline::resize(Extent extent) {
    if (extent == mExtent) {
        return;
    }
    mExtent = extent;
    mResources.pool().clear();
    for (FramePass* pass : mOrder->all()) {
        pass->resize(extent);
    }
    mResetExposure = true; // a new size is a new view: snap exposure
    mResetHistory = true;
}

glm::vec2 Pipeline::beginFrame(const FrameTime& time, const Camera* camera) {
    if (camera && camera->cut) {
        reset();
    }
    mBeganFrame = true;
    if (subframeCount() > 1) {
        mJitter = subframeJitter(0);
        return mJitter;
    }
    const JitterMode mode = mSettings.temporal.jitter;
    const bool jitter =
        mode == JitterMode::On || (mode == JitterMode::Auto && mSettings.temporalAntiAliasing());
    mJitter = jitter ? haltonJitter(time.frameIndex, mSettings.temporal.jitterCycle) : glm::vec2(0.0f);
    return mJitter;
}

bool Pipeline::bindInputs(const FrameInputs& in) {
    mInputErrors.clear();
    mResources.clear();
    if (in.color == nullptr || !in.color->valid() || in.color->extent().empty()) {
        mInputErrors.emplace_back("color: missing (a null or empty texture); the frame shows black");
        return false;
    }
    mResources.bind(Resource::Color, *in.color);
    mResources.bind(Resource::SceneColor, *in.color); // replaced by the sanitised copy on the HDR path
    // What the passes keep from frame to frame (the exposure state, histories) goes on the blackboard.
    for (const FramePass* pass : mOrder->all()) {
        pass->publishState(mResources);
    }

    // In this order, which the input errors keep.
    const Extent extent = in.color->extent();
    bindGeometry(in, extent);
    bindCamera(in);
    bindOptional(Resource::ObjectId, "objectId", in.objectId, extent, {GL_R32UI, GL_R16UI, GL_R8UI});
    bindOptional(Resource::Material, "material", in.material, extent, {GL_RGBA16F, GL_RGBA32F, GL_RGBA8});
    bindSun(in);
    return true;
}

void Pipeline::bindOptional(Resource r, const char* name, const Texture* t, Extent extent,
                            std::initializer_list<GLenum> formats) {
    bindOptional(r, name, t, extent, std::span<const GLenum>(formats.begin(), formats.size()));
}

void Pipeline::bindOptional(Resource r, const char* name, const Texture* t, Extent extent,
                            std::span<const GLenum> formats) {
    if (t == nullptr) {
        return;
    }
    std::string problem = textureProblem(name, *t, extent, formats);
    if (problem.empty()) {
        mResources.bind(r, *t);
    } else {
        mInputErrors.push_back(std::move(problem));
    }
}

void Pipeline::bindGeometry(const FrameInputs& in, Extent extent) {
    if (in.depthKind == DepthKind::LinearView) {
        bindOptional(Resource::Depth, "depth", in.depth, extent, {GL_R32F, GL_R16F, GL_RG32F, GL_RGBA32F});
    } else {
        bindOptional(Resource::Depth, "depth", in.depth, extent,
                     {GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32, GL_DEPTH_COMPONENT32F,
                      GL_DEPTH24_STENCIL8, GL_DEPTH32F_STENCIL8, GL_R32F});
    }
    if (in.normalEncoding == NormalEncoding::Octahedral) {
        bindOptional(Resource::Normals, "normals", in.normals, extent,
                     {GL_RG16F, GL_RG32F, GL_RG16_SNORM, GL_RG8_SNORM});
    } else {
        bindOptional(
            Resource::Normals, "normals", in.normals, extent,
            {GL_RGB16F, GL_RGBA16F, GL_RGB32F, GL_RGBA32F, GL_RGB10_A2, GL_RGBA16_SNORM, GL_RGBA8_SNORM});
    }
    bindOptional(Resource::Motion, "motion", in.motion, extent, kMotionFormats);
}

void Pipeline::bindCamera(const FrameInputs& in) {
    if (in.camera) {
        if (const char* reason = invalidCameraReason(*in.camera)) {
            mInputErrors.emplace_back(reason);
        } else {
            mResources.markPresent(Resource::Camera);
        }
    }
}

void Pipeline::bindSun(const FrameInputs& in) {
    if (in.sunDirection) {
        const glm::vec3 d = *in.sunDirection;
        const float length2 = glm::dot(d, d);
        if (std::isfinite(length2) && length2 > 1e-12f) {
            mResources.markPresent(Resource::SunDirection);
        } else {
            mInputErrors.emplace_back("sunDirection: not a finite, non-zero vector");
        }
    }
    if (in.sunShadow.depth != nullptr) {
        if (std::string problem = sunShadowProblem(in.sunShadow); problem.empty()) {
            mResources.bind(Resource::SunShadowMap, *in.sunShadow.depth);
        } else {
            mInputErrors.push_back(std::move(problem));
        }
    }
}

FrameContext Pipeline::makeContext(const FrameInputs& inputs, const FrameTime& time,
                                   const QualityTier& tier) {
    return FrameContext{.settings = mSettings,
                        .tier = tier,
                        .caps = mCaps,
                        .inputs = inputs,
                        .time = time,
                        .extent = mExtent,
                        .hdr = tier.hdrPath,
                        .resetExposure = mResetExposure,
                        .resetHistory = mResetHistory,
                        .timers = &mTimers,
                        .autoExposure = &mSettings.autoExposure,
                        .exposureOverrideLog2 = mExposureOverride,
                        .subjects = &mOrder->probes().tracker(),
                        .exposureTelemetry = &mOrder->exposure().lastTelemetry()};
}

const LightingOutputs& Pipeline::renderLighting(const FrameInputs& inputs, const FrameTime& time) {
    const GlStateScope hostState;
    mLighting = {};
    if (!bindInputs(inputs)) {
        return mLighting;
    }
    resize(inputs.color->extent());
    const QualityTier tier = effectiveTier(mCaps, mSettings.quality);
    FrameContext ctx = makeContext(inputs, time, tier);
    mResources.pool().beginFrame();
    if (!mLightingTimed) {
        mTimers.beginFrame(); // the lighting stage's passes are timed with the frame execute() finishes
        mLightingTimed = true;
    }
    mLightingSequencer.run(mOrder->lighting(), {.resources = kLightingOutputs}, ctx, mResources);
    mLighting.ambientOcclusion = mResources.texture(Resource::AmbientOcclusion);
    mLighting.ambientOcclusionPower = mSettings.gtao.power;
    mLighting.contactShadows = mResources.texture(Resource::ContactShadows);
    mContactShadowSteps = mResources.texture(Resource::ContactShadowSteps);
    return mLighting;
}

void Pipeline::warnLightingStageMissing() const {
    try {
        if (mSettings.gtao.enabled && mSettings.gtao.apply == GtaoApply::Lighting)
            warnOnce(
                "ssao.no-lighting",
                "ssao.apply is lighting but the host does not call renderLighting(): no ambient occlusion "
                "is computed; ssao.apply=multiply applies it to the scene colour instead");
        if (mSettings.contactShadows.enabled)
            warnOnce(
                "contactShadows.no-lighting",
                "contactShadows.enabled but the host does not call renderLighting(): contact shadows are "
                "the sun's visibility for the host's own sun term, so without the lighting stage they "
                "darken nothing");
    } catch (...) { // logging must not take the frame down
    }
}

const Texture& Pipeline::execute(const FrameInputs& inputs, const FrameTime& time) {
    const GlStateScope hostState;
    // The lighting stage's outputs stay bound for the post stage when the host ran it this frame.
    const LightingOutputs lighting = std::exchange(mLighting, {});
    const Texture* contactShadowSteps = std::exchange(mContactShadowSteps, nullptr);
    if (!bindInputs(inputs)) {
        return invalidFrame();
    }
    warnInputProblems();
    bindLightingOutputs(lighting, contactShadowSteps);
    resize(inputs.color->extent());
    if (mResetHistory) {
        for (FramePass* pass : mOrder->all()) {
            pass->invalidateHistory();
        }
    }
    const bool lightingRan = mLightingTimed; // renderLighting() ran for this frame
    if (!mLightingTimed) {
        mTimers.beginFrame();
    }
    mLightingTimed = false;
    const QualityTier tier = effectiveTier(mCaps, mSettings.quality);
    FrameContext ctx = makeContext(inputs, time, tier);
    ctx.sanitizeScene = readsRawScene(mOrder->post(), mOrder->sanitize(), ctx);
    if (lighting.ambientOcclusion == nullptr && lighting.contactShadows == nullptr) {
        mResources.pool().beginFrame(); // else the lighting stage began it and its textures are in use
    }
    warnHostCallsMissing(lightingRan);
    mOutput = mPostSequencer.run(mOrder->post(), {.resources = kPostOutputs, .firstAvailable = true}, ctx,
                                 mResources);
    mResourcesRead = mPostSequencer.neededReads();
    if (lightingRan)
        mResourcesRead |= mLightingSequencer.neededReads();
    mResetExposure = false;
    mResetHistory = false;
    mTimers.endFrame();
    const Texture* out = mResources.texture(mOutput);
    PHOTOPIC_ASSERT(out != nullptr);
    return *out;
}

const Texture& Pipeline::invalidFrame() noexcept {
    if (mLightingTimed) {
        mTimers.endFrame();
        mLightingTimed = false;
    }
    try {
        warnOnce("input.color", "execute(): " + mInputErrors.front());
    } catch (...) { // logging must not take the frame down
    }
    return mInvalid;
}

void Pipeline::warnInputProblems() noexcept {
    for (const std::string& problem : mInputErrors) {
        try {
            warnOnce("input." + problem.substr(0, problem.find(':')), "execute(): " + problem + "; ignored");
        } catch (...) { // logging must not take the frame down
        }
    }
}

void Pipeline::bindLightingOutputs(const LightingOutputs& lighting,
                                   const Texture* contactShadowSteps) noexcept {
    if (lighting.ambientOcclusion) {
        mResources.bind(Resource::AmbientOcclusion, *lighting.ambientOcclusion);
    }
    if (lighting.contactShadows) {
        mResources.bind(Resource::ContactShadows, *lighting.contactShadows);
    }
    if (contactShadowSteps) {
        mResources.bind(Resource::ContactShadowSteps, *contactShadowSteps);
    }
}

void Pipeline::warnHostCallsMissing(bool lightingRan) noexcept {
    if (mSettings.antiAliasing() == AntiAliasing::Ssaa && !mAccumulating) {
        try {
            warnOnce("ssaa.no-subframes", "aa.mode is ssaa but the host rendered no sub-frames "
                                          "(accumulateSubframe): one sample per pixel, no anti-aliasing");
        } catch (...) { // logging must not take the frame down
        }
    }
    mAccumulating = false;
    if (!mBeganFrame && mSettings.temporalAntiAliasing()) {
        try {
            warnOnce("taa.no-jitter", "TAA is on but the host does not call beginFrame(): its frames are not "
                                      "jittered, so TAA only filters over time and cannot anti-alias edges");
        } catch (...) { // logging must not take the frame down
        }
    }
    mBeganFrame = false;
    if (!lightingRan)
        warnLightingStageMissing();
}

std::bitset<kResourceCount> Pipeline::plannedReads(std::bitset<kResourceCount> inputs, bool lighting) {
    const auto has = [&](Resource r) { return inputs.test(std::size_t(r)); };
    // The passes' enabled() look at which inputs the frame has, never at what they hold: a present texture
    // input is the 1x1 placeholder here, the camera a default one. Nothing is bound or read.
    const Camera camera;
    FrameInputs in{.color = &mInvalid};
    in.depth = has(Resource::Depth) ? &mInvalid : nullptr;
    in.normals = has(Resource::Normals) ? &mInvalid : nullptr;
    in.motion = has(Resource::Motion) ? &mInvalid : nullptr;
    in.camera = has(Resource::Camera) ? &camera : nullptr;
    if (has(Resource::SunDirection)) {
        in.sunDirection = glm::vec3(0.0f, 1.0f, 0.0f);
    }
    in.objectId = has(Resource::ObjectId) ? &mInvalid : nullptr;
    in.material = has(Resource::Material) ? &mInvalid : nullptr;
    in.sunShadow.depth = has(Resource::SunShadowMap) ? &mInvalid : nullptr;

    Sequencer::ResourceSet bound;
    for (const Resource r : kHostInputs) {
        bound.set(std::size_t(r), has(r));
    }
    // What bindInputs() binds besides the host's inputs.
    for (const Resource r : {Resource::Color, Resource::SceneColor, Resource::ExposureState}) {
        bound.set(std::size_t(r));
    }
    const QualityTier tier = effectiveTier(mCaps, mSettings.quality);
    const FrameTime time;
    FrameContext ctx = makeContext(in, time, tier);
    std::bitset<kResourceCount> reads;
    if (lighting) {
        Sequencer stage;
        const Sequencer::ResourceSet made =
            stage.plan(mOrder->lighting(), {.resources = kLightingOutputs}, ctx, bound);
        reads |= stage.neededReads();
        // execute() binds the lighting stage's textures for the post stage.
        for (const Resource r :
             {Resource::AmbientOcclusion, Resource::ContactShadows, Resource::ContactShadowSteps}) {
            bound.set(std::size_t(r), made.test(std::size_t(r)));
        }
    }
    ctx.sanitizeScene = readsRawScene(mOrder->post(), mOrder->sanitize(), ctx);
    Sequencer stage;
    (void)stage.plan(mOrder->post(), {.resources = kPostOutputs, .firstAvailable = true}, ctx, bound);
    return reads | stage.neededReads();
}

int Pipeline::subframeCount() const noexcept {
    return mSettings.antiAliasing() == AntiAliasing::Ssaa ? 1 << std::clamp(mSettings.aa.level, 1, 4) : 1;
}

glm::vec2 Pipeline::subframeJitter(int index) const noexcept {
    // An N-rooks lattice: sample k sits in column k and row (k * m) mod N of an N x N sub-grid, so every row
    // and every column holds one sample (N coverage levels for horizontal and vertical edges alike), and the
    // multiplier m spreads the samples over the pixel (m = 2 x 2 - 1 gives the rotated grid of 4x SSAA).
    const int n = subframeCount();
    const int multiplier = n == 2 ? 1 : n == 4 ? 3 : n == 8 ? 3 : 5;
    const int k = std::clamp(index, 0, n - 1);
    const int row = n == 2 ? 1 - k : (k * multiplier) % n;
    return {(float(k) + 0.5f) / float(n) - 0.5f, (float(row) + 0.5f) / float(n) - 0.5f};
}

void Pipeline::accumulateSubframe(const Texture& color, int index) {
    const GlStateScope hostState;
    if (!mSsaa) {
        mSsaa = std::make_unique<SsaaAccumulator>();
    }
    if (!mAccumulating) {
        mSsaa->begin(color.extent());
        mAccumulating = true;
    }
    mSsaa->add(color, ssaaWeight(mSettings.aa.ssaaFilter, subframeJitter(index)), &mTimers);
}

const Texture& Pipeline::subframeMean() const {
    if (!mSsaa) {
        throw GlError("subframeMean(): no sub-frame has been accumulated");
    }
    return mSsaa->mean();
}

const Texture& Pipeline::supersample(const Texture& color, const std::function<void(glm::vec2)>& draw) {
    const int subframes = subframeCount();
    if (subframes <= 1) {
        return color;
    }
    accumulateSubframe(color, 0);
    for (int i = 1; i < subframes; ++i) {
        draw(subframeJitter(i));
        accumulateSubframe(color, i);
    }
    return subframeMean();
}

const Texture& Pipeline::sceneReferred() {
    const GlStateScope hostState;
    if (!mCaps.rgba32fRenderable) {
        throw GlError("the scene-referred (EXR) output needs RGBA32F render targets, which this GPU lacks");
    }
    const Texture* scene = mResources.texture(Resource::SceneColor);
    if (scene == nullptr) {
        throw GlError("no frame has been executed: there is no scene-referred image yet");
    }
    // A debug view of data (visibility, steps) writes its values as they are, not an image of them.
    if (const Texture* raw = mOrder->debugView().rawValues();
        raw != nullptr && mOutput == Resource::DebugColor && mPostSequencer.ran(mOrder->debugView())) {
        return *raw;
    }
    const QualityTier tier = effectiveTier(mCaps, mSettings.quality);
    const Texture* bloom = mResources.texture(Resource::Bloom);
    return mOrder->tonemap().renderScene({.scene = scene,
                                          .exposureState = &mOrder->exposure().state(),
                                          .tonemapping = &mSettings.tonemapping,
                                          .output = &mSettings.output,
                                          .bloom = bloom,
                                          .bloomSettings = &mSettings.bloom,
                                          .glow = bloom == nullptr && legacyGlow(tier, mSettings),
                                          .grading = &mSettings.colorGrading,
                                          .frameIndex = 0,
                                          .timers = nullptr});
}

PipelineStatus Pipeline::status() const {
    PipelineStatus t;
    const QualityTier tier = effectiveTier(mCaps, mSettings.quality);
    t.quality = mSettings.quality;
    if (tier.hdrPath && mCaps.path == ColorPath::Hdr) {
        t.path = ColorPath::Hdr;
        t.pathReason = mCaps.pathReason;
    } else {
        t.path = ColorPath::Ldr;
        t.pathReason = mCaps.path == ColorPath::Ldr ? mCaps.pathReason : "quality=legacy runs the LDR path";
    }
    t.bloomLevels = mPostSequencer.ran(mOrder->bloom()) ? mOrder->bloom().levels() : 0;
    t.passes = mTimers.latest();
    for (const Sequencer* s : {&mLightingSequencer, &mPostSequencer}) {
        for (std::string& name : s->ranPasses()) {
            t.ran.push_back(std::move(name));
        }
        for (SkippedPass& skipped : s->skippedPasses()) {
            t.skipped.push_back(std::move(skipped));
        }
    }
    t.inputErrors = mInputErrors;
    return t;
}

const ExposureTelemetry& Pipeline::telemetry() {
    const GlStateScope hostState;
    return mOrder->exposure().telemetry();
}

std::vector<ExposureTelemetry> Pipeline::drainTelemetry() {
    const GlStateScope hostState;
    return mOrder->exposure().drainTelemetry();
}

std::uint64_t Pipeline::droppedTelemetry() const {
    return mOrder->exposure().droppedTelemetry();
}

void Pipeline::setTelemetryReadyOverride(std::function<bool()> ready) {
    mOrder->exposure().setTelemetryReadyOverride(std::move(ready));
}

const Buffer& Pipeline::exposureState() const {
    return mOrder->exposure().state();
}

void Pipeline::setSubjects(std::span<const Subject> subjects, glm::vec2 viewCentreWorld) noexcept {
    mOrder->probes().setPending(subjects, viewCentreWorld);
}

void Pipeline::setOutdoorsMask(const OutdoorsMask* mask) noexcept {
    mOrder->probes().tracker().setOutdoorsMask(mask);
}

const SubjectContext* Pipeline::contextForSubject(std::uint32_t id) const noexcept {
    return mOrder->probes().tracker().contextForSubject(id);
}

const SubjectContext* Pipeline::subjectContext() const noexcept {
    return mOrder->probes().tracker().subjectContext();
}

float Pipeline::outdoorsAtWorld(float x, float y) const noexcept {
    return mOrder->probes().tracker().outdoorsAtWorld(x, y);
}

const SubjectTracker& Pipeline::subjects() const {
    return mOrder->probes().tracker();
}

std::uint64_t Pipeline::droppedProbes() const {
    return mOrder->probes().droppedProbes();
}

Image8 processImage(Pipeline& pipeline, const ImageF& image, const FrameTime& time) {
    const GlStateScope hostState;
    const Texture input = makeTexture(image, "input");
    return readTexture8(pipeline.execute({.color = &input}, time));
}

} // namespace photopic
