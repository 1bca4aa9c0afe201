#pragma once
// Depth of field (Jimenez 2014, "Next Generation Post Processing in Call of Duty: Advanced Warfare"): each
// pixel's signed circle of confusion from its depth (the camera's thin lens, or an artistic focal distance
// and range), near and far fields at half resolution, the near field's reach dilated over tiles, a gather
// of each over a disc or hexagon, and a full-resolution composite over the sharp image. It runs on the
// scene-referred colour after exposure is metered and before bloom, so bokeh highlights stay HDR and bloom.
// docs/architecture.md ("Depth of field") has the algorithm and its measured agreement with the testbed's
// thin-lens ray tracing.

#include "passes/FramePass.h"

#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>

namespace photopic {

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

private:
    Program mCoc;
    Program mPrepare;
    Program mTiles;
    Program mDilate;
    Program mFar;
    Program mNear;
    Program mComposite;
    ParameterBlock<DofParameters> mParameters;
};

} // namespace photopic
