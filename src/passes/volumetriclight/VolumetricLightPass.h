#pragma once
// Volumetric light (Mitchell, "Volumetric Light Scattering as a Post-Process", GPU Gems 3 ch. 13): light
// scattered towards the camera along rays from the sun's projected position, added to the HDR image after
// SSR. Four compute dispatches: the occlusion source at full resolution (the sky's colour, 0 where depth
// holds a surface), the radial march from each half-resolution texel towards the sun, a temporal
// accumulation of the dithered march (reprojected, clamped to this frame's neighbourhood), and the composite
// at full resolution. The rays fade out as the sun leaves the screen (core/VolumetricLight.h).
// With the host's sun shadow map (FrameInputs::sunShadow) and mode shadowmap or auto, three other dispatches
// instead: single scattering ray-marched along the view rays at half or quarter resolution against the map,
// its temporal accumulation reprojected by the camera's motion from depth, and a depth-aware upsample added
// to the image at the same place in the frame.
// docs/architecture.md ("Volumetric light") has the settings, the measured figures and the limits.
// Tests: tests/gl/test_volumetric_light.cpp, tests/gl/test_volumetric_shadow.cpp,
// tests/e2e/volumetric_light.sh.

#include "passes/FramePass.h"
#include "passes/HistoryTexture.h"

#include <cstdint>
#include <glm/vec2.hpp>

namespace photopic {

/// std140 mirror of volumetric_light_common.h.glsl's parameter block (every dispatch of the pass).
struct VolumetricLightParameters {
    glm::vec2 sunUv{0.5f};      ///< the sun's projected position, UV ((0, 0) bottom-left; may be off screen)
    glm::vec2 halfSize{1.0f};   ///< texels of the half-resolution march
    glm::vec2 fullSize{1.0f};   ///< pixels
    float density = 1.0f;       ///< fraction of the way to the sun the samples reach
    float logDecay = 0.0f;      ///< 64 log2(decay): a sample at fraction t of the way weighs exp2(t logDecay)
    float scale = 0.0f;         ///< intensity x weight x exposure x the sun's fade
    float historyWeight = 0.9f; ///< the clamped history's weight in the accumulation
    std::int32_t samples = 64;
    std::uint32_t frame = 0; ///< moves the dithered start
    std::int32_t hasHistory = 0;
    std::int32_t hasMotion = 0;
    std::int32_t writeView = 0; ///< the volumetric-light debug view is on: write the light added
    std::int32_t active = 0;    ///< the sun's fade is above 0 (else every dispatch writes 0)
    float skyDepth = 0.0f;      ///< linear depths at or beyond this are the sky (+inf always is)
    float padding[3] = {};
};
static_assert(sizeof(VolumetricLightParameters) == 80);
static_assert(offsetof(VolumetricLightParameters, density) == 24);
static_assert(offsetof(VolumetricLightParameters, historyWeight) == 36);
static_assert(offsetof(VolumetricLightParameters, samples) == 40);
static_assert(offsetof(VolumetricLightParameters, active) == 60);
static_assert(offsetof(VolumetricLightParameters, skyDepth) == 64);

/// std140 mirror of volumetric_shadow_common.h.glsl's parameter block (the shadow-map march's dispatches).
struct VolumetricShadowParameters {
    glm::mat4 worldToShadowClip{1.0f};            ///< world -> the sun view's clip space (the host's matrix)
    glm::mat4 inverseView{1.0f};                  ///< view -> world
    glm::mat4 prevViewProjection{1.0f};           ///< world -> last frame's clip space
    glm::vec4 projection{1.0f, 1.0f, 0.0f, 0.0f}; ///< 1 / P00, 1 / P11, P20, P21
    glm::vec4 light{0.0f};    ///< rgb: illuminance x albedo (decay); w: Henyey-Greenstein g
    glm::vec4 toSun{0.0f};    ///< xyz: towards the sun, unit; w: unused
    glm::vec2 lowSize{1.0f};  ///< texels of the march
    glm::vec2 fullSize{1.0f}; ///< pixels
    float extinction = 0.0f;  ///< per scene unit: density x scattering
    float maxDistance = 100.0f;
    float historyWeight = 0.9f;
    float skyDepth = 0.0f;
    std::int32_t samples = 64;
    std::uint32_t frame = 0;
    std::int32_t hasHistory = 0;
    std::int32_t writeView = 0;
    std::int32_t factor = 2; ///< pixels per march texel on each axis
    float intensity = 1.0f;
    float padding[2] = {};
};
static_assert(sizeof(VolumetricShadowParameters) == 304);
static_assert(offsetof(VolumetricShadowParameters, lowSize) == 240);
static_assert(offsetof(VolumetricShadowParameters, samples) == 272);
static_assert(offsetof(VolumetricShadowParameters, intensity) == 292);

class VolumetricLightPass final : public FramePass {
public:
    VolumetricLightPass();
    [[nodiscard]] std::string_view name() const override { return "volumetric light"; }
    /// sceneColor, linearDepth, camera, sunDirection, motion?, sunShadow? -> sceneColor, volumetricLight
    /// (view)
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        return ctx.hdr && ctx.settings.volumetricLight.enabled;
    }
    void invalidateHistory() override {
        mHistory.invalidate();
        mShadowLight.invalidate();
        mShadowDepth.invalidate();
    }
    void execute(FrameContext& ctx, FrameResources& resources) override;

