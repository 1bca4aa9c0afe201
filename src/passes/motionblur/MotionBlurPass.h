#pragma once
// Motion blur in the HDR domain (docs/architecture.md, "Motion blur"): a reconstruction filter over the
// frame's motion vectors after McGuire et al. 2012, "A Reconstruction Filter for Plausible Motion Blur", and
// Guertin, McGuire and Nowrouzezahrai 2014, "A Fast and Stable Feature-Aware Motion Blur Filter". Four
// dispatches: prepare (motion to blur radius in pixels over the shutter, clamped), tile maximum,
// neighbourhood maximum, and the gather along the neighbourhood's dominant velocity, which composites front
// to back: samples nearer than the pixel cover it by the share of their streak that reaches it, and the
// pixel's own layer fills the rest: the points its own streak sweeps (its surface, what its motion uncovers
// behind it, and its own colour where a still nearer surface hides where it comes from).
// Tests: tests/gl/test_motion_blur.cpp, tests/e2e/mblur.sh, tests/e2e/blender.sh.

#include "passes/FramePass.h"

#include <cstdint>
#include <glm/vec2.hpp>

namespace photopic {

/// std140 mirror of motion_blur_common.h.glsl's parameter block.
struct MotionBlurParameters {
    glm::vec2 fullSize{1.0f};   ///< pixels
    float radiusScale = 0.25f;  ///< UV motion x fullSize x this = blur radius in pixels (half the streak)
    float maxBlur = 20.0f;      ///< pixels, the longest radius
    std::int32_t tileSize = 20; ///< pixels
    std::int32_t sampleCount = 15;
    std::uint32_t frame = 0;     ///< moves the samples' jitter
    std::int32_t writeTiles = 0; ///< the velocity-tiles debug view is on
    glm::ivec2 tileCount{1};
    float padding[2] = {};
};
static_assert(sizeof(MotionBlurParameters) == 48);
static_assert(offsetof(MotionBlurParameters, radiusScale) == 8);
static_assert(offsetof(MotionBlurParameters, tileSize) == 16);
static_assert(offsetof(MotionBlurParameters, writeTiles) == 28);
static_assert(offsetof(MotionBlurParameters, tileCount) == 32);

/// The shutter's open time as a fraction of the frame interval, from the settings (angle, or the camera's
/// exposure time over dt, else its shutter angle), in [0, 1] and more for an exposure longer than a frame.
[[nodiscard]] float shutterFraction(const MotionBlurSettings& settings, const Camera* camera,
                                    float dt) noexcept;

class MotionBlurPass final : public FramePass {
public:
    /// The pass runs where the settings place it: one instance before TAA, one after.
    explicit MotionBlurPass(MotionBlurPlacement placement);
    [[nodiscard]] std::string_view name() const override {
        return mPlacement == MotionBlurPlacement::BeforeTaa ? "motion blur" : "motion blur (after taa)";
    }
    /// sceneColor, motion, linearDepth -> sceneColor (and velocityTiles for the debug view).
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override;
    void execute(FrameContext& ctx, FrameResources& resources) override;

private:
    /// The frame's intermediate textures and outputs.
    struct Targets {
        const Texture* velocity = nullptr;     ///< full resolution, RG16F
        const Texture* tileMax = nullptr;      ///< per tile
        const Texture* neighbourMax = nullptr; ///< per tile, over its 3x3 neighbourhood
        const Texture* out = nullptr;
        const Texture* tilesView = nullptr; ///< the velocity tiles debug view, when asked for
    };
    [[nodiscard]] static Targets acquireTargets(const FrameContext& ctx, FrameResources& resources,
                                                Extent tiles);
    /// This frame's parameter block.
    [[nodiscard]] static MotionBlurParameters parameters(const FrameContext& ctx, Extent tiles,
                                                         bool writeTiles);
    /// The velocity, its per-tile maximum and the tiles' neighbourhood maximum.
    void tileVelocities(const FrameContext& ctx, const FrameResources& resources, const Targets& t,
                        Extent tiles);
    /// The blur: each pixel gathers along the neighbourhood's dominant velocity.
    void gather(const FrameContext& ctx, const FrameResources& resources, const Targets& t);

    MotionBlurPlacement mPlacement;
    Program mPrepare;
    Program mTiles;
    Program mNeighbours;
    Program mGather;
    SamplerSlot mPrepareMotion = mPrepare.sampler("uMotion");
    ImageSlot mPrepareVelocity = mPrepare.image("uVelocity");
    SamplerSlot mTilesVelocity = mTiles.sampler("uVelocity");
    ImageSlot mTilesTileMax = mTiles.image("uTileMax");
    SamplerSlot mNeighboursTileMax = mNeighbours.sampler("uTileMax");
    ImageSlot mNeighboursNeighbourMax = mNeighbours.image("uNeighbourMax");
    SamplerSlot mGatherScene = mGather.sampler("uScene");
    SamplerSlot mGatherVelocity = mGather.sampler("uVelocity");
    SamplerSlot mGatherDepth = mGather.sampler("uDepth");
    SamplerSlot mGatherNeighbourMax = mGather.sampler("uNeighbourMax");
    ImageSlot mGatherOut = mGather.image("uOut");
    ImageSlot mGatherTiles = mGather.image("uTiles");
    ParameterBlock<MotionBlurParameters> mParameters;
    Texture mNoTiles; ///< bound to the debug image unit when no debug view asks for the tiles
};

} // namespace photopic
