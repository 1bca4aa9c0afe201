#include "gl/TextureReadback.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace photopic {

namespace {
std::size_t sampleBytes(GLenum type) {
    switch (type) {
    case GL_UNSIGNED_BYTE:
        return 1;
    case GL_UNSIGNED_SHORT:
        return 2;
    case GL_FLOAT:
        return 4;
    default:
        throw std::logic_error("TextureReadback: unsupported sample type");
    }
}
} // namespace

TextureReadback::TextureReadback(int slots, std::string_view debugName)
    : mSlots(std::size_t(std::max(slots, 1)))
    , mName(debugName) {}

void TextureReadback::start(const Texture& texture, GLenum type) {
    if (mPending == slotCount())
        throw std::logic_error("TextureReadback '" + mName + "': every slot holds a read not yet finished");
    Slot& slot = mSlots[(mOldest + std::size_t(mPending)) % mSlots.size()];
    const Extent extent = texture.extent();
    const std::size_t bytes = std::size_t(extent.width) * std::size_t(extent.height) * 4 * sampleBytes(type);
    if (slot.buffer.size() < bytes) {
        // Client storage: the GPU writes the packed texels into memory the CPU reads cached, once each.
        const GLbitfield flags = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
        const std::string name = mName + " readback " + std::to_string(&slot - mSlots.data());
        slot.buffer = Buffer({.size = bytes, .flags = flags | GL_CLIENT_STORAGE_BIT, .debugName = name});
        slot.mapped = static_cast<const std::byte*>(
            glMapNamedBufferRange(slot.buffer.id(), 0, GLsizeiptr(bytes), flags));
        if (slot.mapped == nullptr)
            throw GlError("cannot map the read-back buffer '" + name + "' (" + std::to_string(bytes) +
                          " bytes)");
    }
    glBindBuffer(GL_PIXEL_PACK_BUFFER, slot.buffer.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    // With a pack buffer bound, the pointer argument is the offset into it.
    glGetTextureImage(texture.id(), 0, GL_RGBA, type, GLsizei(bytes), nullptr);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    // A coherent mapping shows what the GPU wrote once a fence after the write has signalled.
    slot.fence = Fence::insert();
    // Flushed so the GPU starts on it now, not when the CPU first waits.
    glFlush();
    slot.extent = extent;
    slot.type = type;
    ++mPending;
}

TextureReadback::Slot& TextureReadback::waitOldest(GLenum type) {
    if (mPending == 0)
        throw std::logic_error("TextureReadback '" + mName + "': finish() with no read started");
    Slot& slot = mSlots[mOldest];
    if (slot.type != type)
        throw std::logic_error("TextureReadback '" + mName +
                               "': finish() into another sample type than the "
                               "read was started with");
    slot.fence.wait();
    slot.fence = Fence();
    mOldest = (mOldest + 1) % mSlots.size();
    --mPending;
    return slot;
}

template <class Image>
void TextureReadback::copyOut(Image& image, GLenum type) {
    const Slot& slot = waitOldest(type);
    image.width = slot.extent.width;
    image.height = slot.extent.height;
    const std::size_t rowValues = std::size_t(image.width) * 4;
    image.rgba.resize(rowValues * std::size_t(image.height));
    const std::size_t rowBytes = rowValues * sizeof(image.rgba[0]);
    // GL's rows run bottom to top: the last packed row is the image's first.
    for (int y = 0; y < image.height; ++y) {
        std::memcpy(image.rgba.data() + std::size_t(y) * rowValues,
                    slot.mapped + std::size_t(image.height - 1 - y) * rowBytes, rowBytes);
    }
}

void TextureReadback::finish(Image8& image) {
    copyOut(image, GL_UNSIGNED_BYTE);
}

void TextureReadback::finish(Image16& image) {
    copyOut(image, GL_UNSIGNED_SHORT);
}

void TextureReadback::finish(ImageF& image) {
    copyOut(image, GL_FLOAT);
}

} // namespace photopic
