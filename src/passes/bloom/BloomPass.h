#pragma once
// HDR bloom on exposed colour (after metering, so the frame's exposure is known; docs/architecture.md):
// prefilter + 13-tap downsample chain, tent upsample chain. The result is the bloom image at the size of
// level 0 (half or a quarter of the scene); the tone-map pass composites it (energy-conserving mix or
// threshold add).

#include "core/settings/BloomSettings.h"
#include "gl/ShaderLibrary.h"
#include "passes/FramePass.h"

#include <cstddef>
#include <cstdint>
#include <glm/vec4.hpp>
#include <vector>

namespace photopic {

/// std140 mirror of bloom_downsample.comp.glsl's parameter block (the prefilter and the plain downsample
/// share it; only the prefilter reads threshold and knee). Rewritten before each level's dispatch.
struct BloomDownsampleParameters {
    float targetTexel[2] = {0.0f, 0.0f}; ///< 1 / target size
    float sourceStep[2] = {0.0f,
                           0.0f}; ///< one source texel in UV (two when level 0 is a quarter of the scene)
    std::int32_t threshold = 0;   ///< 1: threshold mode
    std::int32_t padding[3] = {};
    glm::vec4 knee{0.0f}; ///< T, T - knee, 2 knee, 1 / (4 knee)
};
static_assert(sizeof(BloomDownsampleParameters) == 48);
static_assert(offsetof(BloomDownsampleParameters, sourceStep) == 8 &&
              offsetof(BloomDownsampleParameters, threshold) == 16 &&
              offsetof(BloomDownsampleParameters, knee) == 32);

/// std140 mirror of bloom_upsample.comp.glsl's parameter block, rewritten before each level's dispatch.
struct BloomUpsampleParameters {
    float targetTexel[2] = {0.0f, 0.0f}; ///< 1 / size of level i
    float coarseTexel[2] = {0.0f, 0.0f}; ///< 1 / size of level i + 1
    float radius = 0.0f;
    float padding[3] = {};
};
static_assert(sizeof(BloomUpsampleParameters) == 32);
static_assert(offsetof(BloomUpsampleParameters, coarseTexel) == 8 &&
              offsetof(BloomUpsampleParameters, radius) == 16);

/// How the prefilter (level 0, from the scene) reads the scene where level 0 is exactly half of it in tap
/// steps; elsewhere it takes filtered taps one target texel at a time.
enum class BloomPrefilterKernel {
    Taps,       ///< filtered taps in blocks of blockSide() x blockSide() target texels
    Tiles,      ///< 16x16 targets a group from unfiltered scene texels in shared memory (divisor 2 only)
    SharedTaps, ///< 16x16 targets a group from filtered taps fetched once into shared memory
    /// SharedTaps with each tap the mean of its 2x2 texels from unfiltered fetches (to measure the
    /// filtering of wide texels apart from their reading)
    SharedTexels,
};
/// "taps", "tiles", "shared" or "shared-texels": the PHOTOPIC_BLOOM_PREFILTER value and the bench's name of
/// `kernel`.
[[nodiscard]] const char* bloomPrefilterKernelName(BloomPrefilterKernel kernel);

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
    /// The kernels are the renderer's defaults (setBlockSide, setPrefilterKernel) unless the environment says
    /// otherwise, for measuring them against each other on one device: PHOTOPIC_BLOOM_BLOCK_SIDE=1|2|4,
    /// PHOTOPIC_BLOOM_PREFILTER=taps|tiles|shared|shared-texels (an override in force is reported once; a bad
    /// value is reported and ignored).
    BloomPass();
    /// Target texels per side of an invocation's block where a level is exactly half its source: 4 (16 texels
    /// from 61 shared taps) on a software renderer, 2 (4 texels from 25) on a GPU, where holding 61 taps at
    /// once would cost occupancy. With 4, upsampled levels exactly twice the coarser one are computed in 4x4
    /// blocks too (36 fetched texels, constant tent weights); with 2 by filtered taps. 1: one target texel
    /// per invocation everywhere (13 taps each), as levels that are not exactly half are. Tests run all
    /// three.
    void setBlockSide(int side);
    [[nodiscard]] int blockSide() const { return mBlockSide; }
    /// The prefilter's kernel (BloomPrefilterKernel): Taps by default. Tests run them all.
    void setPrefilterKernel(BloomPrefilterKernel kernel);
    [[nodiscard]] BloomPrefilterKernel prefilterKernel() const { return mPrefilterKernel; }
    /// The invocation shape the programs were built with (pixelGroup() when the pass was made).
    [[nodiscard]] PixelGroup group() const { return mGroup; }
    [[nodiscard]] std::string_view name() const override { return "bloom"; }
    /// The prefilter sanitises each of its five boxes (bloom_downsample.comp.glsl).
    [[nodiscard]] bool sanitizesSceneReads() const override { return true; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    /// The HDR path's chain (the LDR path's glow is part of the tone-map pass).
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        return ctx.hdr && ctx.tier.bloom && ctx.settings.bloom.enabled;
    }
    void resize(Extent extent) override;
    void execute(FrameContext& ctx, FrameResources& resources) override;
    const Texture& execute(const Inputs& in);
    /// Levels of the chain the last execute ran.
    [[nodiscard]] int levels() const { return mLevels; }
    /// Downsampled level `level` (0: the prefilter's output) of the last execute, before the upsamples.
    [[nodiscard]] const Texture& downsampled(int level) const { return mDown.at(std::size_t(level)); }
    /// Upsampled level `level` of the last execute (levels() - 1 of them; 0 is the result).
    [[nodiscard]] const Texture& upsampled(int level) const { return mUp.at(std::size_t(level)); }

private:
    void ensureChain(int firstDivisor, int levels);
    void applyEnvironmentOverrides();

    PixelGroup mGroup; ///< the invocation shape of every program here (gl/ShaderLibrary.h pixelGroup)
    /// Level 0 (exposure, Karis average, threshold) and the later levels; `Blocks`: blocks of mBlockSide x
    /// mBlockSide target texels per invocation sharing their taps, for a target exactly half its source.
    Program mPrefilter, mPrefilterBlocks;
    BloomPrefilterKernel mPrefilterKernel = BloomPrefilterKernel::Taps;
    Program mPrefilterTiled; ///< the program of a kernel other than Taps while it is the kernel
    Program mDownsample, mDownsampleBlocks;
    int mBlockSide = 2;
    Program mUpsample;
    /// 4x4 blocks of a level exactly twice the coarser one (with block side 4 only; else not made).
    Program mUpsampleBlocks;
    /// The prefilter's: the scene may be the host's own texture, with its own filtering.
    Sampler mSceneSampler;
    /// One block a level (a block is written only when its contents change: gl/Objects.h), so a chain whose
    /// size and settings hold still updates no buffer in a frame.
    std::vector<ParameterBlock<BloomDownsampleParameters>> mDownParameters;
    std::vector<ParameterBlock<BloomUpsampleParameters>> mUpParameters;
    Extent mExtent;
    int mDivisor = 0;
    int mLevels = 0;
    std::vector<Texture> mDown, mUp;
};

} // namespace photopic
