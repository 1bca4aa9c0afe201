// The pipeline inside a host's renderer: whatever GL state the host leaves on, the output is the same, and
// every piece of the host's state is as the host left it after the call.
#include "GlTest.h"
#include "common/HostGlState.h"

#include "core/Image.h"
#include "gl/Gl.h"
#include "gl/TextureIo.h"
#include "pipeline/Pipeline.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace photopic::test {
namespace {

constexpr int kW = 64, kH = 36;

ImageF hdrImage() {
    ImageF image(kW, kH);
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const float v = 0.02f + 0.5f * float(x) / float(kW);
            const bool light = (x - 40) * (x - 40) + (y - 12) * (y - 12) < 9;
            float* px = image.at(x, y);
            px[0] = light ? 40.0f : v;
            px[1] = v * float(y) / float(kH);
            px[2] = 0.3f * v;
            px[3] = 1.0f;
        }
    }
    return image;
}

Settings hostSettings() {
    Settings s;
    s.autoExposure.enabled = false; // every call gives the same frame
    s.output.dither = false;
    s.bloom.enabled = true;
    s.aa.mode = AntiAliasing::Fxaa;
    return s;
}

} // namespace

TEST_F(GlTest, HostGlStateNeitherChangesTheOutputNorIsChanged) {
    const ImageF image = hdrImage();
    const Texture input = makeTexture(image, "host state input");
    Pipeline pipeline(PipelineCreateInfo{.settings = hostSettings()});
    const FrameTime time{.dt = 1.0f / 60.0f, .frameIndex = 3};
    const Image8 reference = readTexture8(pipeline.execute({.color = &input}, time));
    ASSERT_EQ(readTexture8(pipeline.execute({.color = &input}, time)).rgba, reference.rgba)
        << "the frame is not repeatable, so the comparison below would mean nothing";

    const HostObjects host;
    auto runUnder = [&](const std::vector<const HostState*>& states) {
        SCOPED_TRACE(states.size() == 1 ? states.front()->name : "every host state at once");
        host.bind();
        for (const HostState* s : states) {
            s->set();
        }
        const Texture& out = pipeline.execute({.color = &input}, time);
        for (const std::string& problem : host.changedBindings()) {
            ADD_FAILURE() << problem;
        }
        for (const HostState* s : states) {
            EXPECT_TRUE(s->stillSet()) << s->name << " was not restored";
        }
        defaultState();
        const Image8 result = readTexture8(out);
        EXPECT_EQ(result.rgba, reference.rgba) << "the output changed";
    };
    std::vector<const HostState*> all;
    for (const HostState& s : hostStates()) {
        runUnder({&s});
        all.push_back(&s);
    }
    runUnder(all);
}

TEST_F(GlTest, ConstructingAndDestroyingAPipelineLeavesTheHostsBindings) {
    const HostObjects host;
    host.bind();
    {
        Pipeline pipeline(PipelineCreateInfo{.settings = hostSettings()});
        for (const std::string& problem : host.changedBindings()) {
            ADD_FAILURE() << "after construction: " << problem;
        }
    }
    for (const std::string& problem : host.changedBindings()) {
        ADD_FAILURE() << "after destruction: " << problem;
    }
    defaultState();
}

} // namespace photopic::test
