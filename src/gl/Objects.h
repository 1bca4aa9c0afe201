#pragma once
// Move-only RAII wrappers over GL 4.5 DSA objects with immutable storage. Objects can exist before a context
// (default-constructed, id 0); destructors ignore id 0; moves hand the id over with std::exchange.
// Every object gets a glObjectLabel so a frame capture reads like the frame order.

#include "gl/Gl.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace photopic {

/// Owns one GL name and deletes it with `Deleter` (unless adopted from a host).
template <class Deleter>
class GlObject {
public:
    GlObject() = default;
    explicit GlObject(GLuint id, bool owned = true)
        : mId(id)
        , mOwned(owned) {}
    GlObject(GlObject&& o) noexcept
        : mId(std::exchange(o.mId, 0u))
        , mOwned(o.mOwned) {}
    GlObject& operator=(GlObject&& o) noexcept {
        if (this != &o) {
            reset();
            mId = std::exchange(o.mId, 0u);
            mOwned = o.mOwned;
        }
        return *this;
    }
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;
    ~GlObject() { reset(); }

    [[nodiscard]] GLuint id() const { return mId; }
    [[nodiscard]] bool valid() const { return mId != 0; }
    [[nodiscard]] bool owned() const { return mOwned; }
    void reset() {
        if (mId != 0 && mOwned) {
            Deleter{}(mId);
        }
        mId = 0;
    }

private:
    GLuint mId = 0;
    bool mOwned = true;
};

namespace detail {
struct TextureDeleter {
    void operator()(GLuint id) const { glDeleteTextures(1, &id); }
};
struct BufferDeleter {
    void operator()(GLuint id) const { glDeleteBuffers(1, &id); }
};
struct FramebufferDeleter {
    void operator()(GLuint id) const { glDeleteFramebuffers(1, &id); }
};
struct ProgramDeleter {
    void operator()(GLuint id) const { glDeleteProgram(id); }
};
struct VertexArrayDeleter {
    void operator()(GLuint id) const { glDeleteVertexArrays(1, &id); }
};
struct QueryDeleter {
    void operator()(GLuint id) const { glDeleteQueries(1, &id); }
};
struct SamplerDeleter {
    void operator()(GLuint id) const { glDeleteSamplers(1, &id); }
};
} // namespace detail

struct TextureCreateInfo {
    Extent extent;
    GLenum format = GL_RGBA16F; ///< sized internal format
    int levels = 1;
    GLenum minFilter = GL_LINEAR;
    GLenum magFilter = GL_LINEAR;
    GLenum wrap = GL_CLAMP_TO_EDGE;
    std::string_view debugName;
};

/// A 2D texture with immutable storage, or a host's texture adopted by id (not deleted by us).
class Texture {
public:
    Texture() = default;
    explicit Texture(const TextureCreateInfo& info);
    /// Wraps a texture the host owns; Photopic never deletes it. `format` is its sized internal format.
    static Texture adopt(GLuint id, Extent extent, GLenum format);

    [[nodiscard]] GLuint id() const { return mObject.id(); }
    [[nodiscard]] bool valid() const { return mObject.valid(); }
    [[nodiscard]] bool owned() const { return mObject.owned(); }
    [[nodiscard]] Extent extent() const { return mExtent; }
    [[nodiscard]] GLenum format() const { return mFormat; }
    [[nodiscard]] int levels() const { return mLevels; }
    /// Size of mip `level` (at least 1x1).
    [[nodiscard]] Extent levelExtent(int level) const;

    /// Uploads RGBA float pixels (rows top to bottom) into level 0; GL's origin is bottom-left, so rows are
    /// flipped to keep texel (x, y) == image pixel (x, y) with v = 0 at the bottom of the texture.
    void uploadRgba32f(const float* rgba) const;
    /// Copies `extent` of `source`'s level 0 (the same format) into this texture's level 0 at the origin: a
    /// copy at the memory's speed, for a pass that writes only part of an image over its input.
    void copyLevel0From(const Texture& source, Extent extent) const;

private:
    GlObject<detail::TextureDeleter> mObject;
    Extent mExtent;
    GLenum mFormat = 0;
    int mLevels = 0;
};

struct BufferCreateInfo {
    std::size_t size = 0;
    GLbitfield flags = GL_DYNAMIC_STORAGE_BIT; ///< glNamedBufferStorage flags
    const void* data = nullptr;
    std::string_view debugName;
};