    /// The history's weight against this frame's march, per frame (about 10 frames of accumulation).
    static constexpr float kHistoryWeight = 0.9f;

    /// The mode that runs with or without a sun shadow map: shadowmap needs one (without it, screen runs).
    [[nodiscard]] static bool marchesShadowMap(VolumetricLightMode mode, bool hasShadowMap) {
        return hasShadowMap && mode != VolumetricLightMode::Screen;
    }

private:
    void executeScreen(FrameContext& ctx, FrameResources& resources);
    void executeShadowMap(FrameContext& ctx, FrameResources& resources, const Texture& shadowMap);
    /// The screen-space march's steps: the light source (the sky, from colour and depth), the march toward
    /// the sun at half resolution, the resolve with the history, the composite (`view`: the debug view).
    void lightSource(const FrameContext& ctx, const FrameResources& resources, const Texture& source);
    void scatter(const FrameContext& ctx, const Texture& source, const Texture& raw, Extent half);
    void resolve(const FrameContext& ctx, const FrameResources& resources, const Texture& raw, Extent half);
    void composite(const FrameContext& ctx, const FrameResources& resources, const Texture& out,
                   const Texture* view, Extent half);
    /// The shadow map's steps: the march through the map at `low` resolution, the resolve with the
    /// histories, the composite.
    void shadowMarch(const FrameContext& ctx, const FrameResources& resources, const Texture& shadowMap,
                     const Texture& raw, Extent low);
    void shadowResolve(const FrameContext& ctx, const Texture& raw, Extent low);
    void shadowComposite(const FrameContext& ctx, const FrameResources& resources, const Texture& out,
                         const Texture* view, Extent low);

    Program mPrepare;
    Program mScatter;
    Program mResolve;
    Program mComposite;
    SamplerSlot mPrepareScene = mPrepare.sampler("uScene");
    SamplerSlot mPrepareDepth = mPrepare.sampler("uDepth");
    ImageSlot mPrepareSource = mPrepare.image("uSource");
    SamplerSlot mScatterSource = mScatter.sampler("uSource");
    ImageSlot mScatterOut = mScatter.image("uOut");
    SamplerSlot mResolveRaw = mResolve.sampler("uRaw");
    SamplerSlot mResolveHistory = mResolve.sampler("uHistory");
    SamplerSlot mResolveMotion = mResolve.sampler("uMotion");
    ImageSlot mResolveOut = mResolve.image("uOut");
    SamplerSlot mCompositeScene = mComposite.sampler("uScene");
    SamplerSlot mCompositeLight = mComposite.sampler("uLight");
    ImageSlot mCompositeOut = mComposite.image("uOut");
    ImageSlot mCompositeView = mComposite.image("uView");
    ParameterBlock<VolumetricLightParameters> mParameters;
    HistoryTexture mHistory; ///< the accumulated half-resolution light (before the final scale)
    Texture mNoView;         ///< bound to the view's image unit when no debug view asks for it
    Program mShadowMarch;
    Program mShadowResolve;
    Program mShadowComposite;
    ImageSlot mMarchDepth = mShadowMarch.image("uDepth");
    SamplerSlot mMarchShadowMap = mShadowMarch.sampler("uShadowMap");
    ImageSlot mMarchOut = mShadowMarch.image("uOut");
    ImageSlot mMarchLowDepth = mShadowMarch.image("uLowDepth");
    ImageSlot mShadowResolveRaw = mShadowResolve.image("uRaw");
    ImageSlot mShadowResolveHistory = mShadowResolve.image("uHistory");
    ImageSlot mShadowResolveLowDepth = mShadowResolve.image("uLowDepth");
    ImageSlot mShadowResolvePrevLowDepth = mShadowResolve.image("uPrevLowDepth");
    ImageSlot mShadowResolveOut = mShadowResolve.image("uOut");
    ImageSlot mShadowCompositeScene = mShadowComposite.image("uScene");
    ImageSlot mShadowCompositeDepth = mShadowComposite.image("uDepth");
    ImageSlot mShadowCompositeLowDepth = mShadowComposite.image("uLowDepth");
    ImageSlot mShadowCompositeAccumulated = mShadowComposite.image("uAccumulated");
    ImageSlot mShadowCompositeOut = mShadowComposite.image("uOut");
    ImageSlot mShadowCompositeView = mShadowComposite.image("uView");
    ParameterBlock<VolumetricShadowParameters> mShadowParameters;
    HistoryTexture mShadowLight; ///< the shadow-map march's accumulated light (before intensity)
    HistoryTexture mShadowDepth; ///< the march texels' linear depths, this frame's and last frame's
    Sampler mShadowSampler;      ///< linear, LEQUAL comparison, clamped: the host's map read as visibility
    /// Whether the shadow-map march ran last frame (switching mode starts the other's history over).
    bool mLastRanShadowMap = false;
};

} // namespace photopic
