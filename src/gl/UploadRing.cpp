#include "gl/UploadRing.h"

#include <algorithm>
#include <string>

namespace photopic {

UploadRing::UploadRing(std::size_t bytes, int slots, std::string_view debugName)
    : mBytes(bytes) {
    mSlots.resize(std::size_t(std::max(slots, 1)));
    int i = 0;
    for (auto& slot : mSlots) {
        const std::string name = std::string(debugName) + " upload " + std::to_string(i++);
        // Coherent: the texels written become visible to the uploads issued after the writes, with no flush.
        const GLbitfield flags = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
        slot.buffer = Buffer({.size = bytes, .flags = flags, .data = nullptr, .debugName = name});
        slot.mapped = slot.buffer.mapPersistently(flags, "the upload buffer '" + name + "'");
    }
}

std::span<std::byte> UploadRing::begin() {
    Slot& slot = mSlots[mNext];
    mNext = (mNext + 1) % mSlots.size();
    slot.fence.wait(); // at once unless the GPU is still reading this slot's last texels
    slot.fence = Fence();
    mCurrent = &slot;
    return {slot.mapped, mBytes};
}

void UploadRing::upload(const Texture& texture, std::size_t offset, GLenum format, GLenum type) const {
    const Extent extent = texture.extent();
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, mCurrent->buffer.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // With an unpack buffer bound, the pointer argument is the offset into it.
    glTextureSubImage2D(texture.id(), 0, 0, 0, extent.width, extent.height, format, type,
                        reinterpret_cast<const void*>(offset));
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
}

void UploadRing::end() {
    if (mCurrent != nullptr)
        mCurrent->fence = Fence::insert();
    mCurrent = nullptr;
}

} // namespace photopic
