#pragma once
// GL test fixture: one headless context per test process (made in main), any GL debug error during a test
// fails it, and a test skips -- with the reason -- only when no context could be made. On NVIDIA's driver a
// performance warning fails the test too: it reports memory moved between the GPU and the host, shader
// recompiles and stalls, which a frame must never cause (other drivers' warnings are logged only: Mesa's
// software renderer reports its own fallbacks that say nothing of a GPU). A dispatch that finds a sampler or
// image its program declares not bound through the program's slot (gl/Objects.h checkBindings) fails the test
// too, unless a GlCallAudit collects it.

#include "gl/Context.h"
#include "gl/Debug.h"
#include "gl/Objects.h"
#include "gl/ShaderLibrary.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

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
        mBindingProblems.clear();
        mOuterBindingHandler = setBindingProblemHandler(
            [this](const std::string& problem) { mBindingProblems.push_back(problem); });
    }
    void TearDown() override {
        // A test that forces the renderer's choices (a pass's invocation shape, its shared-memory build) to
        // compare them leaves the next test the renderer's own, even after a failed assertion.
        forcePixelGroup(std::nullopt);
        forceSharedMemoryTiles(std::nullopt);
        if (glContext()) {
            setBindingProblemHandler(std::move(mOuterBindingHandler));
            EXPECT_TRUE(mBindingProblems.empty())
                << "a binding problem (a declared sampler or image unbound, or an image in another format): "
                << mBindingProblems.front();
            EXPECT_EQ(glDebugErrorCount(), 0u) << "GL debug errors were raised during the test (see log)";
            EXPECT_EQ(glDebugUndefinedBehaviourCount(), 0u)
                << "the driver reported undefined behaviour during the test (see log)";
            if (glContext()->info().vendor.find("NVIDIA") != std::string::npos) {
                EXPECT_EQ(glDebugPerformanceWarningCount(), 0u)
                    << "the driver raised performance warnings during the test (see log)";
            }
        }
    }

private:
    std::vector<std::string> mBindingProblems;
    BindingProblemHandler mOuterBindingHandler;
};

} // namespace photopic::test
