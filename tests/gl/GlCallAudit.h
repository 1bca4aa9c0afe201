#pragma once
// Watches the GL calls made while it exists and checks, at each, the rules behind NVIDIA's performance and
// undefined-behaviour messages, which Mesa's software renderer never raises, so a test catches them here:
// - a CPU read straight from a buffer's storage (glGet(Named)BufferSubData, or a map for reading that is not
//   a persistent mapping of a dedicated read-back buffer) makes the driver move a GPU-written buffer to host
//   memory;
// - a clear with a graphics program current: the driver checks that program against the clear's state and
//   recompiles its vertex shader when the state differs from the one it was drawn with;
// - draws of one program with different vertex-fetch states (enabled attribute arrays, their sizes and
//   types): the vertex shader is recompiled for each;
// - a shadow sampler whose unit holds no depth texture with comparison on (or a plain sampler reading a
//   depth texture with comparison on): undefined behaviour;
// - a draw whose program declares a uniform or storage block with no buffer bound, or one smaller than the
//   block: undefined behaviour;
// - a dispatch (through photopic::dispatch) whose program declares a sampler or image that was not bound
//   through its slot since the last dispatch: the pass reads whatever an earlier pass left on that unit.
//
// It replaces libepoxy's dispatch pointers (every GL call of the process, the library's included, goes
// through them) with hooks that check and then call the driver's functions (from eglGetProcAddress), and
// puts them back when it goes. One at a time, on the thread that owns an EGL context.

#include "gl/Objects.h"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace photopic::test {

class GlCallAudit {
public:
    GlCallAudit();
    ~GlCallAudit();
    GlCallAudit(const GlCallAudit&) = delete;
    GlCallAudit& operator=(const GlCallAudit&) = delete;

    /// CPU reads straight from a buffer's storage.
    [[nodiscard]] int directBufferReads() const { return mDirectBufferReads; }
    /// Every rule broken, one line each, naming the call, the program (its label) and what was wrong.
    [[nodiscard]] const std::vector<std::string>& problems() const { return mProblems; }
    /// For each program drawn (by label), the vertex-fetch states its draws saw.
    [[nodiscard]] const std::map<std::string, std::set<std::string>>& fetchStates() const {
        return mFetchStates;
    }
    [[nodiscard]] int draws() const { return mDraws; }
    [[nodiscard]] int dispatches() const { return mDispatches; }
    [[nodiscard]] int clears() const { return mClears; }
    /// Buffer clears (glClearNamedBufferData) and GPU-side buffer copies (glCopyNamedBufferSubData).
    [[nodiscard]] int bufferClears() const { return mBufferClears; }
    [[nodiscard]] int bufferCopies() const { return mBufferCopies; }

    // Called by the hooks.
    void onBufferRead(const char* call, GLuint buffer);
    void onClear(const char* call);
    void onDraw(const char* call);
    void onDispatch(const char* call);
    void onBufferClear() { ++mBufferClears; }
    void onBufferCopy() { ++mBufferCopies; }

private:
    void checkSamplers(GLuint program, const char* call);
    void checkBlocks(GLuint program, const char* call);
    [[nodiscard]] bool isGraphics(GLuint program) const;

    int mDirectBufferReads = 0;
    int mDraws = 0;
    int mDispatches = 0;
    int mClears = 0;
    int mBufferClears = 0;
    int mBufferCopies = 0;
    std::vector<std::string> mProblems;
    std::map<std::string, std::set<std::string>> mFetchStates;
    std::set<GLuint> mDrawn;
    BindingProblemHandler mOuterHandler; ///< the binding-problem handler before this audit's
};

} // namespace photopic::test
