#pragma once
// FXAA 3.11 (quality path) on the display-referred RGBA8 image (DESIGN.md step 10).

#include "core/settings/DisplaySettings.h"
#include "gl/GpuTimers.h"
#include "gl/Objects.h"

namespace photopic {

class FxaaPass {
public:
    struct Inputs {
        const Texture* display = nullptr; ///< tone-mapped, sRGB-encoded RGBA8
        const FxaaSettings* settings = nullptr;
        GpuTimers* timers = nullptr;
    };
    FxaaPass();
    void resize(Extent extent);
    const Texture& execute(const Inputs& in);

private:
    Program mProgram;
    VertexArray mVao;
    Texture mOutput;
    Framebuffer mFbo;
};

} // namespace photopic
