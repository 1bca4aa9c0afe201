#pragma once

#include "core/Settings.h"
#include "gl/GpuTimers.h"
#include "gl/Objects.h"

#include <cstdint>
#include <map>

namespace photopic {

/// The uber pass: exposure, bloom composite, HDR grading, tone curve, sRGB, dither -> RGBA8 display image;
/// or, as `renderScene`, the composited and graded scene-referred image just before the curve (RGBA32F) for
/// EXR output.
class TonemapPass {
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
    TonemapPass();
    /// Compiles the programs `tonemapping` and `grading` select (with and without bloom) ahead of the first
    /// frame: a set-up boundary, throws GlError with the log. execute() compiles any still missing.
    void prepare(const ToneMappingSettings& tonemapping, const ColorGradingSettings& grading, bool glow);
    void resize(Extent extent);
    const Texture& execute(const Inputs& in);
    const Texture& renderScene(const Inputs& in);

private:
    void draw(const Program& program, const Inputs& in);
    /// One program per (curve, bloom, grading, scene output): the curve and the switches are #defines, not
    /// uniforms. Mesa llvmpipe executes every case of a switch on a uniform under a SIMD mask, so a runtime
    /// curve switch cost all eleven curves per pixel (1920x1080, --sync wall time: 280 ms against 49 ms for
    /// a fixed curve); on a GPU the branch is uniform but registers are allocated for the costliest case.
    const Program& variant(ToneMapper mode, bool bloom, bool glow, bool grade, bool scene);

    std::map<int, Program> mPrograms; ///< by variant key (see variant())
    VertexArray mVao;
    Texture mDisplay;
    Framebuffer mDisplayFbo;
    Texture mScene;
    Framebuffer mSceneFbo;
};

} // namespace photopic
