#pragma once
// Display-domain effects in one pass (DESIGN.md step 11 and "Cost"): chromatic aberration, lens flare
// composite, dazzle, vignette and grain on the tone-mapped RGBA8 image, one read and one write.

#include "core/settings/DisplaySettings.h"
#include "gl/GpuTimers.h"
#include "gl/Objects.h"

#include <cstdint>

namespace photopic {

class DisplayEffectsPass {
public:
    struct Inputs {
        const Texture* display = nullptr;      ///< tone-mapped sRGB-encoded RGBA8
        const Buffer* exposureState = nullptr; ///< GpuExposureState (dazzle)
        const Texture* flare = nullptr;        ///< lens flare buffer, or null
        const Texture* glare = nullptr;        ///< bloom image for dazzle's glare, or null
        const VignetteSettings* vignette = nullptr;
        bool chromaticAberration = true; ///< the quality tier allows it
        const GrainSettings* grain = nullptr;
        const DazzleSettings* dazzle = nullptr;
        std::uint64_t frameIndex = 0;
        GpuTimers* timers = nullptr;
    };
    DisplayEffectsPass();
    void resize(Extent extent);
    const Texture& execute(const Inputs& in);

private:
    Program mProgram;
    VertexArray mVao;
    Texture mBlack; ///< bound where an optional input is absent, so every sampler has a complete texture
    Texture mOutput;
    Framebuffer mFbo;
};

} // namespace photopic
