#pragma once

#include "core/Settings.h"
#include "gl/GpuTimers.h"
#include "gl/Objects.h"

#include <cstdint>

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
        const BloomSettings* bloomSettings = nullptr;  ///< mode and intensity, when `bloom` is set
        const ColorGradingSettings* grading = nullptr; ///< null or disabled: no grading
        std::uint64_t frameIndex = 0;
        GpuTimers* timers = nullptr;
    };
    TonemapPass();
    void resize(Extent extent);
    const Texture& execute(const Inputs& in);
    const Texture& renderScene(const Inputs& in);

private:
    void draw(const Program& program, const Inputs& in);

    Program mDisplayProgram[2]; ///< [bloom composited]
    Program mSceneProgram[2];
    VertexArray mVao;
    Texture mDisplay;
    Framebuffer mDisplayFbo;
    Texture mScene;
    Framebuffer mSceneFbo;
};

} // namespace photopic
