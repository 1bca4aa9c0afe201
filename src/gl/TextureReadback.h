#pragma once
// Whole-texture GPU -> CPU reads that the CPU collects later (the mirror of UploadRing, for a sequence
// written frame after frame). start() asks the GPU to pack level 0 of a texture into a persistently mapped
// pixel-pack buffer and fences it; finish() waits for the oldest read started and copies it out, rows top to
// bottom. Between the two the CPU is free: a caller that starts frame N's read, prepares frame N+1 and then
// finishes N lets the GPU end frame N's work and copy it out while the CPU decodes and uploads the next
// frame, where a glGetTextureImage into client memory would wait for both, and on some drivers go through a
// staging copy.
//
// Each slot's buffer grows to the largest read it has held and is kept after that, so a sequence allocates
// nothing once its first frames are read.

#include "core/Image.h"
#include "gl/Objects.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace photopic {

class TextureReadback {
public:
    TextureReadback() = default;
    /// Up to `slots` reads started and not yet finished.
    TextureReadback(int slots, std::string_view debugName);

    /// Starts reading level 0 of `texture` as RGBA values of `type` (GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT or
    /// GL_FLOAT; GL converts from the texture's format as glGetTextureImage does). Throws std::logic_error
    /// when `slots` reads are already started and not finished.
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

    std::vector<Slot> mSlots;
    std::string mName;
    std::size_t mOldest = 0; ///< the slot the next finish() takes
    int mPending = 0;
};

} // namespace photopic
