#include "gl/Objects.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <string>
#include <vector>

namespace photopic {

namespace {
void label(GLenum type, GLuint id, std::string_view name) {
    if (!name.empty()) {
        glObjectLabel(type, id, GLsizei(name.size()), name.data());
    }
}

// Only GL threads create objects, but a host may run pipelines on several contexts and threads.
std::atomic<std::uint64_t> gTexturesCreated{0};
std::atomic<std::uint64_t> gBuffersCreated{0};

void checkComplete(GLuint id, std::string_view debugName, GLenum firstFormat) {
    const GLenum status = glCheckNamedFramebufferStatus(id, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        throw GlError("framebuffer '" + std::string(debugName) + "' is incomplete with a " +
                      std::string(formatName(firstFormat)) + " attachment (status 0x" +
                      std::to_string(status) + ")");
    }
}
} // namespace

GlObjectCounts glObjectCounts() noexcept {
    return {.textures = gTexturesCreated.load(), .buffers = gBuffersCreated.load()};
}

bool isDepthFormat(GLenum format) noexcept {
    switch (format) {
    case GL_DEPTH_COMPONENT16:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT32:
    case GL_DEPTH_COMPONENT32F:
    case GL_DEPTH24_STENCIL8:
    case GL_DEPTH32F_STENCIL8:
        return true;
    default:
        return false;
    }
}

Texture::Texture(const TextureCreateInfo& info)
    : mExtent(info.extent)
    , mFormat(info.format)
    , mLevels(info.levels) {
    if (info.extent.empty() || info.levels < 1) {
        throw GlError("texture '" + std::string(info.debugName) + "': empty extent or no levels");
    }
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    ++gTexturesCreated;
    mObject = GlObject<detail::TextureDeleter>(id);
    glTextureStorage2D(id, info.levels, info.format, info.extent.width, info.extent.height);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GLint(info.minFilter));
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GLint(info.magFilter));
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, GLint(info.wrap));
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, GLint(info.wrap));
    glTextureParameteri(id, GL_TEXTURE_MAX_LEVEL, info.levels - 1);
    label(GL_TEXTURE, id, info.debugName);
}

Texture Texture::adopt(GLuint id, Extent extent, GLenum format) {
    Texture t;
    t.mObject = GlObject<detail::TextureDeleter>(id, /*owned=*/false);
    t.mExtent = extent;
    t.mFormat = format;
    t.mLevels = 1;
    return t;
}

Extent Texture::levelExtent(int level) const {
    return {std::max(1, mExtent.width >> level), std::max(1, mExtent.height >> level)};
}

