#pragma once
// GL test fixture: one headless context per test process (made in main), any GL debug error during a test
// fails it, and a test skips -- with the reason -- only when no context could be made.

#include "gl/Context.h"
#include "gl/Debug.h"

#include <gtest/gtest.h>

#include <string>

namespace photopic::test {

/// The process's context, or nullptr with `glUnavailableReason()` saying why.
HeadlessContext* glContext();
const std::string& glUnavailableReason();

class GlTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!glContext()) {
            GTEST_SKIP() << "no OpenGL 4.5 context: " << glUnavailableReason();
        }
        resetGlDebugErrorCount();
    }
    void TearDown() override {
        if (glContext()) {
            EXPECT_EQ(glDebugErrorCount(), 0u) << "GL debug errors were raised during the test (see log)";
        }
    }
};

} // namespace photopic::test
