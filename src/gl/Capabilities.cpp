#include "gl/Capabilities.h"

#include "core/Environment.h"
#include "core/Log.h"
#include "gl/Gl.h"

#include <string_view>

namespace photopic {

namespace {

/// Asks the driver, then checks for real: a 4x4 attachment must make a complete framebuffer.
bool renderable(GLenum format) {
    GLint supported = GL_FALSE;
    glGetInternalformativ(GL_TEXTURE_2D, format, GL_COLOR_RENDERABLE, 1, &supported);
    if (supported != GL_TRUE) {
        return false;
    }
    GLuint tex = 0, fbo = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &tex);
    glTextureStorage2D(tex, 1, format, 4, 4);
    glCreateFramebuffers(1, &fbo);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, tex, 0);
    const bool complete = glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(1, &tex);
    return complete;
}

} // namespace

Capabilities detectCapabilities(bool forceLdr) {
    Capabilities caps;
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    caps.computeShaders = major > 4 || (major == 4 && minor >= 3);
    GLint timerBits = 0;
    glGetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &timerBits);
    caps.timerQueries = timerBits > 0;
    caps.rgba16fRenderable = renderable(GL_RGBA16F);
    caps.rgba32fRenderable = renderable(GL_RGBA32F);

    const bool envForce = environmentSwitch("PHOTOPIC_FORCE_LDR");
    if (forceLdr || envForce) {
        caps.path = ColorPath::Ldr;
        caps.pathReason = envForce ? "LDR forced by PHOTOPIC_FORCE_LDR" : "LDR forced by the caller";
    } else if (caps.rgba16fRenderable && caps.computeShaders) {
        caps.path = ColorPath::Hdr;
        caps.pathReason = "RGBA16F is colour-renderable";
    } else {
        caps.path = ColorPath::Ldr;
        caps.pathReason = caps.rgba16fRenderable ? "no compute shaders" : "RGBA16F is not colour-renderable";
    }
    if (caps.path == ColorPath::Ldr) {
        warnOnce("ldr-path",
                 "running the LDR (RGBA8) path: " + caps.pathReason +
                     "; HDR effects (bloom, metering) are off and values above 1 clip before tone mapping");
    }
    return caps;
}

bool isSoftwareRenderer() {
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const std::string_view renderer = name ? name : "";
    return renderer.find("llvmpipe") != std::string_view::npos ||
           renderer.find("softpipe") != std::string_view::npos ||
           renderer.find("SwiftShader") != std::string_view::npos;
}

} // namespace photopic