class Buffer {
public:
    Buffer() = default;
    explicit Buffer(const BufferCreateInfo& info);
    [[nodiscard]] GLuint id() const { return mObject.id(); }
    [[nodiscard]] std::size_t size() const { return mSize; }
    [[nodiscard]] bool valid() const { return mObject.valid(); }
    void update(const void* data, std::size_t bytes, std::size_t offset = 0) const;
    /// Sets `count` (a multiple of four) uints from `words` at `offset` (a multiple of 16 bytes) as a
    /// GPU-side clear, in order with the commands around it: a tile list's dispatch arguments, reset each
    /// frame without waiting for the GPU to release the buffer.
    void clearWords(std::size_t offset, const std::uint32_t* words, std::size_t count) const;
    /// Maps all of it with `access` for as long as it lives (made with GL_MAP_PERSISTENT_BIT and those access
    /// bits). Throws GlError "cannot map `what` (N bytes)" when the driver refuses.
    [[nodiscard]] std::byte* mapPersistently(GLbitfield access, std::string_view what) const;

private:
    GlObject<detail::BufferDeleter> mObject;
    std::size_t mSize = 0;
};

/// Attachments of a framebuffer: colour targets in draw-buffer order (MRT) and an optional depth or
/// depth-stencil texture, all at mip `level` and the same size.
struct FramebufferCreateInfo {
    std::initializer_list<const Texture*> color;
    const Texture* depth = nullptr; ///< GL_DEPTH_COMPONENT* or GL_DEPTH24_STENCIL8 / GL_DEPTH32F_STENCIL8
    int level = 0;
    std::string_view debugName;
};

/// A framebuffer: one colour attachment (what a full-screen pass needs), or several plus depth (a scene's
/// G-buffer-style outputs). Throws GlError naming it when incomplete.
class Framebuffer {
public:
    Framebuffer() = default;
    Framebuffer(const Texture& color, int level, std::string_view debugName);
    explicit Framebuffer(const FramebufferCreateInfo& info);
    [[nodiscard]] GLuint id() const { return mObject.id(); }
    [[nodiscard]] Extent extent() const { return mExtent; }
    /// Makes `color` (level `level`) its one colour attachment in place of the one it had: a framebuffer kept
    /// for textures that change from call to call, without making one per texture. Throws GlError naming
    /// `debugName` when the result is incomplete.
    void attach(const Texture& color, int level, std::string_view debugName);
    /// Binds it, sets the viewport to the attachment's size.
    void bind() const;

private:
    GlObject<detail::FramebufferDeleter> mObject;
    Extent mExtent;
};

/// A std140 uniform block mirrored by `T` in C++ (explicit padding, static_asserts on size and offsets next
/// to the struct): one immutable buffer per block, updated with glNamedBufferSubData and bound to its
/// binding index before a dispatch or draw. An update that repeats the block's contents writes nothing:
/// a pass whose parameters hold still updates no buffer in a frame, so the driver never has to version a
/// buffer that a dispatch still reads (a measurable cost a frame on a GPU, docs/bench/LOG.md). Shaders cannot
/// write a uniform block, so what it last wrote is what it holds.
template <class T>
class ParameterBlock {
    static_assert(std::is_trivially_copyable_v<T>, "a parameter block's contents are compared as bytes");

public:
    ParameterBlock() = default;
    explicit ParameterBlock(std::string_view debugName, const T& initial = T{})
        : mBuffer(
              {.size = sizeof(T), .flags = GL_DYNAMIC_STORAGE_BIT, .data = &initial, .debugName = debugName})
        , mWritten(initial) {}
    void update(const T& value) {
        if (std::memcmp(&value, &mWritten, sizeof(T)) != 0) {
            mBuffer.update(&value, sizeof(T));
            mWritten = value;
        }
    }
    void bind(GLuint binding) const { glBindBufferBase(GL_UNIFORM_BUFFER, binding, mBuffer.id()); }
    [[nodiscard]] const Buffer& buffer() const { return mBuffer; }
    [[nodiscard]] bool valid() const { return mBuffer.valid(); }

private:
    Buffer mBuffer;
    T mWritten{}; ///< what the buffer holds
};

