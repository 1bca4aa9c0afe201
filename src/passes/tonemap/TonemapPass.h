#pragma once

#include "core/Settings.h"
#include "passes/FramePass.h"

#include <cstdint>
#include <map>

namespace photopic {

/// The uber pass: exposure, bloom composite, HDR grading, tone curve, sRGB, dither -> RGBA8 display image;
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
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    /// Compiles the programs the settings select (with and without bloom) ahead of the first frame: a
    /// set-up boundary, throws GlError with the log. execute() compiles any still missing.
    void configure(const Settings& settings) override;
    void execute(FrameContext& ctx, FrameResources& resources) override;
    /// The composited and graded scene-referred image just before the curve (RGBA32F), for EXR output.
    const Texture& renderScene(const Inputs& in);

private:
    void draw(const Program& program, const Inputs& in, Extent extent);
    /// One program per (curve, bloom, grading, scene output): the curve and the switches are #defines, not
    /// uniforms. Mesa llvmpipe executes every case of a switch on a uniform under a SIMD mask, so a runtime
    /// curve switch cost all eleven curves per pixel (1920x1080, --sync wall time: 280 ms against 49 ms for
    /// a fixed curve); on a GPU the branch is uniform but registers are allocated for the costliest case.
    const Program& variant(ToneMapper mode, bool bloom, bool glow, bool grade, bool scene);

    std::map<int, Program> mPrograms; ///< by variant key (see variant())
    const Capabilities& mCaps;
    VertexArray mVao;
    Texture mScene;
    Framebuffer mSceneFbo;
};

} // namespace photopic
