#pragma once
// Whole-texture GPU -> CPU reads that the CPU collects later (the mirror of UploadRing, for a sequence
// written frame after frame). start() has the GPU pack level 0 of a texture into a persistently mapped buffer
// and fences it; finish() waits for the oldest read started and copies it out. Between the two the CPU is
// free: a caller that starts frame N's read, prepares frame N+1 and then finishes N lets the GPU end frame
// N's work and pack it while the CPU decodes and uploads the next frame, where a glGetTextureImage into
// client memory waits for both (and a discrete GPU's driver goes through a staging copy of its own, since the
// GPU cannot write pageable memory).
//
// How the GPU packs: on a GPU, a compute shader (gl/texture_pack.comp.glsl) writes the samples, rows already
// top to bottom, straight into the mapped buffer: the values glGetTextureImage gives (unsigned normalised
// samples rounded to nearest, floats as they are), with no GL pixel transfer for the driver to run in step
// with rendering (NVIDIA's driver reports a read into a pack buffer as "synchronized with 3D rendering", a
// performance warning). On a
// software renderer, GL's pixel pack into the buffer: its copy is a memcpy there (a small part of what the
// shader took: docs/bench/LOG.md), and the rows are flipped as they are copied out.
//
// Each slot's buffer grows to the largest read it has held and is kept after that, so a sequence allocates
// nothing once its first frames are read.

#include "core/Image.h"
#include "gl/Objects.h"

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace photopic {

class TextureReadback {
public:
    TextureReadback() = default;
    enum class Pack {
        Auto,      ///< PixelPath on a software renderer, else Shader
        Shader,    ///< the compute shader, in bands of rows that one storage binding reaches
        PixelPath, ///< glGetTextureImage into the buffer
    };
    /// Up to `slots` reads started and not yet finished (the context must be current). `bandBytes` bounds
    /// one dispatch's share of the buffer with Shader (0: GL_MAX_SHADER_STORAGE_BLOCK_SIZE, which may be
    /// smaller than an image; tests pass a small one to pack in many bands).
    TextureReadback(int slots, std::string_view debugName, Pack pack = Pack::Auto, std::size_t bandBytes = 0);

    /// Starts reading level 0 of `texture` as RGBA values of `type` (GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT or
    /// GL_FLOAT, converted from the texture's format as glGetTextureImage converts). Throws std::logic_error
    /// when `slots` reads are already started and not finished, and for an sRGB, integer or depth texture.
    void start(const Texture& texture, GLenum type);
    /// Waits for the oldest read started and copies it into `image` (its storage kept when it already has the
    /// size), rows top to bottom. The image's sample type must be the one the read was started with
    /// (std::logic_error otherwise, and when no read is started).
    void finish(Image8& image);
    void finish(Image16& image);
    void finish(ImageF& image);

    /// Reads started and not yet finished.
    [[nodiscard]] int pending() const { return mPending; }
    [[nodiscard]] int slotCount() const { return int(mSlots.size()); }
    /// How this one packs (Auto resolved).
    [[nodiscard]] Pack pack() const { return mPack; }

private:
    struct Slot {
        Buffer buffer;
        const std::byte* mapped = nullptr;
        Fence fence;
        Extent extent;
        GLenum type = GL_NONE;
    };
    /// The oldest started slot, once its fence has signalled, checked to hold samples of `type`.
    Slot& waitOldest(GLenum type);
    template <class Image>
    void copyOut(Image& image, GLenum type);
    void packWithShader(const Texture& texture, const Slot& slot, std::size_t sample);

    std::vector<Slot> mSlots;
    std::array<Program, 3> mPrograms; ///< by sample size 1, 2, 4 bytes, made at their first read
    std::string mName;
    Pack mPack = Pack::Shader;
    std::size_t mBandBytes = 0;
    std::size_t mOldest = 0; ///< the slot the next finish() takes
    int mPending = 0;
};

} // namespace photopic
