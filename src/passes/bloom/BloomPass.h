#pragma once
// HDR bloom on exposed colour (after metering, so the frame's exposure is known): a pyramid of levels, each
// the one above (or the frame) downsampled by a binomial filter and blurred by a Gaussian of two of its own
// texels, summed from the widest up (docs/architecture.md, "Bloom"). The result covers the frame at the
// size of level 0 (half or a quarter of it); alpha holds the share of each texel's glow that came from
// inside the frame. The tone-map pass composites it (energy-conserving mix or threshold add).
// Tests: tests/gl/test_bloom.cpp (each step against its CPU twin, energy, threshold),
// tests/gl/test_bloom_roundness.cpp (the glow of a point in every mode and preset).

#include "core/Bloom.h"
#include "gl/ShaderLibrary.h"
#include "passes/FramePass.h"
#include "passes/ProgramVariants.h"
#include "passes/bloom/BloomSettings.h"

#include <cstddef>
#include <cstdint>
#include <glm/vec4.hpp>
#include <vector>

namespace photopic {

/// std140 mirror of bloom_step.h.glsl's parameter block, which every step of the chain reads; one block a
/// step, rewritten only when its contents change.
struct BloomStepParameters {
    float sourceTexel[2] = {0.0f, 0.0f};   ///< 1 / the extent of the texture read
    float sourceScale[2] = {0.0f, 0.0f};   ///< source coordinate of target texel t: t * scale + origin
    float sourceOrigin[2] = {0.0f, 0.0f};  ///< (texel-centre coordinates)
    float coarseTexel[2] = {0.0f, 0.0f};   ///< upsample: 1 / the coarser result's extent
    float coarseOrigin[2] = {0.0f, 0.0f};  ///< upsample: coarse coordinate of level texel q: q / 2 + origin
    std::int32_t frameSize[2] = {0, 0};    ///< prefilter: the frame's size
    std::int32_t threshold = 0;            ///< prefilter: 1 in threshold mode
    float radius = 0.0f;                   ///< upsample: share handed to the wider levels
    std::int32_t targetOffset[2] = {0, 0}; ///< upsample: level texel of target texel t, minus t
    glm::vec4 knee{0.0f};                  ///< prefilter: T, T - knee, 2 knee, 1 / (4 knee)
    glm::vec4 weights[3] = {};             ///< blur and upsample: the Gaussian's weights 0 .. 8 texels out
};
static_assert(sizeof(BloomStepParameters) == 128 && kBloomBlurReach + 1 <= 12);
static_assert(offsetof(BloomStepParameters, frameSize) == 40 &&
              offsetof(BloomStepParameters, threshold) == 48 &&
              offsetof(BloomStepParameters, targetOffset) == 56 &&
              offsetof(BloomStepParameters, knee) == 64 && offsetof(BloomStepParameters, weights) == 80);

class BloomPass final : public FramePass {
public:
    struct Inputs {
        const Texture* scene = nullptr;        ///< sanitised scene-referred colour (not yet exposed)
        const Buffer* exposureState = nullptr; ///< GpuExposureState
        const BloomSettings* settings = nullptr;
        int firstDivisor = 2; ///< level 0 is the scene / this (2 or 4; the quality tier decides)
        int mipCount = 6;     ///< levels wanted (fewer when the image is small)
        GpuTimers* timers = nullptr;
    };
    BloomPass();
    [[nodiscard]] std::string_view name() const override { return "bloom"; }
    /// The prefilter sanitises the mean of each footprint (bloom_downsample.comp.glsl).
    [[nodiscard]] bool sanitizesSceneReads() const override { return true; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    /// The HDR path's chain (the LDR path's glow is part of the tone-map pass); in glare mode the glare pass
    /// (passes/glare/) writes the bloom instead.
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        return ctx.hdr && ctx.tier.bloom && ctx.settings.bloom.enabled &&
               ctx.settings.bloom.mode != BloomMode::Glare;
    }
    void resize(Extent extent) override;
    void execute(FrameContext& ctx, FrameResources& resources) override;
    /// Runs the chain; the result covers the frame at level 0's size (bloomLevelFrame), alpha its coverage.
    const Texture& execute(const Inputs& in);
    /// Levels of the chain the last execute ran.
    [[nodiscard]] int levels() const { return mLevels; }
    /// Level `level` (0: the prefilter's output) of the last execute, downsampled, with its guard band.
    [[nodiscard]] const Texture& downsampled(int level) const { return mDown.at(std::size_t(level)); }
    /// Level `level` of the last execute blurred along rows, with its guard band.
    [[nodiscard]] const Texture& blurredRows(int level) const { return mRows.at(std::size_t(level)); }
    /// The result of level `level` of the last execute (levels() of them; 0 is the chain's result, without
    /// a guard band; the others have one).
    [[nodiscard]] const Texture& upsampled(int level) const { return mUp.at(std::size_t(level)); }

private:
    void ensureChain(int firstDivisor, int levels);
    void downsample(const Inputs& in, int level);
    void blurRows(const Inputs& in, int level);
    void upsample(const Inputs& in, int level);
    /// One program of the chain: it reads its source and writes its target (bloom_step.h.glsl's readers).
    struct Step : ProgramSlots {
        using ProgramSlots::ProgramSlots;
        SamplerSlot source = program.sampler("uSource");
        ImageSlot target = program.image("uTarget");
    };
    /// Binds `step`'s program, `block` (updated to `p`), the source with the chain's sampler and the target.
    void bindStep(const Step& step, ParameterBlock<BloomStepParameters>& block, const BloomStepParameters& p,
                  const Texture& source, const Texture& target);

    PixelGroup mGroup; ///< the invocation shape of every program here (gl/ShaderLibrary.h pixelGroup)
    Step mPrefilter, mPrefilterQuarter, mDownsample, mBlurRows, mUpsample, mUpsampleCoarse;
    SamplerSlot mCoarse = mUpsampleCoarse.program.sampler("uCoarse"); ///< the coarser level's result
    /// Every read of the chain: past a texture's edge lies transparent black (the frame's outside, and the
    /// levels' bands beyond what they hold).
    Sampler mSampler;
    std::vector<ParameterBlock<BloomStepParameters>> mDownBlocks, mRowBlocks, mUpBlocks;
    Extent mExtent;
    int mDivisor = 0;
    int mLevels = 0;
    std::vector<Texture> mDown, mRows, mUp;
};

} // namespace photopic
