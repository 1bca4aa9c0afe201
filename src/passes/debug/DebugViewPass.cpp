#include "passes/debug/DebugViewPass.h"

#include "core/Log.h"
#include "passes/Bindings.h"

#include <algorithm>

namespace photopic {

namespace {
constexpr const char* kVertex = "passes/common/fullscreen.vert.glsl";
/// Histogram panel: margin and largest size in pixels; it shrinks with small images.
constexpr int kPanelMargin = 8;
constexpr int kPanelMaxWidth = 512;
constexpr int kPanelMaxHeight = 160;
} // namespace

DebugViewPass::DebugViewPass()
    : mSceneProgram(makeGraphicsProgram(kVertex, "passes/debug/debug_view.frag.glsl", bindingDefines()))
    , mHistogramProgram(
          makeGraphicsProgram(kVertex, "passes/debug/debug_histogram.frag.glsl", bindingDefines()))
    , mVao(VertexArray::create("debug view")) {}

void DebugViewPass::resize(Extent extent) {
    if (mOutput.valid() && mOutput.extent() == extent) {
        return;
    }
    mOutput = Texture({.extent = extent, .format = GL_RGBA8, .debugName = "debug view"});
    mFbo = Framebuffer(mOutput, 0, "debug view");
}

const Texture& DebugViewPass::execute(const Inputs& in) noexcept {
    const Extent e = mOutput.extent();
    DebugGroup group("debug view");
    ScopedGpuTimer timer(in.timers, "debug view", double(e.width) * e.height * 12);
    const AutoExposureSettings& ae = *in.autoExposure;
    mFbo.bind();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingExposureState, in.exposureState->id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingHistogram, in.histogram->id());
    if (in.view == DebugView::Histogram) {
        const Program& p = mHistogramProgram;
        const int width = std::min(kPanelMaxWidth, std::max(e.width - 2 * kPanelMargin, 1));
        const int height = std::min(kPanelMaxHeight, std::max(e.height / 3, 1));
        setUniform(p, "uPanel", float(kPanelMargin), float(kPanelMargin), float(width), float(height));
        setUniform(p, "uLog2Min", ae.histogramLog2Min);
        setUniform(p, "uLog2Max", ae.histogramLog2Max);
        setUniform(p, "uKeyValue", ae.keyValue);
        p.use();
        glBindTextureUnit(0, in.display->id());
    } else {
        const Program& p = mSceneProgram;
        if (in.view == DebugView::Bloom && !in.bloom) {
            try {
                warnOnce("debug.bloom.missing",
                         "debug.view is \"bloom\" but the pipeline has no bloom; showing black");
            } catch (...) { // logging must not take the frame down
            }
        }
        setUniform(p, "uView", int(in.view));
        setUniform(p, "uHasBloom", in.bloom ? 1 : 0);
        setUniform(p, "uHasMask", in.mask ? 1 : 0);
        setUniform(p, "uMeteringMode", int(ae.metering));
        setUniform(p, "uLog2Min", ae.histogramLog2Min);
        setUniform(p, "uLog2Max", ae.histogramLog2Max);
        setUniform(p, "uSpotUv", ae.spot.u, ae.spot.v);
        setUniform(p, "uSpotRadius", ae.spot.radius);
        p.use();
        glBindTextureUnit(0, in.scene->id());
        glBindTextureUnit(1, in.mask ? in.mask->id() : in.scene->id());
        glBindTextureUnit(2, in.bloom ? in.bloom->id() : in.scene->id());
    }
    glBindVertexArray(mVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return mOutput;
}

} // namespace photopic
