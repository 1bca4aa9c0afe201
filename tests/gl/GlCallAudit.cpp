#include "GlCallAudit.h"

#include <epoxy/egl.h>
#include <fmt/format.h>

#include <array>
#include <stdexcept>

namespace photopic::test {

namespace {

GlCallAudit* gAudit = nullptr;

// A hook per audited entry point: `Before` runs (when an audit is active), then the driver's function.
// gSaved_ keeps libepoxy's pointer to put back; gReal_ is the driver's function, from eglGetProcAddress:
// libepoxy's pointer may still be its resolving stub, which calls through the dispatch pointer, the hook.
#define PHOTOPIC_AUDIT_HOOK(Ret, name, Params, Args, Before)                                                 \
    decltype(epoxy_##name) gSaved_##name = nullptr;                                                          \
    decltype(epoxy_##name) gReal_##name = nullptr;                                                           \
    Ret EPOXY_CALLSPEC hook_##name Params {                                                                  \
        if (gAudit != nullptr) {                                                                             \
            Before;                                                                                          \
        }                                                                                                    \
        return gReal_##name Args;                                                                            \
    }

bool readsPlainly(GLbitfield access) {
    return (access & GL_MAP_READ_BIT) != 0 && (access & GL_MAP_PERSISTENT_BIT) == 0;
}
bool readsPlainlyWhole(GLenum access) {
    return access == GL_READ_ONLY || access == GL_READ_WRITE;
}
GLuint bufferOn(GLenum target) {
    GLenum binding = 0;
    switch (target) {
    case GL_SHADER_STORAGE_BUFFER:
        binding = GL_SHADER_STORAGE_BUFFER_BINDING;
        break;
    case GL_UNIFORM_BUFFER:
        binding = GL_UNIFORM_BUFFER_BINDING;
        break;
    case GL_COPY_READ_BUFFER:
        binding = GL_COPY_READ_BUFFER_BINDING;
        break;
    case GL_PIXEL_PACK_BUFFER:
        binding = GL_PIXEL_PACK_BUFFER_BINDING;
        break;
    case GL_ARRAY_BUFFER:
        binding = GL_ARRAY_BUFFER_BINDING;
        break;
    default:
        return 0;
    }
    GLint id = 0;
    glGetIntegerv(binding, &id);
    return GLuint(id);
}

PHOTOPIC_AUDIT_HOOK(void, glGetNamedBufferSubData, (GLuint b, GLintptr o, GLsizeiptr s, void* d),
                    (b, o, s, d), gAudit->onBufferRead("glGetNamedBufferSubData", b))
PHOTOPIC_AUDIT_HOOK(void, glGetBufferSubData, (GLenum t, GLintptr o, GLsizeiptr s, void* d), (t, o, s, d),
                    gAudit->onBufferRead("glGetBufferSubData", bufferOn(t)))
PHOTOPIC_AUDIT_HOOK(void*, glMapNamedBufferRange, (GLuint b, GLintptr o, GLsizeiptr s, GLbitfield a),
                    (b, o, s, a), if (readsPlainly(a)) gAudit->onBufferRead("glMapNamedBufferRange", b))
PHOTOPIC_AUDIT_HOOK(void*, glMapBufferRange, (GLenum t, GLintptr o, GLsizeiptr s, GLbitfield a), (t, o, s, a),
                    if (readsPlainly(a)) gAudit->onBufferRead("glMapBufferRange", bufferOn(t)))
PHOTOPIC_AUDIT_HOOK(void*, glMapNamedBuffer, (GLuint b, GLenum a), (b, a),
                    if (readsPlainlyWhole(a)) gAudit->onBufferRead("glMapNamedBuffer", b))
PHOTOPIC_AUDIT_HOOK(void*, glMapBuffer, (GLenum t, GLenum a), (t, a),
                    if (readsPlainlyWhole(a)) gAudit->onBufferRead("glMapBuffer", bufferOn(t)))

PHOTOPIC_AUDIT_HOOK(void, glClear, (GLbitfield m), (m), gAudit->onClear("glClear"))
PHOTOPIC_AUDIT_HOOK(void, glClearNamedFramebufferfv, (GLuint f, GLenum b, GLint i, const GLfloat* v),
                    (f, b, i, v), gAudit->onClear("glClearNamedFramebufferfv"))
PHOTOPIC_AUDIT_HOOK(void, glClearNamedFramebufferiv, (GLuint f, GLenum b, GLint i, const GLint* v),
                    (f, b, i, v), gAudit->onClear("glClearNamedFramebufferiv"))
PHOTOPIC_AUDIT_HOOK(void, glClearNamedFramebufferuiv, (GLuint f, GLenum b, GLint i, const GLuint* v),
                    (f, b, i, v), gAudit->onClear("glClearNamedFramebufferuiv"))
PHOTOPIC_AUDIT_HOOK(void, glClearNamedFramebufferfi, (GLuint f, GLenum b, GLint i, GLfloat d, GLint s),
                    (f, b, i, d, s), gAudit->onClear("glClearNamedFramebufferfi"))
PHOTOPIC_AUDIT_HOOK(void, glClearBufferfv, (GLenum b, GLint i, const GLfloat* v), (b, i, v),
                    gAudit->onClear("glClearBufferfv"))
PHOTOPIC_AUDIT_HOOK(void, glClearBufferiv, (GLenum b, GLint i, const GLint* v), (b, i, v),
                    gAudit->onClear("glClearBufferiv"))
PHOTOPIC_AUDIT_HOOK(void, glClearBufferuiv, (GLenum b, GLint i, const GLuint* v), (b, i, v),
                    gAudit->onClear("glClearBufferuiv"))
PHOTOPIC_AUDIT_HOOK(void, glClearBufferfi, (GLenum b, GLint i, GLfloat d, GLint s), (b, i, d, s),
                    gAudit->onClear("glClearBufferfi"))

PHOTOPIC_AUDIT_HOOK(void, glDrawArrays, (GLenum m, GLint f, GLsizei c), (m, f, c),
                    gAudit->onDraw("glDrawArrays"))
PHOTOPIC_AUDIT_HOOK(void, glDrawArraysInstanced, (GLenum m, GLint f, GLsizei c, GLsizei n), (m, f, c, n),
                    gAudit->onDraw("glDrawArraysInstanced"))
PHOTOPIC_AUDIT_HOOK(void, glDrawElements, (GLenum m, GLsizei c, GLenum t, const void* i), (m, c, t, i),
                    gAudit->onDraw("glDrawElements"))
PHOTOPIC_AUDIT_HOOK(void, glDrawElementsBaseVertex, (GLenum m, GLsizei c, GLenum t, const void* i, GLint b),
                    (m, c, t, i, b), gAudit->onDraw("glDrawElementsBaseVertex"))
PHOTOPIC_AUDIT_HOOK(void, glDrawElementsInstanced, (GLenum m, GLsizei c, GLenum t, const void* i, GLsizei n),
                    (m, c, t, i, n), gAudit->onDraw("glDrawElementsInstanced"))
PHOTOPIC_AUDIT_HOOK(void, glDrawElementsInstancedBaseVertex,
                    (GLenum m, GLsizei c, GLenum t, const void* i, GLsizei n, GLint b), (m, c, t, i, n, b),
                    gAudit->onDraw("glDrawElementsInstancedBaseVertex"))

PHOTOPIC_AUDIT_HOOK(void, glDispatchCompute, (GLuint x, GLuint y, GLuint z), (x, y, z),
                    gAudit->onDispatch("glDispatchCompute"))
PHOTOPIC_AUDIT_HOOK(void, glDispatchComputeIndirect, (GLintptr i), (i),
                    gAudit->onDispatch("glDispatchComputeIndirect"))

PHOTOPIC_AUDIT_HOOK(void, glClearNamedBufferData, (GLuint b, GLenum f, GLenum fm, GLenum t, const void* d),
                    (b, f, fm, t, d), gAudit->onBufferClear())
PHOTOPIC_AUDIT_HOOK(void, glCopyNamedBufferSubData,
                    (GLuint r, GLuint w, GLintptr ro, GLintptr wo, GLsizeiptr s), (r, w, ro, wo, s),
                    gAudit->onBufferCopy())

#undef PHOTOPIC_AUDIT_HOOK

#define PHOTOPIC_AUDITED(X)                                                                                  \
    X(glGetNamedBufferSubData)                                                                               \
    X(glGetBufferSubData)                                                                                    \
    X(glMapNamedBufferRange)                                                                                 \
    X(glMapBufferRange)                                                                                      \
    X(glMapNamedBuffer)                                                                                      \
    X(glMapBuffer)                                                                                           \
    X(glClear)                                                                                               \
    X(glClearNamedFramebufferfv)                                                                             \
    X(glClearNamedFramebufferiv)                                                                             \
    X(glClearNamedFramebufferuiv)                                                                            \
    X(glClearNamedFramebufferfi)                                                                             \
    X(glClearBufferfv)                                                                                       \
    X(glClearBufferiv)                                                                                       \
    X(glClearBufferuiv)                                                                                      \
    X(glClearBufferfi)                                                                                       \
    X(glDrawArrays)                                                                                          \
    X(glDrawArraysInstanced)                                                                                 \
    X(glDrawElements)                                                                                        \
    X(glDrawElementsBaseVertex)                                                                              \
    X(glDrawElementsInstanced)                                                                               \
    X(glDrawElementsInstancedBaseVertex)                                                                     \
    X(glDispatchCompute)                                                                                     \
    X(glDispatchComputeIndirect)                                                                             \
    X(glClearNamedBufferData)                                                                                \
    X(glCopyNamedBufferSubData)

std::string label(GLenum kind, GLuint id) {
    std::array<char, 256> text{};
    GLsizei length = 0;
    glGetObjectLabel(kind, id, GLsizei(text.size()), &length, text.data());
    const std::string name =
        length > 0 ? std::string(text.data(), std::size_t(length)) : std::string("unlabelled");
    return fmt::format("'{}' ({})", name, id);
}

GLuint currentProgram() {
    GLint program = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    return GLuint(program);
}

/// The enabled attribute arrays of the bound vertex array and their formats.
std::string fetchState() {
    GLint vao = 0;
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao);
    if (vao == 0) {
        return "no vertex array";
    }
    GLint count = 0;
    glGetIntegerv(GL_MAX_VERTEX_ATTRIBS, &count);
    std::string state;
    for (GLuint a = 0; a < GLuint(count); ++a) {
        GLint enabled = 0;
        glGetVertexArrayIndexediv(GLuint(vao), a, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &enabled);
        if (enabled == 0) {
            continue;
        }
        GLint size = 0, type = 0, normalized = 0, integer = 0;
        glGetVertexArrayIndexediv(GLuint(vao), a, GL_VERTEX_ATTRIB_ARRAY_SIZE, &size);
        glGetVertexArrayIndexediv(GLuint(vao), a, GL_VERTEX_ATTRIB_ARRAY_TYPE, &type);
        glGetVertexArrayIndexediv(GLuint(vao), a, GL_VERTEX_ATTRIB_ARRAY_NORMALIZED, &normalized);
        glGetVertexArrayIndexediv(GLuint(vao), a, GL_VERTEX_ATTRIB_ARRAY_INTEGER, &integer);
        state += fmt::format("{}:{}x{:#x}{}{} ", a, size, type, normalized != 0 ? " normalized" : "",
                             integer != 0 ? " integer" : "");
    }
    return state.empty() ? "no arrays" : state;
}

struct SamplerKind {
    GLenum binding = 0; ///< the texture-binding query of its target; 0: not a sampler the audit reads
    bool shadow = false;
    bool cube = false;
};

SamplerKind samplerKind(GLenum type) {
    switch (type) {
    case GL_SAMPLER_2D:
    case GL_INT_SAMPLER_2D:
    case GL_UNSIGNED_INT_SAMPLER_2D:
        return {GL_TEXTURE_BINDING_2D, false, false};
    case GL_SAMPLER_2D_SHADOW:
        return {GL_TEXTURE_BINDING_2D, true, false};
    case GL_SAMPLER_2D_ARRAY:
    case GL_INT_SAMPLER_2D_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_2D_ARRAY:
        return {GL_TEXTURE_BINDING_2D_ARRAY, false, false};
    case GL_SAMPLER_2D_ARRAY_SHADOW:
        return {GL_TEXTURE_BINDING_2D_ARRAY, true, false};
    case GL_SAMPLER_3D:
    case GL_INT_SAMPLER_3D:
    case GL_UNSIGNED_INT_SAMPLER_3D:
        return {GL_TEXTURE_BINDING_3D, false, false};
    case GL_SAMPLER_CUBE:
    case GL_INT_SAMPLER_CUBE:
    case GL_UNSIGNED_INT_SAMPLER_CUBE:
        return {GL_TEXTURE_BINDING_CUBE_MAP, false, true};
    case GL_SAMPLER_CUBE_SHADOW:
        return {GL_TEXTURE_BINDING_CUBE_MAP, true, true};
    default:
        return {};
    }
}

/// The texture of `binding`'s target and the sampler object on texture unit `unit`.
std::pair<GLuint, GLuint> boundOn(GLint unit, GLenum binding) {
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    GLint texture = 0, sampler = 0;
    glGetIntegerv(binding, &texture);
    glGetIntegerv(GL_SAMPLER_BINDING, &sampler);
    glActiveTexture(GLenum(active));
    return {GLuint(texture), GLuint(sampler)};
}

bool compares(GLuint texture, GLuint sampler) {
    GLint mode = 0;
    if (sampler != 0) {
        glGetSamplerParameteriv(sampler, GL_TEXTURE_COMPARE_MODE, &mode);
    } else {
        glGetTextureParameteriv(texture, GL_TEXTURE_COMPARE_MODE, &mode);
    }
    return mode == GL_COMPARE_REF_TO_TEXTURE;
}

bool hasDepth(GLuint texture) {
    GLint bits = 0;
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_DEPTH_SIZE, &bits);
    return bits > 0;
}

} // namespace

