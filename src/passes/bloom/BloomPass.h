#pragma once
// HDR bloom on exposed colour (DESIGN.md step 6): prefilter + 13-tap downsample chain, tent upsample chain.
// The result is the bloom image at the size of level 0 (half or a quarter of the scene); the tone-map pass
// composites it (energy-conserving mix or threshold add).

#include "core/settings/BloomSettings.h"
#include "gl/GpuTimers.h"
#include "gl/Objects.h"

#include <vector>

namespace photopic {

class BloomPass {
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
    void resize(Extent extent);
    const Texture& execute(const Inputs& in);
    /// Levels of the chain the last execute ran.
    [[nodiscard]] int levels() const { return mLevels; }

private:
    void ensureChain(int firstDivisor, int levels);

    Program mPrefilter; ///< level 0: exposure, Karis average, threshold
    Program mDownsample;
    Program mUpsample;
    VertexArray mVao;
    Extent mExtent;
    int mDivisor = 0;
    int mLevels = 0;
    std::vector<Texture> mDown, mUp;
    std::vector<Framebuffer> mDownFbo, mUpFbo;
};

} // namespace photopic
