// GpuTimers: results come back frames later without a wait; collect() hands over what has arrived, oldest
// first, and each frame only once.

#include "GlTest.h"

#include "gl/GpuTimers.h"

namespace photopic::test {

TEST_F(GlTest, GpuTimersCollectHandsOverArrivedFramesOnceOldestFirst) {
    GpuTimers timers;
    const Texture target({.extent = {4, 4}, .format = GL_RGBA8, .debugName = "timed clear"});
    for (const char* name : {"first", "second"}) {
        timers.beginFrame();
        timers.begin(name);
        glClearTexImage(target.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        timers.end();
        timers.endFrame();
    }
    glFinish(); // both frames' timestamps are then available
    const std::vector<std::vector<PassTiming>> frames = timers.collect();
    ASSERT_EQ(frames.size(), 2u);
    ASSERT_EQ(frames[0].size(), 1u);
    EXPECT_EQ(frames[0][0].name, "first");
    EXPECT_EQ(frames[1][0].name, "second");
    EXPECT_GE(frames[0][0].gpuMs, 0.0);
    EXPECT_TRUE(timers.collect().empty()) << "a frame is handed over once";
    EXPECT_TRUE(timers.drain().empty());
}

} // namespace photopic::test
