#include "gl/ShaderLibrary.h"

#include "gl/Capabilities.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <memory>
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

/// Compiles `name`; appends its preprocessed source to `sources` (what the program's reflection keeps).
GLuint compile(GLenum stage, std::string_view name, const ShaderDefines& defines, std::string& sources) {
    std::string source = preprocessShader(name, defines);
    const GLuint shader = compileSource(stage, source, name);
    sources += source;
    return shader;
}

bool isSamplerType(GLenum type) {
    switch (type) {
    case GL_SAMPLER_1D:
    case GL_SAMPLER_2D:
    case GL_SAMPLER_3D:
    case GL_SAMPLER_CUBE:
    case GL_SAMPLER_2D_SHADOW:
    case GL_SAMPLER_2D_ARRAY:
    case GL_SAMPLER_2D_ARRAY_SHADOW:
    case GL_SAMPLER_CUBE_SHADOW:
    case GL_SAMPLER_2D_MULTISAMPLE:
    case GL_SAMPLER_BUFFER:
    case GL_INT_SAMPLER_2D:
    case GL_INT_SAMPLER_3D:
    case GL_INT_SAMPLER_2D_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_2D:
    case GL_UNSIGNED_INT_SAMPLER_3D:
    case GL_UNSIGNED_INT_SAMPLER_2D_ARRAY:
        return true;
    default:
        return false;
    }
}

bool isImageType(GLenum type) {
    switch (type) {
    case GL_IMAGE_2D:
    case GL_IMAGE_3D:
    case GL_IMAGE_2D_ARRAY:
    case GL_IMAGE_CUBE:
    case GL_IMAGE_BUFFER:
    case GL_INT_IMAGE_2D:
    case GL_INT_IMAGE_3D:
    case GL_INT_IMAGE_2D_ARRAY:
    case GL_UNSIGNED_INT_IMAGE_2D:
    case GL_UNSIGNED_INT_IMAGE_3D:
    case GL_UNSIGNED_INT_IMAGE_2D_ARRAY:
        return true;
    default:
        return false;
    }
}

/// The samplers and images `program` declares, with the units their layout(binding = N) gave.
std::shared_ptr<const ProgramInterface> reflect(GLuint program, std::string_view label, std::string source) {
    auto interface = std::make_shared<ProgramInterface>();
    interface->label = std::string(label);
    interface->source = std::move(source);
    GLint count = 0;
    glGetProgramInterfaceiv(program, GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
    for (GLint i = 0; i < count; ++i) {
        const std::array<GLenum, 3> props = {GL_TYPE, GL_LOCATION, GL_ARRAY_SIZE};
        std::array<GLint, 3> v{};
        glGetProgramResourceiv(program, GL_UNIFORM, GLuint(i), GLsizei(props.size()), props.data(),
                               GLsizei(v.size()), nullptr, v.data());
        const bool image = isImageType(GLenum(v[0]));
        if ((!image && !isSamplerType(GLenum(v[0]))) || v[1] < 0) {
            continue;
        }
        std::array<char, 128> name{};
        glGetProgramResourceName(program, GL_UNIFORM, GLuint(i), GLsizei(name.size()), nullptr, name.data());
        std::string uniform = name.data();
        if (const auto bracket = uniform.find('['); bracket != std::string::npos) {
            uniform.resize(bracket); // an array: its slot is its first element's unit (passes declare none)
        }
        GLint unit = 0;
        glGetUniformiv(program, v[1], &unit);
        const GLenum format = image ? declaredImageFormat(interface->source, uniform) : 0;
        interface->uniforms.push_back({std::move(uniform), unit, image, format});
    }
    return interface;
}

Program link(std::initializer_list<GLuint> shaders, std::string_view label, std::string source) {
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
    return Program(program, reflect(program, label, std::move(source)));
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
    std::string source;
    const GLuint shader = compile(GL_COMPUTE_SHADER, computeName, defines, source);
    return link({shader}, computeName, std::move(source));
}

Program makeComputeProgramFromSource(const std::string& source, std::string_view name) {
    return link({compileSource(GL_COMPUTE_SHADER, source, name)}, name, source);
}

Program makeGraphicsProgram(std::string_view vertexName, std::string_view fragmentName,
                            const ShaderDefines& defines) {
    std::string sources;
    const GLuint vs = compile(GL_VERTEX_SHADER, vertexName, defines, sources);
    GLuint fs = 0;
    try {
        fs = compile(GL_FRAGMENT_SHADER, fragmentName, defines, sources);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    return link({vs, fs}, fragmentName, std::move(sources));
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
std::optional<bool> gForcedSharedMemoryTiles;
} // namespace

bool sharedMemoryTiles() {
    return gForcedSharedMemoryTiles.value_or(!isSoftwareRenderer());
}

void forceSharedMemoryTiles(std::optional<bool> shared) {
    gForcedSharedMemoryTiles = shared;
}

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
    const Groups groups = pixelGroups(extent, group);
    glDispatchCompute(groups.x, groups.y, groups.z);
}

void computeReadBarrier() noexcept {
    memoryBarrier(Barrier::ComputeRead);
}

void imageWriteBarrier() noexcept {
    memoryBarrier(Barrier::ImageWrite);
}

void memoryBarrier(Barrier barrier) noexcept {
    GLbitfield bits = 0;
    switch (barrier) {
    case Barrier::None:
        return;
    case Barrier::TextureFetch:
        bits = GL_TEXTURE_FETCH_BARRIER_BIT;
        break;
    case Barrier::ImageAccess:
        bits = GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;
        break;
    case Barrier::TextureFetchAndCopy:
        bits = GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT;
        break;
    case Barrier::ComputeRead:
        bits = GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;
        break;
    case Barrier::ImageWrite:
        bits = GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
               GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT;
        break;
    case Barrier::Storage:
        bits = GL_SHADER_STORAGE_BARRIER_BIT;
        break;
    case Barrier::StorageReadback:
        bits = GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT;
        break;
    case Barrier::StorageAsUniform:
        bits = GL_SHADER_STORAGE_BARRIER_BIT | GL_UNIFORM_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT;
        break;
    case Barrier::IndirectDispatch:
        bits = GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
               GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;
        break;
    }
    glMemoryBarrier(bits);
}

void dispatch(const Program& program, Groups groups, Barrier after) {
    checkBindings(program);
    glDispatchCompute(groups.x, groups.y, groups.z);
    memoryBarrier(after);
}

void dispatch(const Program& program, Extent extent, Barrier after, PixelGroup group) {
    dispatch(program, pixelGroups(extent, group), after);
}

void dispatchIndirect(const Program& program, GLuint arguments, GLintptr offset, Barrier after) {
    checkBindings(program);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, arguments);
    glDispatchComputeIndirect(offset);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    memoryBarrier(after);
}

Groups pixelGroups(Extent extent, PixelGroup group) noexcept {
    return {GLuint((extent.width + group.width - 1) / group.width),
            GLuint((extent.height + group.height - 1) / group.height), 1};
}

} // namespace photopic
