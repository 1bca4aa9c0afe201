// The bench's `--queue-ahead` busy work (QueueAhead.h).
#include "QueueAhead.h"

#include "gl/ShaderLibrary.h"

#include <algorithm>
#include <chrono>

namespace photopic::cli {

QueueAhead::QueueAhead()
    : mProgram(makeComputeProgram("gl/gpu_busy.comp.glsl"))
    , mSink({.size = kInvocations * sizeof(float), .flags = 0, .debugName = "bench busy sink"})
    , mEnd(GL_TIMESTAMP) {}

void QueueAhead::calibrate(double ms) {
    const double target = std::min(ms, kMaxMs);
    for (;;) {
        glFinish();
        const auto start = std::chrono::steady_clock::now();
        submit();
        glFinish();
        mBusyMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (mBusyMs >= target || mGroups >= kMaxGroups) {
            return;
        }
        const double scale = std::clamp(mBusyMs > 0 ? 1.25 * target / mBusyMs : 16.0, 1.1, 16.0);
        if (mIterations < kMaxIterations) {
            mIterations = GLuint(std::min(double(mIterations) * scale, double(kMaxIterations)));
        } else {
            mGroups = GLuint(std::min(double(mGroups) * scale, double(kMaxGroups)));
        }
    }
}

void QueueAhead::submit() {
    mProgram.use();
    glProgramUniform1ui(mProgram.id(), 0, mIterations);
    glProgramUniform1f(mProgram.id(), 1, -1.0f);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, mSink.id());
    glDispatchCompute(mGroups, 1, 1);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    glQueryCounter(mEnd.id(), GL_TIMESTAMP);
    glFlush();
}

void QueueAhead::settle() {
    GLuint64 end = 0;
    glGetQueryObjectui64v(mEnd.id(), GL_QUERY_RESULT, &end);
    mHeld += mSubmittedAt >= 0 && GLuint64(mSubmittedAt) < end ? 1 : 0;
    ++mTimed;
}

} // namespace photopic::cli