void Texture::uploadRgba32f(const float* rgba) const {
    const std::size_t row = std::size_t(mExtent.width) * 4;
    std::vector<float> flipped(row * std::size_t(mExtent.height));
    for (int y = 0; y < mExtent.height; ++y) {
        std::copy_n(rgba + std::size_t(mExtent.height - 1 - y) * row, row,
                    flipped.data() + std::size_t(y) * row);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(id(), 0, 0, 0, mExtent.width, mExtent.height, GL_RGBA, GL_FLOAT, flipped.data());
}

void Texture::copyLevel0From(const Texture& source, Extent extent) const {
    glCopyImageSubData(source.id(), GL_TEXTURE_2D, 0, 0, 0, 0, id(), GL_TEXTURE_2D, 0, 0, 0, 0, extent.width,
                       extent.height, 1);
}

Buffer::Buffer(const BufferCreateInfo& info)
    : mSize(info.size) {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    ++gBuffersCreated;
    mObject = GlObject<detail::BufferDeleter>(id);
    glNamedBufferStorage(id, GLsizeiptr(info.size), info.data, info.flags);
    label(GL_BUFFER, id, info.debugName);
}

void Buffer::update(const void* data, std::size_t bytes, std::size_t offset) const {
    glNamedBufferSubData(id(), GLintptr(offset), GLsizeiptr(bytes), data);
}

void Buffer::clearWords(std::size_t offset, const std::uint32_t* words, std::size_t count) const {
    // glClearNamedBufferSubData fills a range with one RGBA32UI value: one clear per four words.
    for (std::size_t i = 0; i < count; i += 4) {
        glClearNamedBufferSubData(id(), GL_RGBA32UI, GLintptr(offset + i * sizeof(std::uint32_t)), 16,
                                  GL_RGBA_INTEGER, GL_UNSIGNED_INT, words + i);
    }
}

std::byte* Buffer::mapPersistently(GLbitfield access, std::string_view what) const {
    void* mapped = glMapNamedBufferRange(id(), 0, GLsizeiptr(mSize), access);
    if (mapped == nullptr)
        throw GlError("cannot map " + std::string(what) + " (" + std::to_string(mSize) + " bytes)");
    return static_cast<std::byte*>(mapped);
}

Framebuffer::Framebuffer(const Texture& color, int level, std::string_view debugName) {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    mObject = GlObject<detail::FramebufferDeleter>(id);
    label(GL_FRAMEBUFFER, id, debugName);
    attach(color, level, debugName);
}

void Framebuffer::attach(const Texture& color, int level, std::string_view debugName) {
    mExtent = color.levelExtent(level);
    glNamedFramebufferTexture(id(), GL_COLOR_ATTACHMENT0, color.id(), level);
    checkComplete(id(), debugName, color.format());
}

Framebuffer::Framebuffer(const FramebufferCreateInfo& info) {
    const Texture* first = info.color.size() > 0 ? *info.color.begin() : info.depth;
    if (first == nullptr || info.color.size() > 8) {
        throw GlError("framebuffer '" + std::string(info.debugName) +
                      "': no attachment, or more than 8 colour");
    }
    mExtent = first->levelExtent(info.level);
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    mObject = GlObject<detail::FramebufferDeleter>(id);
    GLenum drawBuffers[8] = {};
    GLsizei count = 0;
    for (const Texture* t : info.color) {
        if (t == nullptr || t->levelExtent(info.level) != mExtent) {
            throw GlError("framebuffer '" + std::string(info.debugName) +
                          "': a colour attachment is missing or of another size");
        }
        drawBuffers[count] = GLenum(GL_COLOR_ATTACHMENT0 + count);
        glNamedFramebufferTexture(id, drawBuffers[count], t->id(), info.level);
        ++count;
    }
    glNamedFramebufferDrawBuffers(id, count, drawBuffers);
    if (info.depth) {
        if (!isDepthFormat(info.depth->format()) || info.depth->levelExtent(info.level) != mExtent) {
            throw GlError("framebuffer '" + std::string(info.debugName) +
                          "': the depth attachment is not a depth format or is of another size");
        }
        const bool stencil =
            info.depth->format() == GL_DEPTH24_STENCIL8 || info.depth->format() == GL_DEPTH32F_STENCIL8;
        glNamedFramebufferTexture(id, stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                                  info.depth->id(), info.level);
    }
    label(GL_FRAMEBUFFER, id, info.debugName);
    checkComplete(id, info.debugName, first->format());
}

void Framebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, id());
    glViewport(0, 0, mExtent.width, mExtent.height);
}

VertexArray VertexArray::create(std::string_view debugName) {
    VertexArray v;
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    v.mObject = GlObject<detail::VertexArrayDeleter>(id);
    label(GL_VERTEX_ARRAY, id, debugName);
    return v;
}

Sampler Sampler::clamped(GLenum filter, std::string_view debugName) {
    Sampler s;
    GLuint id = 0;
    glCreateSamplers(1, &id);
    s.mObject = GlObject<detail::SamplerDeleter>(id);
    glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, GLint(filter));
    glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, GLint(filter));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    label(GL_SAMPLER, id, debugName);
    return s;
}

Sampler Sampler::nearest(std::string_view debugName) {
    return clamped(GL_NEAREST, debugName);
}

Sampler Sampler::linear(std::string_view debugName) {
    return clamped(GL_LINEAR, debugName);
}

Sampler Sampler::linearTransparentBorder(std::string_view debugName) {
    Sampler s = clamped(GL_LINEAR, debugName);
    constexpr GLfloat kTransparent[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    glSamplerParameterfv(s.id(), GL_TEXTURE_BORDER_COLOR, kTransparent);
    return s;
}

Sampler Sampler::depthCompare(std::string_view debugName) {
    Sampler s = clamped(GL_LINEAR, debugName);
    glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    return s;
}

Query::Query(GLenum target) {
    GLuint id = 0;
    glCreateQueries(target, 1, &id);
    mObject = GlObject<detail::QueryDeleter>(id);
}

Fence Fence::insert() {
    Fence f;
    f.mSync = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    return f;
}

Fence& Fence::operator=(Fence&& o) noexcept {
    if (this != &o) {
        if (mSync) {
            glDeleteSync(mSync);
        }
        mSync = std::exchange(o.mSync, nullptr);
    }
    return *this;
}

Fence::~Fence() {
    if (mSync) {
        glDeleteSync(mSync);
    }
}

bool Fence::signalled() const {
    if (!mSync) {
        return true;
    }
    GLint status = GL_UNSIGNALED;
    glGetSynciv(mSync, GL_SYNC_STATUS, 1, nullptr, &status);
    return status == GL_SIGNALED;
}

void Fence::wait() const {
    if (!mSync) {
        return;
    }
    while (glClientWaitSync(mSync, GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000) == GL_TIMEOUT_EXPIRED) {
    }
}

DebugGroup::DebugGroup(std::string_view name) {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, GLsizei(name.size()), name.data());
}
DebugGroup::~DebugGroup() {
    glPopDebugGroup();
}

