// How driver messages are counted: the GL tests fail on NVIDIA's performance warnings and on undefined
// behaviour anywhere; its compiles of a program for a draw state are counted apart, for the steady-state
// tests.
#include "GlTest.h"

#include "gl/Debug.h"
#include "gl/Gl.h"

#include <string>

namespace photopic::test {

namespace {

void say(GLenum type, const std::string& text) {
    glDebugMessageInsert(GL_DEBUG_SOURCE_THIRD_PARTY, type, 1, GL_DEBUG_SEVERITY_MEDIUM, GLsizei(text.size()),
                         text.c_str());
}

} // namespace

TEST_F(GlTest, DebugMessagesCountRecompilesApartFromPerformanceWarningsAndUndefinedBehaviour) {
    const std::string recompile3 = "Vertex shader in program 3 is being recompiled based on GL state.";
    say(GL_DEBUG_TYPE_PERFORMANCE, recompile3);
    say(GL_DEBUG_TYPE_PERFORMANCE, "Fragment shader in program 3 is being recompiled based on GL state.");
    say(GL_DEBUG_TYPE_PERFORMANCE,
        "Vertex shader in program 4 is being recompiled based on GL state, and was "
        "not found in the disk cache");
    say(GL_DEBUG_TYPE_PERFORMANCE, recompile3);
    EXPECT_EQ(glDebugRecompileCount(), 4u);
    EXPECT_EQ(glDebugPerformanceWarningCount(), 0u)
        << "a compile for a draw state is not a warning of its own";
    say(GL_DEBUG_TYPE_PERFORMANCE, "Buffer object 5 is being copied/moved from VIDEO memory to HOST memory.");
    EXPECT_EQ(glDebugPerformanceWarningCount(), 1u);
    EXPECT_EQ(glDebugRecompileCount(), 4u);
    say(GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR,
        "a shadow sampler over a texture object (0) with a non-depth format");
    EXPECT_EQ(glDebugUndefinedBehaviourCount(), 1u);
    EXPECT_EQ(glDebugErrorCount(), 0u);

    resetGlDebugErrorCount(); // what this test raised on purpose is not the fixture's to report
    EXPECT_EQ(glDebugPerformanceWarningCount(), 0u);
    EXPECT_EQ(glDebugUndefinedBehaviourCount(), 0u);
    EXPECT_EQ(glDebugRecompileCount(), 0u);
}

} // namespace photopic::test