/// A sampler a program declares (`layout(binding = N) uniform sampler2D uName;`), looked up by name once
/// (when the pass is made) with Program::sampler: the GLSL is the one place its unit is named. A slot whose
/// sampler the compiler optimised away (unit -1) binds nothing.
struct SamplerSlot {
    GLint unit = -1;
    [[nodiscard]] bool active() const { return unit >= 0; }
};
/// An image a program declares (`layout(binding = N, rgba16f) uniform image2D uName;`), from Program::image,
/// with the format its qualifier names (GL reflects none: read from the program's source, 0 where none was
/// found): a texture bound through it in another format would load and store undefined values.
struct ImageSlot {
    GLint unit = -1;
    GLenum format = 0;
    std::string_view label; ///< the program's and the image's names, for the format check's report (they
    std::string_view name;  ///< live in the program's reflection, as long as the program)
    [[nodiscard]] bool active() const { return unit >= 0; }
};
enum class ImageAccess : GLenum { Read = GL_READ_ONLY, Write = GL_WRITE_ONLY, ReadWrite = GL_READ_WRITE };

/// What a program declares, reflected after linking: its label (the shader file) and its active sampler and
/// image uniforms (name, unit), for the slots and the binding check at each dispatch.
struct ProgramInterface {
    struct Uniform {
        std::string name;
        GLint unit = -1;
        bool image = false;
        GLenum format = 0; ///< an image's declared format (declaredImageFormat), 0 for samplers
    };
    std::string label;
    std::string source; ///< the preprocessed sources: tells a name optimised away from a misspelt one
    std::vector<Uniform> uniforms;
    mutable std::uint64_t checked = 0; ///< the bind count at its last binding check (checkBindings)
};

/// The format the image uniform `name` is declared with in a program's `source` (`layout(binding = N,
/// rgba16f) uniform readonly image2D name;`): the layout entry that is no assignment, as a qualifier or as a
/// define whose every definition names the same one. 0 when no declaration names one, or when declarations in
/// branches of the preprocessor name different ones (GL reflects no format qualifier). A scan of the text:
/// every program made pays for it.
GLenum declaredImageFormat(std::string_view source, std::string_view name);

class Program {
public:
    Program() = default;
    explicit Program(GLuint id)
        : mObject(id) {}
    Program(GLuint id, std::shared_ptr<const ProgramInterface> interface)
        : mObject(id)
        , mInterface(std::move(interface)) {}
    [[nodiscard]] GLuint id() const { return mObject.id(); }
    [[nodiscard]] bool valid() const { return mObject.valid(); }
    void use() const { glUseProgram(mObject.id()); }

    /// The sampler `name` declares. Throws GlError naming the shader and `name` when the program declares no
    /// such sampler; one the compiler optimised away (named in the source, not active) gives an inactive
    /// slot.
    [[nodiscard]] SamplerSlot sampler(std::string_view name) const;
    /// The image `name` declares; throws like sampler().
    [[nodiscard]] ImageSlot image(std::string_view name) const;
    /// Its reflected samplers and images (null for a program made from a bare id).
    [[nodiscard]] const ProgramInterface* interface() const { return mInterface.get(); }

private:
    GlObject<detail::ProgramDeleter> mObject;
    std::shared_ptr<const ProgramInterface> mInterface;
};

class VertexArray {
public:
    VertexArray() = default;
    static VertexArray create(std::string_view debugName);
    [[nodiscard]] GLuint id() const { return mObject.id(); }

private:
    GlObject<detail::VertexArrayDeleter> mObject;
};

/// A sampler object: filtering that overrides, on the unit it is bound to, whatever the texture there set.
class Sampler {
public:
    Sampler() = default;
    /// NEAREST filtering, clamped: what an integer texture read with texelFetch needs to be complete.
    static Sampler nearest(std::string_view debugName);
    /// LINEAR filtering (level 0 only), clamped: bilinear reads of a texture whose own filtering and
    /// completeness the caller does not control (a host's).
    static Sampler linear(std::string_view debugName);
    /// LINEAR filtering with depth comparison (LEQUAL), clamped: a depth texture read through a
    /// sampler2DShadow as the share of a 2x2 footprint whose depth is at or beyond the reference.
    static Sampler depthCompare(std::string_view debugName);
    /// LINEAR filtering (level 0 only) with a transparent black border: reads past the texture's edge are
    /// (0, 0, 0, 0), for filters that treat what lies outside an image as nothing.
    static Sampler linearTransparentBorder(std::string_view debugName);
    [[nodiscard]] GLuint id() const { return mObject.id(); }

private:
    /// `filter` for minification and magnification, clamped to the edge.
    static Sampler clamped(GLenum filter, std::string_view debugName);