namespace {
/// Every sized internal format the library names: its name, its bytes a texel (bandwidth estimates) and its
/// GLSL image format qualifier (empty where no image can take it: three channels, sRGB, depth).
struct FormatInfo {
    GLenum format;
    std::string_view name;
    int bytes;
    std::string_view qualifier;
};
constexpr FormatInfo kFormats[] = {
    {GL_RGBA32F, "RGBA32F", 16, "rgba32f"},
    {GL_RGBA16F, "RGBA16F", 8, "rgba16f"},
    {GL_RGB32F, "RGB32F", 12, {}},
    {GL_RGB16F, "RGB16F", 6, {}},
    {GL_RG32F, "RG32F", 8, "rg32f"},
    {GL_RG16F, "RG16F", 4, "rg16f"},
    {GL_R11F_G11F_B10F, "R11F_G11F_B10F", 4, "r11f_g11f_b10f"},
    {GL_R32F, "R32F", 4, "r32f"},
    {GL_R16F, "R16F", 2, "r16f"},
    {GL_RGBA32UI, "RGBA32UI", 16, "rgba32ui"},
    {GL_RGBA16UI, "RGBA16UI", 8, "rgba16ui"},
    {GL_RGBA8UI, "RGBA8UI", 4, "rgba8ui"},
    {GL_RG32UI, "RG32UI", 8, "rg32ui"},
    {GL_RG16UI, "RG16UI", 4, "rg16ui"},
    {GL_RG8UI, "RG8UI", 2, "rg8ui"},
    {GL_R32UI, "R32UI", 4, "r32ui"},
    {GL_R16UI, "R16UI", 2, "r16ui"},
    {GL_R8UI, "R8UI", 1, "r8ui"},
    {GL_RGBA16, "RGBA16", 8, "rgba16"},
    {GL_RGB10_A2, "RGB10_A2", 4, "rgb10_a2"},
    {GL_RGBA8, "RGBA8", 4, "rgba8"},
    {GL_SRGB8_ALPHA8, "SRGB8_ALPHA8", 4, {}},
    {GL_RG16, "RG16", 4, "rg16"},
    {GL_RG8, "RG8", 2, "rg8"},
    {GL_R16, "R16", 2, "r16"},
    {GL_R8, "R8", 1, "r8"},
    {GL_RGBA16_SNORM, "RGBA16_SNORM", 8, "rgba16_snorm"},
    {GL_RGBA8_SNORM, "RGBA8_SNORM", 4, "rgba8_snorm"},
    {GL_RG16_SNORM, "RG16_SNORM", 4, "rg16_snorm"},
    {GL_RG8_SNORM, "RG8_SNORM", 2, "rg8_snorm"},
    {GL_R16_SNORM, "R16_SNORM", 2, "r16_snorm"},
    {GL_R8_SNORM, "R8_SNORM", 1, "r8_snorm"},
    {GL_DEPTH_COMPONENT16, "DEPTH_COMPONENT16", 2, {}},
    {GL_DEPTH_COMPONENT24, "DEPTH_COMPONENT24", 4, {}},
    {GL_DEPTH_COMPONENT32, "DEPTH_COMPONENT32", 4, {}},
    {GL_DEPTH_COMPONENT32F, "DEPTH_COMPONENT32F", 4, {}},
    {GL_DEPTH24_STENCIL8, "DEPTH24_STENCIL8", 4, {}},
    {GL_DEPTH32F_STENCIL8, "DEPTH32F_STENCIL8", 8, {}},
};

const FormatInfo* findFormat(GLenum format) noexcept {
    for (const FormatInfo& f : kFormats) {
        if (f.format == format) {
            return &f;
        }
    }
    return nullptr;
}
} // namespace

int bytesPerTexel(GLenum format) {
    const FormatInfo* f = findFormat(format);
    return f ? f->bytes : 4;
}

std::string formatName(GLenum format) {
    if (const FormatInfo* f = findFormat(format)) {
        return std::string(f->name);
    }
    char hex[32];
    std::snprintf(hex, sizeof hex, "format 0x%04X", unsigned(format));
    return hex;
}

std::string_view imageFormatQualifier(GLenum format) {
    const FormatInfo* f = findFormat(format);
    return f ? f->qualifier : std::string_view{};
}

GLenum imageFormatFromQualifier(std::string_view qualifier) {
    for (const FormatInfo& f : kFormats) {
        if (!qualifier.empty() && f.qualifier == qualifier) {
            return f.format;
        }
    }
    return 0;
}

} // namespace photopic
