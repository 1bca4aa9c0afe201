#pragma once
// Debug views (settings `debug.view`). Scene-value views (exposure false colour, luma, EV, metering weights,
// bloom) replace the image before tone mapping (DESIGN.md step 8) and are shown as they are; the histogram is
// an overlay over the tone-mapped image (step 12), drawn from the GPU histogram buffer.

#include "core/Settings.h"
#include "gl/GpuTimers.h"
#include "gl/Objects.h"

namespace photopic {

class DebugViewPass {
public:
    struct Inputs {
        DebugView view = DebugView::None;
        const Texture* scene = nullptr;        ///< sanitised HDR colour (scene views)
        const Texture* display = nullptr;      ///< tone-mapped RGBA8 image (histogram overlay)
        const Texture* mask = nullptr;         ///< metering mask, when loaded
        const Texture* bloom = nullptr;        ///< bloom texture, when the pipeline has bloom
        const Buffer* exposureState = nullptr; ///< GpuExposureState
        const Buffer* histogram = nullptr;     ///< 256 uint bins
        const AutoExposureSettings* autoExposure = nullptr;
        GpuTimers* timers = nullptr;
    };
    DebugViewPass();
    void resize(Extent extent);
    /// The view as a display image (RGBA8, sRGB-encoded values). view must not be None.
    const Texture& execute(const Inputs& in) noexcept;

    /// True for the views that replace the scene before tone mapping.
    [[nodiscard]] static bool isSceneView(DebugView view) {
        return view != DebugView::None && view != DebugView::Histogram;
    }

private:
    Program mSceneProgram;
    Program mHistogramProgram;
    VertexArray mVao;
    Texture mOutput;
    Framebuffer mFbo;
};

} // namespace photopic
