#include "HostGlState.h"

#include <array>

namespace photopic::test {
namespace {

bool enabled(GLenum cap) {
    return glIsEnabled(cap) == GL_TRUE;
}

} // namespace

HostObjects::HostObjects() {
    glCreateTextures(GL_TEXTURE_2D, 1, &target);
    glTextureStorage2D(target, 1, GL_RGBA8, 8, 8);
    glCreateFramebuffers(1, &framebuffer);
    glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, target, 0);
    const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
    const char* source = "#version 450\nlayout(local_size_x = 1) in;\nvoid main() {}\n";
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    program = glCreateProgram();
    glAttachShader(program, shader);
    glLinkProgram(program);
    glDeleteShader(shader);
    glCreateVertexArrays(1, &vao);
    for (GLuint* t : {&texture0, &texture3, &image}) {
        glCreateTextures(GL_TEXTURE_2D, 1, t);
        glTextureStorage2D(*t, 1, GL_RGBA16F, 4, 4);
    }
    for (GLuint* b : {&ssbo, &ubo, &array}) {
        glCreateBuffers(1, b);
        glNamedBufferStorage(*b, 1024, nullptr, 0);
    }
    glCreateSamplers(1, &sampler);
}
HostObjects::~HostObjects() {
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteProgram(program);
    glDeleteVertexArrays(1, &vao);
    for (GLuint t : {target, texture0, texture3, image}) {
        glDeleteTextures(1, &t);
    }
    for (GLuint b : {ssbo, ubo, array}) {
        glDeleteBuffers(1, &b);
    }
    glDeleteSamplers(1, &sampler);
}

void HostObjects::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(1, 2, 3, 4);
    glScissor(2, 3, 4, 5);
    glUseProgram(program);
    glBindVertexArray(vao);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture0);
    glBindSampler(0, sampler);
    glActiveTexture(GL_TEXTURE3);
    glBindTexture(GL_TEXTURE_2D, texture3);
    glBindImageTexture(0, image, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA16F);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, ssbo);
    glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 1, ssbo, 256, 512);
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, ubo);
    glBindBuffer(GL_ARRAY_BUFFER, array);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, ssbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
}

std::vector<std::string> HostObjects::changedBindings() const {
    std::vector<std::string> changed;
    auto expect = [&](const char* what, GLint value, GLint wanted) {
        if (value != wanted) {
            changed.push_back(std::string(what) + " is " + std::to_string(value) + ", the host left " +
                              std::to_string(wanted));
        }
    };
    auto get = [](GLenum name) {
        GLint v = 0;
        glGetIntegerv(name, &v);
        return v;
    };
    auto getAt = [](GLenum name, GLuint index) {
        GLint v = 0;
        glGetIntegeri_v(name, index, &v);
        return v;
    };
    expect("draw framebuffer", get(GL_DRAW_FRAMEBUFFER_BINDING), GLint(framebuffer));
    expect("read framebuffer", get(GL_READ_FRAMEBUFFER_BINDING), GLint(framebuffer));
    std::array<GLint, 4> viewport{}, scissor{};
    glGetIntegerv(GL_VIEWPORT, viewport.data());
    glGetIntegerv(GL_SCISSOR_BOX, scissor.data());
    expect("viewport", viewport == std::array<GLint, 4>{1, 2, 3, 4}, 1);
    expect("scissor box", scissor == std::array<GLint, 4>{2, 3, 4, 5}, 1);
    expect("program", get(GL_CURRENT_PROGRAM), GLint(program));
    expect("vertex array", get(GL_VERTEX_ARRAY_BINDING), GLint(vao));
    expect("active texture", get(GL_ACTIVE_TEXTURE), GL_TEXTURE3);
    expect("texture on unit 3", get(GL_TEXTURE_BINDING_2D), GLint(texture3));
    glActiveTexture(GL_TEXTURE0);
    expect("texture on unit 0", get(GL_TEXTURE_BINDING_2D), GLint(texture0));
    expect("sampler on unit 0", get(GL_SAMPLER_BINDING), GLint(sampler));
    glActiveTexture(GL_TEXTURE3);
    expect("image unit 0", getAt(GL_IMAGE_BINDING_NAME, 0), GLint(image));
    expect("image unit 0 format", getAt(GL_IMAGE_BINDING_FORMAT, 0), GL_RGBA16F);
    expect("storage buffer 0", getAt(GL_SHADER_STORAGE_BUFFER_BINDING, 0), GLint(ssbo));
    expect("storage buffer 1", getAt(GL_SHADER_STORAGE_BUFFER_BINDING, 1), GLint(ssbo));
    GLint64 start = 0, size = 0;
    glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_START, 1, &start);
    glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_SIZE, 1, &size);
    expect("storage buffer 1 range", start == 256 && size == 512, 1);
    expect("storage buffer 2", getAt(GL_SHADER_STORAGE_BUFFER_BINDING, 2), 0);
    expect("uniform buffer 0", getAt(GL_UNIFORM_BUFFER_BINDING, 0), GLint(ubo));
    expect("uniform buffer 1", getAt(GL_UNIFORM_BUFFER_BINDING, 1), 0);
    expect("generic storage buffer", get(GL_SHADER_STORAGE_BUFFER_BINDING), GLint(ssbo));
    expect("array buffer", get(GL_ARRAY_BUFFER_BINDING), GLint(array));
    expect("pack alignment", get(GL_PACK_ALIGNMENT), 1);
    expect("unpack alignment", get(GL_UNPACK_ALIGNMENT), 1);
    return changed;
}

