#pragma once
// Temporal anti-aliasing: this frame's jittered samples resolved with the reprojected history, in the HDR
// domain before metering (the image the exposure reads is the anti-aliased one). The resolve replaces
// sceneColor and keeps itself, with each pixel's depth, as next frame's history.
// Tests: tests/gl/test_taa.cpp.

#include "gl/ShaderLibrary.h"
#include "passes/FramePass.h"
#include "passes/HistoryTexture.h"
#include "passes/ProgramVariants.h"

#include <cstdint>
#include <glm/mat4x4.hpp>

namespace photopic {

/// std140 mirror of taa_resolve.comp.glsl's parameter block.
struct TaaParameters {
    glm::mat4 invProjection{1.0f};
    glm::mat4 viewToPreviousClip{1.0f}; ///< this frame's view space -> last frame's clip space
    float blend = 0.9f;
    float gamma = 1.0f;
    float feedbackMin = 0.88f;
    float feedbackMax = 0.97f;
    float stillPixels = 0.25f;
    std::int32_t hasHistory = 0;
    std::int32_t hasDepth = 0;
    std::int32_t hasCamera = 0;
    std::int32_t writeDebug = 0;
    std::int32_t adaptive = 0;
    std::int32_t bilinearHistory = 0;
    std::int32_t padding = 0;
};
static_assert(sizeof(TaaParameters) == 176);
static_assert(offsetof(TaaParameters, blend) == 128);
static_assert(offsetof(TaaParameters, hasHistory) == 148);
static_assert(offsetof(TaaParameters, bilinearHistory) == 168);

class TaaPass final : public FramePass {
public:
    TaaPass();
    [[nodiscard]] std::string_view name() const override { return "taa"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override;
    void invalidateHistory() override {
        mHistory.invalidate();
        mHistoryAux.invalidate();
    }
    void execute(FrameContext& ctx, FrameResources& resources) override;

private:
    /// This frame's parameter block.
    [[nodiscard]] TaaParameters parameters(const FrameContext& ctx, const FrameResources& resources,
                                           bool debug) const;
    /// The debug target when a TAA debug view asks for one, else null.
    [[nodiscard]] static const Texture* debugTarget(const FrameContext& ctx, FrameResources& resources);
    /// The resolve for a history filter, the inputs present (TAA_BILINEAR, TAA_DEPTH, TAA_CAMERA) and the
    /// motion input's format (TAA_MOTION_FORMAT), and its slots.
    struct ResolveProgram : ProgramSlots {
        using ProgramSlots::ProgramSlots;
        ImageSlot current = program.image("uCurrent");
        SamplerSlot history = program.sampler("uHistory");
        ImageSlot historyAux = program.image("uHistoryAux");
        ImageSlot motion = program.image("uMotion");
        ImageSlot depth = program.image("uDepth");
        ImageSlot output = program.image("uOutput");
        ImageSlot outputAux = program.image("uOutputAux");
        ImageSlot debug = program.image("uDebug");
    };
    /// Built on first use.
    const ResolveProgram& resolveProgram(const TaaParameters& p, GLenum motionFormat);
    void bindInputs(const ResolveProgram& program, const FrameResources& resources,
                    const Texture* debugTarget) const;

    /// The 3x3 neighbourhood from a shared tile (sharedMemoryTiles(): a GPU), for the pass's life.
    bool mSharedTile = sharedMemoryTiles();
    /// By bilinear history (bit 0), depth (bit 1), camera (bit 2) and motion format (bits 3-4).
    ProgramVariants<ResolveProgram, 32> mPrograms{"passes/taa/taa_resolve.comp.glsl"};
    ParameterBlock<TaaParameters> mParameters;
    HistoryTexture mHistory;    ///< the resolved colour
    HistoryTexture mHistoryAux; ///< per pixel: linear depth and stability (how long it has held still)
    Texture mNoDebug;           ///< bound to the debug image unit when no debug view asks for it
};

} // namespace photopic
