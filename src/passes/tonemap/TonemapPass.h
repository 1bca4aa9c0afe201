#pragma once

#include "core/Settings.h"
#include "gl/GpuTimers.h"
#include "gl/Objects.h"

#include <cstdint>

namespace photopic {

/// Exposure x tone curve x sRGB x dither -> RGBA8 display image; or, as `renderScene`, the exposed
/// scene-referred image just before the curve (RGBA32F) for EXR output.
class TonemapPass {
public:
    struct Inputs {
        const Texture* scene = nullptr;        ///< scene-referred colour (sanitised or the host's)
        const Buffer* exposureState = nullptr; ///< GpuExposureState
        const ToneMappingSettings* tonemapping = nullptr;
        const OutputSettings* output = nullptr;
        std::uint64_t frameIndex = 0;
        GpuTimers* timers = nullptr;
    };
    TonemapPass();
    void resize(Extent extent);
    const Texture& execute(const Inputs& in);
    const Texture& renderScene(const Inputs& in);

private:
    void draw(const Program& program, const Inputs& in);

    Program mDisplayProgram;
    Program mSceneProgram;
    VertexArray mVao;
    Texture mDisplay;
    Framebuffer mDisplayFbo;
    Texture mScene;
    Framebuffer mSceneFbo;
};

} // namespace photopic