void defaultState() {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glUseProgram(0);
    glBindVertexArray(0);
    glActiveTexture(GL_TEXTURE0);
    for (GLuint unit = 0; unit < 8; ++unit) {
        glBindTextureUnit(unit, 0);
        glBindSampler(unit, 0);
        glBindImageTexture(unit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R8);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, unit, 0);
        glBindBufferBase(GL_UNIFORM_BUFFER, unit, 0);
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    for (GLenum cap : {GL_SCISSOR_TEST, GL_CULL_FACE, GL_RASTERIZER_DISCARD, GL_FRAMEBUFFER_SRGB, GL_BLEND,
                       GL_DEPTH_TEST, GL_STENCIL_TEST, GL_COLOR_LOGIC_OP}) {
        glDisable(cap);
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    glDepthFunc(GL_LESS);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glBlendFunc(GL_ONE, GL_ZERO);
    glLogicOp(GL_COPY);
}

const std::vector<HostState>& hostStates() {
    static const std::vector<HostState> kStates = {
        {"scissor test", [] { glEnable(GL_SCISSOR_TEST); }, [] { return enabled(GL_SCISSOR_TEST); }},
        {"colour mask off", [] { glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE); },
         [] {
             std::array<GLboolean, 4> m{};
             glGetBooleanv(GL_COLOR_WRITEMASK, m.data());
             return m == std::array<GLboolean, 4>{GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE};
         }},
        {"clockwise front faces, culling both",
         [] {
             glFrontFace(GL_CW);
             glCullFace(GL_FRONT_AND_BACK);
             glEnable(GL_CULL_FACE);
         },
         [] {
             GLint front = 0, cull = 0;
             glGetIntegerv(GL_FRONT_FACE, &front);
             glGetIntegerv(GL_CULL_FACE_MODE, &cull);
             return enabled(GL_CULL_FACE) && front == GL_CW && cull == GL_FRONT_AND_BACK;
         }},
        {"polygon mode line", [] { glPolygonMode(GL_FRONT_AND_BACK, GL_LINE); },
         [] {
             std::array<GLint, 2> mode{};
             glGetIntegerv(GL_POLYGON_MODE, mode.data());
             return mode[0] == GL_LINE;
         }},
        {"rasterizer discard", [] { glEnable(GL_RASTERIZER_DISCARD); },
         [] { return enabled(GL_RASTERIZER_DISCARD); }},
        {"sRGB framebuffer writes", [] { glEnable(GL_FRAMEBUFFER_SRGB); },
         [] { return enabled(GL_FRAMEBUFFER_SRGB); }},
        {"blending that keeps the destination",
         [] {
             glEnable(GL_BLEND);
             glBlendFunc(GL_ZERO, GL_ONE);
         },
         [] { return enabled(GL_BLEND); }},
        {"depth test that never passes",
         [] {
             glEnable(GL_DEPTH_TEST);
             glDepthFunc(GL_NEVER);
         },
         [] { return enabled(GL_DEPTH_TEST); }},
        {"stencil test that never passes",
         [] {
             glEnable(GL_STENCIL_TEST);
             glStencilFunc(GL_NEVER, 0, 0xff);
         },
         [] { return enabled(GL_STENCIL_TEST); }},
        {"logic op clear",
         [] {
             glEnable(GL_COLOR_LOGIC_OP);
             glLogicOp(GL_CLEAR);
         },
         [] { return enabled(GL_COLOR_LOGIC_OP); }},
    };
    return kStates;
}

} // namespace photopic::test
