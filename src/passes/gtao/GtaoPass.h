#pragma once
// Ground-truth ambient occlusion (Jimenez et al. 2016, "Practical Real-Time Strategies for Accurate Indirect
// Occlusion"): per pixel, a few screen-space slices around the view vector; in each, the two horizons within
// the world-space radius, clamped to the normal's hemisphere, and the cosine-weighted visibility between them
// integrated analytically. A depth-aware spatial filter then removes the per-pixel noise. The output is the
// raw visibility in [0, 1] (1 for the sky), the quantity a ray tracer measures; `ssao.power` is not in it.
//
// Two instances: one in the lighting stage (ssao.apply = lighting: the host multiplies its indirect light by
// it) and one in the post stage (ssao.apply = multiply), followed by AoMultiplyPass.
// Tests: tests/gl/test_gtao.cpp, tests/e2e/blender.sh (against Cycles' AO).

#include "passes/FramePass.h"
#include "passes/ProgramVariants.h"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

namespace photopic {

/// std140 mirror of gtao_common.h.glsl's parameter block (the horizon search and the denoiser).
struct GtaoParameters {
    glm::mat4 projection{1.0f};
    glm::vec2 fullSize{1.0f}; ///< full-resolution extent, pixels
    float radius = 1.0f;      ///< world units
    float bias = 0.0f;        ///< world units along the normal
    std::int32_t slices = 3;
    std::int32_t steps = 3;      ///< per side
    std::int32_t scale = 1;      ///< full-resolution pixels per AO texel (1 or 2)
    std::uint32_t frame = 0;     ///< rotates the noise
    std::int32_t octahedral = 0; ///< normals are octahedral-encoded (else view xyz)
    std::int32_t padding = 0;
    /// A texel's view position without divisions (gtao_common.h.glsl viewPositionAtTexel): texelToView().
    glm::vec2 texelScale{0.0f};
    glm::vec2 texelBias{0.0f};
    glm::vec2 depthScale{0.0f};
    glm::vec2 viewOffset{0.0f};
    std::int32_t padding2[2] = {};
};
static_assert(sizeof(GtaoParameters) == 144);
static_assert(offsetof(GtaoParameters, fullSize) == 64);
static_assert(offsetof(GtaoParameters, frame) == 92);
static_assert(offsetof(GtaoParameters, texelScale) == 104);

/// std140 mirror of ao_multiply.comp.glsl's parameter block.
struct AoMultiplyParameters {
    float power = 1.0f;
    float padding[3] = {};
};
static_assert(sizeof(AoMultiplyParameters) == 16);

class GtaoPass final : public FramePass {
public:
    enum class Stage { Lighting, Post };
    explicit GtaoPass(Stage stage);
    [[nodiscard]] std::string_view name() const override { return "gtao"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    /// ssao.enabled, and ssao.apply picks this instance's stage.
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override;
    void execute(FrameContext& ctx, FrameResources& resources) override;

    /// Slices and steps per side for a quality tier.
    [[nodiscard]] static glm::ivec2 slicesAndSteps(EffectQuality quality) noexcept;
    /// Sets `p`'s texel-to-view constants from its projection and full size: a texel's view xy at linear
    /// depth z is (texel scale + bias) w + z depthScale + viewOffset, w = P[3][3] - P[2][3] z.
    static void texelToView(GtaoParameters& p) noexcept;
    /// The coarse levels above the full-resolution surface (ssao.sampleMips): sizes the image and reaches the
    /// shaders as GTAO_SURFACE_LEVELS (gtao_pyramid.h.glsl). At most 4: a pixel's place in its block rides in
    /// 4 bits an axis.
    static constexpr int kSurfaceLevels = 4;
    static_assert(kSurfaceLevels >= 1 && kSurfaceLevels <= 4);
    /// The surface texture's extent for a `full`-sized frame with the coarse levels: level 0 and, to its
    /// right, levels 1-4 one below the other.
    [[nodiscard]] static Extent surfacePyramidExtent(Extent full) noexcept;
    /// The frame's first dispatch: binds the parameter block and packs the linear depth and the normals into
    /// the surface texture (gtao_surface.h.glsl), with the coarse levels under ssao.sampleMips; returns it
    /// (a pool texture of `resources`). execute() begins with it; tests call it alone.
    const Texture& packSurface(FrameContext& ctx, FrameResources& resources);

private:
    /// Full-resolution pixels per AO texel: 1, or 2 at half resolution.
    static int resolutionScale(GtaoResolution resolution) noexcept {
        return resolution == GtaoResolution::Half ? 2 : 1;
    }
    /// The horizon search into `raw` (one texel per AO texel) from packSurface()'s surface, then the
    /// denoise into `out`.
    void search(const Texture& surface, const Texture& raw, EffectQuality quality, int scale, bool mips,
                double bytes, GpuTimers* timers);
    void denoise(const Texture& surface, const Texture& raw, const Texture& out, int scale, double bytes,
                 GpuTimers* timers);

    /// The packing pass, with or without the coarse levels (GTAO_SAMPLE_MIPS), and its slots.
    struct PrepareProgram : ProgramSlots {
        using ProgramSlots::ProgramSlots;
        ImageSlot depth = program.image("uLinearDepth");
        SamplerSlot normals = program.sampler("uNormals");
        ImageSlot surface = program.image("uSurfaceOut");
    };

    /// The horizon search for one preset and resolution (GTAO_SLICES, GTAO_STEPS, GTAO_SCALE) and whether
    /// far steps read the coarse levels (GTAO_SAMPLE_MIPS), and its slots.
    struct SearchProgram : ProgramSlots {
        using ProgramSlots::ProgramSlots;
        ImageSlot surface = program.image("uSurface");
        ImageSlot raw = program.image("uRaw");
    };
    /// The search program for `quality` at `scale` (1 or 2), built on first use.
    const SearchProgram& searchProgram(EffectQuality quality, int scale, bool mips);

    /// The denoiser for one resolution (GTAO_SCALE: full-resolution pixels per AO texel), and its slots.
    struct DenoiseProgram : ProgramSlots {
        using ProgramSlots::ProgramSlots;
        ImageSlot surface = program.image("uSurface");
        ImageSlot raw = program.image("uRaw");
        ImageSlot out = program.image("uVisibility");
    };

    Stage mStage;
    ProgramVariants<PrepareProgram, 2> mPrepare{"passes/gtao/gtao_prepare.comp.glsl"}; ///< by mips
    ProgramVariants<SearchProgram, 16> mSearch{
        "passes/gtao/gtao_main.comp.glsl"}; ///< by (quality x 2 + scale - 1) x 2 + mips
    DenoiseProgram mDenoiseFull;
    DenoiseProgram mDenoiseHalf;
    ParameterBlock<GtaoParameters> mParameters;
};

/// ssao.apply = multiply: sceneColor *= visibility^power (before TAA and metering). It darkens direct light
/// too; a host with a lighting stage should use ssao.apply = lighting instead.
class AoMultiplyPass final : public FramePass {
public:
    AoMultiplyPass();
    [[nodiscard]] std::string_view name() const override { return "ao multiply"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override;
    void execute(FrameContext& ctx, FrameResources& resources) override;

private:
    Program mProgram;
    ParameterBlock<AoMultiplyParameters> mParameters;
    SamplerSlot mScene = mProgram.sampler("uScene");
    SamplerSlot mVisibility = mProgram.sampler("uVisibility");
    ImageSlot mOut = mProgram.image("uOut");
};

} // namespace photopic
