#pragma once
// GLSL embedded at build time (cmake/EmbedShaders.cmake), keyed by path below src/
// ("passes/x/x_y.frag.glsl"). Preprocessing: "#version 450 core", then the variant's #defines, then the
// source with #include "file" resolved (relative to the including file, else to src/), each file once.

#include "gl/Objects.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace photopic {

/// Every embedded shader source (generated).
const std::map<std::string, std::string_view>& embeddedShaders();

using ShaderDefines = std::vector<std::pair<std::string, std::string>>;

/// Full source of `name` ready for glShaderSource; throws GlError naming the file when a source or include is
/// missing.
std::string preprocessShader(std::string_view name, const ShaderDefines& defines = {});

/// Compiles and links; throws GlError with the file name and the driver's log.
Program makeComputeProgram(std::string_view computeName, const ShaderDefines& defines = {});
/// Compiles and links a complete compute source (its version line included: e.g. preprocessShader's output of
/// a header, and a main after it); `name` labels the program and the errors.
Program makeComputeProgramFromSource(const std::string& source, std::string_view name);
Program makeGraphicsProgram(std::string_view vertexName, std::string_view fragmentName,
                            const ShaderDefines& defines = {});

/// Work groups of a full-screen compute pass: 8x8 invocations, one pixel each, covering `extent` (shaders
/// return early outside the image).
inline constexpr int kPixelGroupSize = 8;
void dispatchPixels(Extent extent) noexcept;

/// The invocation shape of the pixel passes that let the host choose it (the bloom chain and the tone-map
/// pass, through passes/common/pixel_group.h.glsl): 8x8 on a GPU, a row of 64 on a software renderer, which
/// runs eight lanes along x and took the default chain to 0.93-0.96 of its 8x8 time that way
/// (docs/architecture.md). Results do not depend on the shape.
struct PixelGroup {
    int width = 8;
    int height = 8;
    friend bool operator==(PixelGroup, PixelGroup) = default;
};
inline constexpr PixelGroup kPixelGroupSquare{kPixelGroupSize, kPixelGroupSize};
inline constexpr PixelGroup kPixelGroupRow{64, 1};
/// The shape for passes built now: by the current context's renderer, unless a test forced one.
PixelGroup pixelGroup();
/// Tests: the shape pixelGroup() gives from now on; nullopt: by the renderer again.
void forcePixelGroup(std::optional<PixelGroup> group);
/// Whether a pass works through its work group's shared memory: gathers a neighbourhood from a shared tile
/// (each texel loaded and prepared once, then a barrier) rather than loading it at every pixel, and builds a
/// chain of reductions (mips, a depth pyramid) in one dispatch rather than a dispatch a level. On a GPU, where
/// the tile saves repeated loads and the single dispatch the waits between levels; not on a software
/// renderer, which runs barriers and the strided accesses of a tile slower than the loads and dispatches they
/// replace (docs/architecture.md). Results do not depend on it. By the current context's renderer, unless a
/// test forced it.
bool sharedMemoryTiles();
/// Tests: what sharedMemoryTiles() gives from now on; nullopt: by the renderer again.
void forceSharedMemoryTiles(std::optional<bool> shared);
/// `defines` with those that select `group` in passes/common/pixel_group.h.glsl (8x8 or 64x1).
ShaderDefines withPixelGroup(ShaderDefines defines, PixelGroup group);
/// Groups of `group` covering `extent`, one invocation per element.
void dispatchPixels(Extent extent, PixelGroup group) noexcept;
/// After a pass's image stores: whatever reads the image next (a sampler, an image load, a blit, a readback
/// or a copy) sees the stores.
void imageWriteBarrier() noexcept;
/// After a pass's image stores that only the next compute passes read (by texture fetches or image loads),
/// as between the levels of a chain: the narrower barrier costs the driver less than imageWriteBarrier's,
/// which also flushes for framebuffer, texture-update and pixel-buffer reads. The chain's last pass ends
/// with imageWriteBarrier.
void computeReadBarrier() noexcept;

/// A memory barrier by what reads next what a dispatch wrote (the only place src/passes issues
/// glMemoryBarrier): each names the glMemoryBarrier bits it issues.
enum class Barrier {
    None,                ///< nothing: the next reader is ordered some other way (or reads nothing of it)
    TextureFetch,        ///< the next pass samples what this one stored (TEXTURE_FETCH)
    ImageAccess,         ///< the next pass loads it as an image (SHADER_IMAGE_ACCESS)
    TextureFetchAndCopy, ///< sampled, or copied by a texture update (TEXTURE_FETCH | TEXTURE_UPDATE)
    ComputeRead,         ///< computeReadBarrier(): sampled or image-loaded by the next compute passes
    ImageWrite,          ///< imageWriteBarrier(): whatever reads the image next
    Storage,             ///< the next pass reads a storage buffer this one wrote (SHADER_STORAGE)
    StorageReadback,     ///< ... or copies or reads it back (SHADER_STORAGE | BUFFER_UPDATE)
    StorageAsUniform,    ///< ... also as a uniform block (SHADER_STORAGE | UNIFORM | BUFFER_UPDATE)
    /// the next pass is dispatched with arguments this one wrote, reads its storage buffer and samples or
    /// loads what it stored (COMMAND | SHADER_STORAGE | TEXTURE_FETCH | SHADER_IMAGE_ACCESS)
    IndirectDispatch,
};
void memoryBarrier(Barrier barrier) noexcept;

/// Work groups of a dispatch.
struct Groups {
    GLuint x = 1;
    GLuint y = 1;
    GLuint z = 1;
};
/// Groups of `group` covering `extent`, one invocation per element.
[[nodiscard]] Groups pixelGroups(Extent extent, PixelGroup group = kPixelGroupSquare) noexcept;

/// A pass's dispatch of `program` (current: use() it first): checks that every sampler and image it declares
/// was bound through a slot since the program's last dispatch (checkBindings: tests report the ones that were
/// not), dispatches `groups` and issues `after`.
void dispatch(const Program& program, Groups groups, Barrier after);
/// The same over the pixels of `extent`, in work groups of `group`.
void dispatch(const Program& program, Extent extent, Barrier after, PixelGroup group = kPixelGroupSquare);
/// The same with the work groups a GPU pass wrote: glDispatchComputeIndirect on the three uints at byte
/// `offset` of `arguments` (bound to GL_DISPATCH_INDIRECT_BUFFER for the call, then unbound).
void dispatchIndirect(const Program& program, GLuint arguments, GLintptr offset, Barrier after);

/// Set uniforms by name on a program (DSA: no bind needed). Missing names are ignored (optimised away).
void setUniform(const Program& p, const char* name, float v);
void setUniform(const Program& p, const char* name, int v);
void setUniform(const Program& p, const char* name, float x, float y);
void setUniform(const Program& p, const char* name, float x, float y, float z);
void setUniform(const Program& p, const char* name, float x, float y, float z, float w);

} // namespace photopic
