#include "gl/ShaderLibrary.h"

#include "gl/Capabilities.h"

#include <fmt/format.h>

#include <set>
#include <sstream>
#include <stdexcept>

namespace photopic {

namespace {

std::string_view findSource(const std::string& name) {
    const auto& all = embeddedShaders();
    const auto it = all.find(name);
    return it == all.end() ? std::string_view{} : it->second;
}

std::string directoryOf(std::string_view name) {
    const auto slash = name.rfind('/');
    return slash == std::string_view::npos ? std::string{} : std::string(name.substr(0, slash + 1));
}

void expand(const std::string& name, std::set<std::string>& included, std::string& out, int depth) {
    if (depth > 16) {
        throw GlError("shader include depth over 16 at " + name);
    }
    if (!included.insert(name).second) {
        return;
    }
    const std::string_view source = findSource(name);
    if (source.data() == nullptr) {
        throw GlError("shader source not embedded: " + name);
    }
    std::istringstream lines{std::string(source)};
    std::string line;
    int lineNo = 0;
    while (std::getline(lines, line)) {
        ++lineNo;
        const auto first = line.find_first_not_of(" \t");
        if (first != std::string::npos && line.compare(first, 8, "#include") == 0) {
            const auto q1 = line.find('"', first);
            const auto q2 = q1 == std::string::npos ? q1 : line.find('"', q1 + 1);
            if (q2 == std::string::npos) {
                throw GlError(fmt::format("{}:{}: malformed #include", name, lineNo));
            }
            const std::string target = line.substr(q1 + 1, q2 - q1 - 1);
            std::string resolved = directoryOf(name) + target;
            if (findSource(resolved).data() == nullptr) {
                resolved = target;
            }
            if (findSource(resolved).data() == nullptr) {
                throw GlError(fmt::format("{}:{}: #include \"{}\" not found", name, lineNo, target));
            }
            expand(resolved, included, out, depth + 1);
            out += fmt::format("#line {}\n", lineNo + 1);
            continue;
        }
        out += line;
        out += '\n';
    }
}

/// The info log of a shader or program (`getiv`/`getLog` are the matching GL queries).
template <class GetIv, class GetLog>
std::string infoLog(GLuint object, GetIv getiv, GetLog getLog) {
    GLint length = 0;
    getiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    getLog(object, length, nullptr, log.data());
    return log;
}

/// Compiles `source` (complete: version line and all); `name` labels the errors.
GLuint compileSource(GLenum stage, const std::string& source, std::string_view name) {
    const GLuint shader = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        const std::string log = infoLog(shader, glGetShaderiv, glGetShaderInfoLog);
        glDeleteShader(shader);
        throw GlError(fmt::format("compiling {} failed:\n{}", name, log));
    }
    return shader;
}

GLuint compile(GLenum stage, std::string_view name, const ShaderDefines& defines) {
    return compileSource(stage, preprocessShader(name, defines), name);
}

Program link(std::initializer_list<GLuint> shaders, std::string_view label) {
    const GLuint program = glCreateProgram();
    for (GLuint s : shaders) {
        glAttachShader(program, s);
    }
    glLinkProgram(program);
    for (GLuint s : shaders) {
        glDetachShader(program, s);
        glDeleteShader(s);
    }
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        const std::string log = infoLog(program, glGetProgramiv, glGetProgramInfoLog);
        glDeleteProgram(program);
        throw GlError(fmt::format("linking {} failed:\n{}", label, log));
    }
    glObjectLabel(GL_PROGRAM, program, GLsizei(label.size()), label.data());
    return Program(program);
}

} // namespace

std::string preprocessShader(std::string_view name, const ShaderDefines& defines) {
    std::string out = "#version 450 core\n";
    for (const auto& [key, value] : defines) {
        out += fmt::format("#define {} {}\n", key, value);
    }
    out += "#line 1\n";
    std::set<std::string> included;
    expand(std::string(name), included, out, 0);
    return out;
}

Program makeComputeProgram(std::string_view computeName, const ShaderDefines& defines) {
    return link({compile(GL_COMPUTE_SHADER, computeName, defines)}, computeName);
}

Program makeComputeProgramFromSource(const std::string& source, std::string_view name) {
    return link({compileSource(GL_COMPUTE_SHADER, source, name)}, name);
}

Program makeGraphicsProgram(std::string_view vertexName, std::string_view fragmentName,
                            const ShaderDefines& defines) {
    const GLuint vs = compile(GL_VERTEX_SHADER, vertexName, defines);
    GLuint fs = 0;
    try {
        fs = compile(GL_FRAGMENT_SHADER, fragmentName, defines);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    return link({vs, fs}, fragmentName);
}

void setUniform(const Program& p, const char* name, float v) {
    glProgramUniform1f(p.id(), glGetUniformLocation(p.id(), name), v);
}
void setUniform(const Program& p, const char* name, int v) {
    glProgramUniform1i(p.id(), glGetUniformLocation(p.id(), name), v);
}
void setUniform(const Program& p, const char* name, float x, float y) {
    glProgramUniform2f(p.id(), glGetUniformLocation(p.id(), name), x, y);
}
void setUniform(const Program& p, const char* name, float x, float y, float z) {
    glProgramUniform3f(p.id(), glGetUniformLocation(p.id(), name), x, y, z);
}
void setUniform(const Program& p, const char* name, float x, float y, float z, float w) {
    glProgramUniform4f(p.id(), glGetUniformLocation(p.id(), name), x, y, z, w);
}

void dispatchPixels(Extent extent) noexcept {
    dispatchPixels(extent, kPixelGroupSquare);
}

namespace {
std::optional<PixelGroup> gForcedPixelGroup;
} // namespace

PixelGroup pixelGroup() {
    if (gForcedPixelGroup) {
        return *gForcedPixelGroup;
    }
    return isSoftwareRenderer() ? kPixelGroupRow : kPixelGroupSquare;
}

void forcePixelGroup(std::optional<PixelGroup> group) {
    if (group && *group != kPixelGroupSquare && *group != kPixelGroupRow) {
        throw std::invalid_argument(
            fmt::format("pixel group {}x{}: 8x8 or 64x1", group->width, group->height));
    }
    gForcedPixelGroup = group;
}

ShaderDefines withPixelGroup(ShaderDefines defines, PixelGroup group) {
    if (group == kPixelGroupRow) {
        defines.emplace_back("PIXEL_GROUP_ROW", "1");
    }
    return defines;
}

void dispatchPixels(Extent extent, PixelGroup group) noexcept {
    glDispatchCompute(GLuint((extent.width + group.width - 1) / group.width),
                      GLuint((extent.height + group.height - 1) / group.height), 1);
}

void computeReadBarrier() noexcept {
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void imageWriteBarrier() noexcept {
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
}

} // namespace photopic
