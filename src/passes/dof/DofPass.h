#pragma once
// Depth of field (Jimenez 2014, "Next Generation Post Processing in Call of Duty: Advanced Warfare"): each
// pixel's signed circle of confusion from its depth (the camera's thin lens, or an artistic focal distance
// and range), near and far fields at half resolution, the near field's reach dilated over tiles, a gather
// of each over a disc or hexagon, and a full-resolution composite over the sharp image. It runs on the
// scene-referred colour after exposure is metered and before bloom, so bokeh highlights stay HDR and bloom.
// docs/architecture.md ("Depth of field") has the algorithm and its measured agreement with the testbed's
// thin-lens ray tracing.
// Tests: tests/gl/test_dof.cpp, tests/core/test_dof_settings.cpp, tests/e2e/dof.sh, tests/e2e/blender.sh.

#include "passes/FramePass.h"
#include "passes/ProgramVariants.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>

namespace photopic {

struct CocModel; // core/DepthOfField.h

/// std140 mirror of dof_common.h.glsl's parameter block.
struct DofParameters {
    glm::vec2 fullSize{1.0f};
    glm::vec2 halfSize{1.0f};
    float cocScale = 0.0f;
    float cocBias = 0.0f;
    float focalDistance = 10.0f;
    float focalRange = 5.0f;
    float bokehRadius = 4.0f;
    float maxCoc = 16.0f;
    std::int32_t artistic = 0;
    std::int32_t kernel = 0;
    std::int32_t rings = 3;
    std::int32_t tileSize = 8;
    glm::ivec2 tileCount{1};
    std::int32_t dilation = 1;
    float padding[3] = {};
};
static_assert(sizeof(DofParameters) == 80);
static_assert(offsetof(DofParameters, cocScale) == 16);
static_assert(offsetof(DofParameters, artistic) == 40);
static_assert(offsetof(DofParameters, tileCount) == 56);
static_assert(offsetof(DofParameters, dilation) == 64);

/// The header of the composite's tile list (dof_changed_tiles.h.glsl): the listed composite's indirect
/// arguments (one work group a tile), the tiles classified, the full composite's arguments (z 0 unless
/// most tiles change), then the tiles.
struct GpuDofTileList {
    std::uint32_t changedArgs[3] = {1, 1, 0};
    std::uint32_t tilesDone = 0;
    std::uint32_t fullArgs[3] = {1, 1, 0};
    std::uint32_t pad = 0;
};
static_assert(sizeof(GpuDofTileList) == 32 && offsetof(GpuDofTileList, fullArgs) == 16);

class DofPass final : public FramePass {
public:
    DofPass();
    [[nodiscard]] std::string_view name() const override { return "depth of field"; }
    /// sceneColor, linearDepth and the camera (physical mode reads its lens; artistic needs it for depth).
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        return ctx.settings.dof.enabled && ctx.hdr;
    }
    void execute(FrameContext& ctx, FrameResources& resources) override;

    /// Half-resolution pixels per side of a near-field tile.
    static constexpr int kTileSize = 8;
    /// Full-resolution pixels per side of a composite tile (dof_changed_tiles.h.glsl's kCompositeTile).
    static constexpr int kCompositeTileSize = 8;

private:
    /// The frame's sizes, intermediate textures and output.
    struct Targets {
        Extent full, half, tiles;
        const Texture* coc = nullptr;       ///< signed, full-resolution pixels
        const Texture* farField = nullptr;  ///< half resolution
        const Texture* nearField = nullptr; ///< half resolution
        const Texture* tileMax = nullptr;   ///< the near field's largest CoC per tile
        const Texture* tileReach = nullptr; ///< ... dilated to the tiles it reaches
        const Texture* farBlur = nullptr;
        const Texture* nearBlur = nullptr;
        const Texture* out = nullptr;
    };
    [[nodiscard]] static Targets acquireTargets(Extent e, FrameResources& resources);
    /// Warns once when a physical lens blurs nothing visibly.
    static void warnIfInvisible(const FrameContext& ctx, const CocModel& model);
    [[nodiscard]] static DofParameters parameters(const FrameContext& ctx, const CocModel& model,
                                                  const Targets& t);
    /// The steps: circles of confusion, the half-resolution fields, the near field's tiles, the two
    /// gathers, the composite.
    void circlesOfConfusion(const FrameContext& ctx, const FrameResources& resources, const Targets& t);
    void prepareFields(const FrameContext& ctx, const FrameResources& resources, const Targets& t);
    void nearTiles(const FrameContext& ctx, const Targets& t);
    void gather(const FrameContext& ctx, const Targets& t);
    void composite(const FrameContext& ctx, const FrameResources& resources, const Targets& t);
    /// The tiles the composite changes, listed in mList (after resetting it for `tiles`).
    void listChangedTiles(const FrameContext& ctx, const Targets& t, Extent tiles);

    Program mCoc;
    Program mPrepare;
    Program mTiles;
    Program mDilate;
    Program mFar;
    Program mNear;
    /// The composite over every pixel ([0]) or over the listed tiles ([1], DOF_LISTED).
    struct CompositeProgram : ProgramSlots {
        using ProgramSlots::ProgramSlots;
        ImageSlot color = program.image("uColor");
        ImageSlot coc = program.image("uCoc");
        ImageSlot far = program.image("uFar");
        SamplerSlot near = program.sampler("uNear");
        ImageSlot out = program.image("uOut");
    };
    std::array<CompositeProgram, 2> mComposite;
    /// Uses `c` with the frame's textures bound.
    static void useComposite(const CompositeProgram& c, const FrameResources& resources, const Targets& t);
    Program mChanged;
    ImageSlot mCocDepth = mCoc.image("uLinearDepth");
    ImageSlot mCocOut = mCoc.image("uCoc");
    ImageSlot mPrepareColor = mPrepare.image("uColor");
    ImageSlot mPrepareCoc = mPrepare.image("uCoc");
    ImageSlot mPrepareFar = mPrepare.image("uFar");
    ImageSlot mPrepareNear = mPrepare.image("uNear");
    SamplerSlot mTilesSource = mTiles.sampler("uSource");
    ImageSlot mTilesOut = mTiles.image("uTiles");
    SamplerSlot mDilateSource = mDilate.sampler("uSource");
    ImageSlot mDilateOut = mDilate.image("uTiles");
    ImageSlot mFarField = mFar.image("uField");
    ImageSlot mFarTiles = mFar.image("uTiles"); ///< read by the near gather only: inactive here
    ImageSlot mFarOut = mFar.image("uOut");
    ImageSlot mNearField = mNear.image("uField");
    ImageSlot mNearTiles = mNear.image("uTiles");
    ImageSlot mNearOut = mNear.image("uOut");
    ImageSlot mChangedCoc = mChanged.image("uCoc");
    ImageSlot mChangedNear = mChanged.image("uNear");
    ParameterBlock<DofParameters> mParameters;
    Buffer mList; ///< GpuDofTileList and the tiles; grown to the largest tile count seen
};

} // namespace photopic
