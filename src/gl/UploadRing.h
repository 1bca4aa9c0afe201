#pragma once
// CPU -> GPU texture uploads that the driver does not convert or copy on the CPU (the mirror of
// ReadbackRing): N slots, each a persistently mapped pixel unpack buffer and a fence. The caller writes a
// frame's texels into a slot's mapped memory, already in the textures' row order and type, and each texture
// takes its texels from there in one glTextureSubImage2D, a copy the GPU makes on its own time. A slot is
// written again only once the GPU has passed the fence set after its last uploads, so the CPU never
// overwrites texels still being read; with two slots, the CPU fills one while the GPU reads the other.
//
// The mapping is write-only and may be write-combined (uncached) memory: fill it front to back, never read
// it back.

#include "gl/Objects.h"

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

namespace photopic {

class UploadRing {
public:
    UploadRing() = default;
    /// `slots` buffers of `bytes` each.
    UploadRing(std::size_t bytes, int slots, std::string_view debugName);

    /// The next slot's mapped memory, `bytes()` long, once the GPU has finished the uploads made from it
    /// before (waits for its fence). Until end(), upload() takes texels from this slot.
    [[nodiscard]] std::span<std::byte> begin();
    /// Replaces level 0 of `texture` with the texels at `offset` in the slot begin() returned, in one
    /// glTextureSubImage2D: rows bottom to top (GL's order), `format`/`type` as glTextureSubImage2D takes
    /// them, rows padded to 4 bytes. `offset` must be a multiple of the size of `type`'s values.
    void upload(const Texture& texture, std::size_t offset, GLenum format, GLenum type) const;
    /// Fences the slot (its next begin() waits for the uploads made from it) and unbinds the unpack buffer.
    void end();

    [[nodiscard]] std::size_t bytes() const { return mBytes; }
    [[nodiscard]] int slotCount() const { return int(mSlots.size()); }
    [[nodiscard]] bool valid() const { return !mSlots.empty(); }

private:
    struct Slot {
        Buffer buffer;
        std::byte* mapped = nullptr;
        Fence fence;
    };
    std::vector<Slot> mSlots;
    std::size_t mBytes = 0;
    std::size_t mNext = 0;    ///< the slot the next begin() takes
    Slot* mCurrent = nullptr; ///< between begin() and end()
};

} // namespace photopic