    GlObject<detail::SamplerDeleter> mObject;
};

/// Binds `texture` to the unit of `slot` (nothing for an inactive slot); the dispatch check counts it bound.
void bind(SamplerSlot slot, const Texture& texture) noexcept;
/// `texture` with the sampler object `sampler` on its unit (its filtering overrides the texture's).
void bind(SamplerSlot slot, const Texture& texture, const Sampler& sampler) noexcept;
/// Leaves the unit of `slot` without a texture (what a pass that must not leave its inputs bound ends with).
void unbind(SamplerSlot slot) noexcept;
/// Puts `sampler` (null: none, the texture's own filtering again) on the unit of `slot`.
void bindSampler(SamplerSlot slot, const Sampler* sampler) noexcept;
/// Binds `level` of `texture` to the image unit of `slot` with `access`, in the texture's format, which must
/// be the one the shader declares: a texture of another format is reported to the binding-problem handler.
void bind(ImageSlot slot, const Texture& texture, ImageAccess access, int level = 0);

/// The binding check at a dispatch: true when every sampler and image `program` declares was bound through a
/// slot since the program's last check (its last dispatch): what a pass binds before its dispatches, each
/// program of it finds bound, and a slot the pass forgot is found stale unless another pass happened to bind
/// its unit in between. Reports each stale one to the handler (tests). A compare per declared uniform (units
/// 0-63; from 64 on, units are not tracked).
bool checkBindings(const Program& program);
/// Tests: called with one line per binding problem: a declared sampler or image that a dispatch found unbound
/// (naming the shader, the uniform and its unit), or a texture bound to an image slot whose shader declares
/// another format. Empty: no handler (the checks still run, and report nothing).
using BindingProblemHandler = std::function<void(const std::string& problem)>;
/// Installs `handler`, returning the one it replaces.
BindingProblemHandler setBindingProblemHandler(BindingProblemHandler handler);

class Query {
public:
    Query() = default;
    explicit Query(GLenum target);
    [[nodiscard]] GLuint id() const { return mObject.id(); }

private:
    GlObject<detail::QueryDeleter> mObject;
};

/// A fence sync; moving hands it over, destruction deletes it.
class Fence {
public:
    Fence() = default;
    static Fence insert();
    Fence(Fence&& o) noexcept
        : mSync(std::exchange(o.mSync, nullptr)) {}
    Fence& operator=(Fence&& o) noexcept;
    Fence(const Fence&) = delete;
    Fence& operator=(const Fence&) = delete;
    ~Fence();
    [[nodiscard]] bool valid() const { return mSync != nullptr; }
    /// Non-blocking: true once the GPU has passed the fence.
    [[nodiscard]] bool signalled() const;
    /// Blocks until signalled (offline paths only, e.g. draining a ring at the end of a sequence).
    void wait() const;

private:
    GLsync mSync = nullptr;
};

/// Scoped KHR_debug group: a pass's name in frame captures and debug output.
class DebugGroup {
public:
    explicit DebugGroup(std::string_view name);
    ~DebugGroup();
    DebugGroup(const DebugGroup&) = delete;
    DebugGroup& operator=(const DebugGroup&) = delete;
};

/// GL textures and buffers this process has created through the wrappers (adopted host objects do not
/// count). A steady-state frame creates none: tests compare the counts over many frames.
struct GlObjectCounts {
    std::uint64_t textures = 0;
    std::uint64_t buffers = 0;
    friend bool operator==(const GlObjectCounts&, const GlObjectCounts&) = default;
};
[[nodiscard]] GlObjectCounts glObjectCounts() noexcept;

/// True for GL_DEPTH_COMPONENT16/24/32F and the depth-stencil formats.
[[nodiscard]] bool isDepthFormat(GLenum format) noexcept;

/// Bytes per texel of a sized internal format, for bandwidth estimates (4 for one the library does not name).
int bytesPerTexel(GLenum format);
/// Human name of a sized internal format ("RGBA16F"); "format 0x8F97" for one the library does not name.
std::string formatName(GLenum format);
/// The GLSL image format qualifier of a sized internal format ("rgba16f"); empty for a format no image can
/// take (three channels, sRGB, depth).
std::string_view imageFormatQualifier(GLenum format);
/// The sized internal format an image format qualifier names; 0 for none.
GLenum imageFormatFromQualifier(std::string_view qualifier);

} // namespace photopic
