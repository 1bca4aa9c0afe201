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

#include "gl/ShaderLibrary.h"
#include "passes/FramePass.h"
#include "passes/ProgramVariants.h"

#include <cstddef>
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

/// std430 mirror of the header of motion_blur_lists.h.glsl's buffer: the indirect dispatches of the gather
/// over the moving tiles and of the copy over the still ones, (work groups a tile side)^2 x tiles listed.
/// `uint listTiles[]` follows: the moving tiles, then (from the tile count on) the still ones.
struct GpuMotionTileLists {
    std::uint32_t movingArgs[3] = {1, 1, 0};
    std::uint32_t stillArgs[3] = {1, 1, 0};
    std::uint32_t pad[2] = {};
};
static_assert(sizeof(GpuMotionTileLists) == 32 && offsetof(GpuMotionTileLists, stillArgs) == 12);

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
    /// The blur: each pixel of a moving tile gathers along the neighbourhood's dominant velocity; the still
    /// tiles keep the scene colour (an image copy).
    void gather(const FrameContext& ctx, const FrameResources& resources, const Targets& t);
    /// Empty lists for `tiles` tiles of `tileSize` pixels, bound at kBindingTileList.
    void resetLists(Extent tiles, int tileSize);

    /// A gather program (the gather, or with MOTION_BLUR_STILL the still tiles' copy and debug view) and its
    /// slots.
    struct GatherProgram : ProgramSlots {
        using ProgramSlots::ProgramSlots;
        ImageSlot scene = program.image("uScene");
        ImageSlot velocity = program.image("uVelocity");
        ImageSlot depth = program.image("uDepth");
        ImageSlot neighbourMax = program.image("uNeighbourMax");
        ImageSlot out = program.image("uOut");
        ImageSlot tiles = program.image("uTiles");
    };
    void runGather(const GatherProgram& program, const FrameResources& resources, const Targets& t,
                   GLintptr arguments);

    MotionBlurPlacement mPlacement;
    /// The tile maximum from a work group per tile through shared memory (sharedMemoryTiles(): a GPU), else
    /// an invocation per tile; for the pass's life.
    bool mSharedTiles = sharedMemoryTiles();
    Program mPrepare;
    Program mTiles;
    Program mNeighbours;
    GatherProgram mGather;
    GatherProgram mStill; ///< the still tiles, for the velocity-tiles view
    SamplerSlot mPrepareMotion = mPrepare.sampler("uMotion");
    ImageSlot mPrepareVelocity = mPrepare.image("uVelocity");
    ImageSlot mTilesVelocity = mTiles.image("uVelocity");
    ImageSlot mTilesTileMax = mTiles.image("uTileMax");
    ImageSlot mNeighboursTileMax = mNeighbours.image("uTileMax");
    ImageSlot mNeighboursNeighbourMax = mNeighbours.image("uNeighbourMax");
    ParameterBlock<MotionBlurParameters> mParameters;
    Texture mNoTiles; ///< bound to the debug image unit when no debug view asks for the tiles
    Buffer mLists;    ///< GpuMotionTileLists and the lists; grown to the largest tile count seen
};

} // namespace photopic