GlCallAudit::GlCallAudit() {
    if (gAudit != nullptr) {
        throw std::logic_error("GlCallAudit: one audit at a time");
    }
    gAudit = this;
#define PHOTOPIC_RESOLVE(name)                                                                               \
    gReal_##name = reinterpret_cast<decltype(epoxy_##name)>(eglGetProcAddress(#name));                       \
    if (gReal_##name == nullptr) {                                                                           \
        gAudit = nullptr;                                                                                    \
        throw std::runtime_error("GlCallAudit: eglGetProcAddress has no " #name);                            \
    }
    PHOTOPIC_AUDITED(PHOTOPIC_RESOLVE)
#undef PHOTOPIC_RESOLVE
#define PHOTOPIC_INSTALL(name)                                                                               \
    gSaved_##name = epoxy_##name;                                                                            \
    epoxy_##name = &hook_##name;
    PHOTOPIC_AUDITED(PHOTOPIC_INSTALL)
#undef PHOTOPIC_INSTALL
    mOuterHandler =
        setBindingProblemHandler([this](const std::string& problem) { mProblems.push_back(problem); });
}

GlCallAudit::~GlCallAudit() {
    setBindingProblemHandler(std::move(mOuterHandler));
#define PHOTOPIC_REMOVE(name) epoxy_##name = gSaved_##name;
    PHOTOPIC_AUDITED(PHOTOPIC_REMOVE)
#undef PHOTOPIC_REMOVE
    gAudit = nullptr;
}

bool GlCallAudit::isGraphics(GLuint program) const {
    if (mDrawn.count(program) != 0) {
        return true;
    }
    // A compute program has no outputs; a graphics program's fragment outputs are its outputs.
    GLint outputs = 0;
    glGetProgramInterfaceiv(program, GL_PROGRAM_OUTPUT, GL_ACTIVE_RESOURCES, &outputs);
    return outputs > 0;
}

void GlCallAudit::onBufferRead(const char* call, GLuint buffer) {
    ++mDirectBufferReads;
    mProblems.push_back(fmt::format("{}: the CPU reads buffer {} straight from its storage", call,
                                    buffer != 0 ? label(GL_BUFFER, buffer) : std::string("(unknown)")));
}

void GlCallAudit::onClear(const char* call) {
    ++mClears;
    const GLuint program = currentProgram();
    if (program != 0 && isGraphics(program)) {
        mProblems.push_back(
            fmt::format("{}: the graphics program {} is current", call, label(GL_PROGRAM, program)));
    }
}

void GlCallAudit::onDraw(const char* call) {
    ++mDraws;
    const GLuint program = currentProgram();
    if (program == 0) {
        mProblems.push_back(fmt::format("{}: no program", call));
        return;
    }
    mDrawn.insert(program);
    mFetchStates[label(GL_PROGRAM, program)].insert(fetchState());
    checkSamplers(program, call);
    checkBlocks(program, call);
}

void GlCallAudit::onDispatch(const char* call) {
    ++mDispatches;
    if (const GLuint program = currentProgram(); program != 0) {
        checkSamplers(program, call);
    }
}

void GlCallAudit::checkSamplers(GLuint program, const char* call) {
    GLint count = 0;
    glGetProgramInterfaceiv(program, GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
    for (GLint i = 0; i < count; ++i) {
        const std::array<GLenum, 3> props = {GL_TYPE, GL_LOCATION, GL_ARRAY_SIZE};
        std::array<GLint, 3> v{};
        glGetProgramResourceiv(program, GL_UNIFORM, GLuint(i), GLsizei(props.size()), props.data(),
                               GLsizei(v.size()), nullptr, v.data());
        const SamplerKind kind = samplerKind(GLenum(v[0]));
        if (kind.binding == 0 || v[1] < 0) {
            continue;
        }
        std::array<char, 128> name{};
        glGetProgramResourceName(program, GL_UNIFORM, GLuint(i), GLsizei(name.size()), nullptr, name.data());
        for (GLint k = 0; k < v[2]; ++k) {
            GLint unit = 0;
            glGetUniformiv(program, v[1] + k, &unit);
            const auto [texture, sampler] = boundOn(unit, kind.binding);
            const auto report = [&](std::string_view what) {
                mProblems.push_back(fmt::format("{}: program {} reads {} on unit {}: {}", call,
                                                label(GL_PROGRAM, program), name.data(), unit, what));
            };
            if (kind.shadow) {
                if (texture == 0) {
                    report("a shadow sampler, and the unit holds no texture");
                } else if (!kind.cube && !hasDepth(texture)) {
                    report("a shadow sampler, and the texture has no depth format");
                } else if (!compares(texture, sampler)) {
                    report("a shadow sampler, and depth comparison is off");
                }
            } else if (texture != 0 && !kind.cube && hasDepth(texture) && compares(texture, sampler)) {
                report("a plain sampler, and the depth texture has comparison on");
            }
        }
    }
}

void GlCallAudit::checkBlocks(GLuint program, const char* call) {
    const struct {
        GLenum interface;
        GLenum binding, start, size;
        const char* kind;
    } blocks[] = {{GL_UNIFORM_BLOCK, GL_UNIFORM_BUFFER_BINDING, GL_UNIFORM_BUFFER_START,
                   GL_UNIFORM_BUFFER_SIZE, "uniform block"},
                  {GL_SHADER_STORAGE_BLOCK, GL_SHADER_STORAGE_BUFFER_BINDING, GL_SHADER_STORAGE_BUFFER_START,
                   GL_SHADER_STORAGE_BUFFER_SIZE, "storage block"}};
    for (const auto& b : blocks) {
        GLint count = 0;
        glGetProgramInterfaceiv(program, b.interface, GL_ACTIVE_RESOURCES, &count);
        for (GLint i = 0; i < count; ++i) {
            const std::array<GLenum, 2> props = {GL_BUFFER_BINDING, GL_BUFFER_DATA_SIZE};
            std::array<GLint, 2> v{};
            glGetProgramResourceiv(program, b.interface, GLuint(i), GLsizei(props.size()), props.data(),
                                   GLsizei(v.size()), nullptr, v.data());
            std::array<char, 128> name{};
            glGetProgramResourceName(program, b.interface, GLuint(i), GLsizei(name.size()), nullptr,
                                     name.data());
            GLint buffer = 0;
            glGetIntegeri_v(b.binding, GLuint(v[0]), &buffer);
            GLint64 start = 0, size = 0;
            if (buffer != 0) {
                glGetInteger64i_v(b.start, GLuint(v[0]), &start);
                glGetInteger64i_v(b.size, GLuint(v[0]), &size);
                if (size == 0) { // bound whole
                    glGetNamedBufferParameteri64v(GLuint(buffer), GL_BUFFER_SIZE, &size);
                    size -= start;
                }
            }
            if (buffer == 0 || size < v[1]) {
                mProblems.push_back(
                    fmt::format("{}: program {} reads {} {} (binding {}): {}", call,
                                label(GL_PROGRAM, program), b.kind, name.data(), v[0],
                                buffer == 0 ? std::string("no buffer is bound")
                                            : fmt::format("{} of its {} bytes are bound", size, v[1])));
            }
        }
    }
}

} // namespace photopic::test
