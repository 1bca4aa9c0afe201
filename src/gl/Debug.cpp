#include "gl/Debug.h"

#include "core/Log.h"
#include "gl/Gl.h"

#include <atomic>
#include <string_view>

namespace photopic {

namespace {

std::atomic<std::uint64_t> gErrors{0};
std::atomic<std::uint64_t> gPerformanceWarnings{0};
std::atomic<std::uint64_t> gUndefinedBehaviour{0};
std::atomic<std::uint64_t> gRecompiles{0};

bool isRecompile(std::string_view text) {
    return text.find("recompiled based on GL state") != std::string_view::npos;
}

void GLAPIENTRY onMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                          const GLchar* message, const void*) {
    (void)source;
    if (type == GL_DEBUG_TYPE_PUSH_GROUP || type == GL_DEBUG_TYPE_POP_GROUP) {
        return;
    }
    const std::string_view text(message,
                                length < 0 ? std::char_traits<char>::length(message) : std::size_t(length));
    const bool error = type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH;
    const bool notable = severity == GL_DEBUG_SEVERITY_MEDIUM || severity == GL_DEBUG_SEVERITY_HIGH;
    if (type == GL_DEBUG_TYPE_PERFORMANCE && notable) {
        ++(isRecompile(text) ? gRecompiles : gPerformanceWarnings);
    }
    if (type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR && notable) {
        ++gUndefinedBehaviour;
    }
    if (error) {
        ++gErrors;
        logError("GL error (id {}): {}", id, text);
    } else if (severity == GL_DEBUG_SEVERITY_MEDIUM) {
        logWarning("GL (id {}): {}", id, text);
    } else {
        logMessage(LogLevel::Debug, std::string("GL: ").append(text));
    }
}

} // namespace

void installDebugOutput() {
    GLint flags = 0;
    glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onMessage, nullptr);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    if (!(flags & GL_CONTEXT_FLAG_DEBUG_BIT)) {
        logMessage(LogLevel::Debug, "GL context has no debug flag; debug output may be partial");
    }
}

std::uint64_t glDebugErrorCount() {
    return gErrors.load();
}
std::uint64_t glDebugPerformanceWarningCount() {
    return gPerformanceWarnings.load();
}
std::uint64_t glDebugRecompileCount() {
    return gRecompiles.load();
}

std::uint64_t glDebugUndefinedBehaviourCount() {
    return gUndefinedBehaviour.load();
}
void resetGlDebugErrorCount() {
    gErrors = 0;
    gPerformanceWarnings = 0;
    gUndefinedBehaviour = 0;
    gRecompiles = 0;
}

} // namespace photopic
