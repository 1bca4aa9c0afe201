#pragma once
// Tests: tests/gl/test_tonemap_gpu.cpp, tests/gl/test_bloom.cpp (the composite).

#include "core/Settings.h"
#include "gl/ShaderLibrary.h"
#include "passes/FramePass.h"
#include "passes/ProgramVariants.h"

#include <cstddef>
#include <cstdint>
#include <map>

namespace photopic {

/// std140 mirror of tonemap.comp.glsl's parameter block, one layout for every variant: the bloom, glow and
/// grading members are read only by the variants that #define BLOOM, GLOW and GRADE.
struct TonemapParameters {
    float whitePoint = 1.0f;
    std::int32_t agxLook = 0;
    std::int32_t dither = 0;
    std::uint32_t frame = 0;
    std::int32_t bloomAdditive = 0; ///< 0: energy-conserving mix (by the bloom's alpha); 1: additive
    float bloomIntensity = 0.0f;
    float bloomPixels = 1.0f; ///< frame pixels per bloom texel
    float padding0 = 0.0f;
    float whiteBalance[3][4] = {}; ///< mat3: three columns, each padded to a vec4
    float contrast = 1.0f;
    float saturation = 1.0f;
    float glowThreshold = 1.0f; ///< exposed scene-linear: only what lies above glows
    float glowIntensity = 0.0f; ///< additive gain
    float glowRadius = 0.0f;    ///< px
    float padding1[3] = {};
    float lift[3] = {0.0f, 0.0f, 0.0f};
    float padding2 = 0.0f;
    float invGamma[3] = {1.0f, 1.0f, 1.0f}; ///< 1 / gamma, per channel
    float padding3 = 0.0f;
    float gain[3] = {1.0f, 1.0f, 1.0f};
    float padding4 = 0.0f;
    std::uint32_t ditherSeeds[2] = {}; ///< the dither's two per-frame seeds (noise.h.glsl triangularNoise3)
    std::uint32_t padding5[2] = {};
};
static_assert(sizeof(TonemapParameters) == 176);
static_assert(offsetof(TonemapParameters, frame) == 12 && offsetof(TonemapParameters, bloomAdditive) == 16 &&
              offsetof(TonemapParameters, whiteBalance) == 32 &&
              offsetof(TonemapParameters, contrast) == 80 && offsetof(TonemapParameters, glowRadius) == 96 &&
              offsetof(TonemapParameters, lift) == 112 && offsetof(TonemapParameters, invGamma) == 128 &&
              offsetof(TonemapParameters, gain) == 144 && offsetof(TonemapParameters, ditherSeeds) == 160);

/// The uber pass: exposure, bloom composite, HDR grading, tone curve, sRGB, dither -> RGBA8 display image
/// (RGBA16 at output.bitDepth 16);
/// or, as `renderScene`, the composited and graded scene-referred image just before the curve (RGBA32F) for
/// EXR output.
class TonemapPass final : public FramePass {
public:
    struct Inputs {
        const Texture* scene = nullptr;        ///< scene-referred colour (sanitised or the host's)
        const Buffer* exposureState = nullptr; ///< GpuExposureState
        const ToneMappingSettings* tonemapping = nullptr;
        const OutputSettings* output = nullptr;
        const Texture* bloom = nullptr; ///< bloom chain result (exposed), or null: no bloom composite
        const BloomSettings* bloomSettings = nullptr; ///< mode and intensity, when `bloom` or `glow` is set
        bool glow =
            false; ///< the legacy tier's cheap glow (no bloom chain): bloomSettings' threshold, intensity
        const ColorGradingSettings* grading = nullptr; ///< null or disabled: no grading
        std::uint64_t frameIndex = 0;
        GpuTimers* timers = nullptr;
    };
    /// `caps` decides whether frames can take the HDR path (for the programs configure() prepares).
    explicit TonemapPass(const Capabilities& caps);
    [[nodiscard]] std::string_view name() const override { return "composite + grade + tonemap"; }
    [[nodiscard]] bool sanitizesSceneReads() const override { return true; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    /// Compiles the programs the settings select (with and without bloom; the bloom one in 4x4 blocks where
    /// those are on) ahead of the first frame: a set-up boundary, throws GlError with the log. execute()
    /// compiles any still missing, such as the per-pixel bloom variant for a frame whose bloom is not half of
    /// it while the blocks are on.
    void configure(const Settings& settings) override;
    void execute(FrameContext& ctx, FrameResources& resources) override;
    /// The composited and graded scene-referred image just before the curve (RGBA32F), for EXR output.
    const Texture& renderScene(const Inputs& in);
    /// Where the bloom image is exactly half the frame, composite 4x4 pixels per invocation from the 4x4
    /// bloom texels their bilinear taps share (fetched once) instead of one filtered tap per pixel: on by
    /// default on a software renderer, where texture reads are what the pass pays for. The same filter, its
    /// sums rounded in another order. Tests set either.
    void setBloomBlocks(bool on);

private:
    /// One program of the pass and its samplers and image (uBloom inactive where BLOOM is not defined).
    struct Variant : ProgramSlots {
        using ProgramSlots::ProgramSlots;
        SamplerSlot scene = program.sampler("uScene");
        SamplerSlot bloom = program.sampler("uBloom");
        ImageSlot output = program.image("uOutput");
    };
    /// One dispatch of `variant` over `target` (RGBA8 or RGBA16 display, or RGBA32F scene-referred output).
    void run(const Variant& variant, const Inputs& in, const Texture& target, bool blocks = false);
    /// Whether this dispatch takes the bloom in 4x4 blocks (setBloomBlocks, and the bloom half of `target`).
    [[nodiscard]] bool bloomBlocks(const Inputs& in, Extent target) const;
    /// One program per (curve, bloom, grading, scene output, display depth): the curve and the switches are
    /// #defines, not
    /// uniforms. Mesa llvmpipe executes every case of a switch on a uniform under a SIMD mask, so a runtime
    /// curve switch costs all eleven curves per pixel; on a GPU the branch is uniform but registers are
    /// allocated for the costliest case.
    const Variant& variant(ToneMapper mode, bool bloom, bool glow, bool grade, bool scene, bool display16,
                           bool blocks = false);

    std::map<int, Variant> mPrograms; ///< by variant key (see variant())
    ParameterBlock<TonemapParameters> mParameters;
    const Capabilities& mCaps;
    PixelGroup mGroup; ///< the programs' invocation shape (gl/ShaderLibrary.h pixelGroup)
    bool mBloomBlocks = false;
    Texture mScene;
};

} // namespace photopic
