#include "gl/TextureReadback.h"

#include "gl/Capabilities.h"
#include "gl/ShaderLibrary.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace photopic {

namespace {
constexpr const char* kPack = "gl/texture_pack.comp.glsl";
constexpr int kGroup = 8; // the shader's local size, both axes

std::size_t sampleBytes(GLenum type) {
    switch (type) {
    case GL_UNSIGNED_BYTE:
        return 1;
    case GL_UNSIGNED_SHORT:
        return 2;
    case GL_FLOAT:
        return 4;
    default:
        throw std::logic_error("TextureReadback: the sample type is not GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT "
                               "or GL_FLOAT");
    }
}

/// Formats a texel fetch reads as glGetTextureImage converts them: unsigned normalised and float colour.
bool packable(GLenum format) {
    switch (format) {
    case GL_R8:
    case GL_RG8:
    case GL_RGBA8:
    case GL_RGBA16:
    case GL_R16F:
    case GL_RG16F:
    case GL_RGB16F:
    case GL_RGBA16F:
    case GL_R32F:
    case GL_RG32F:
    case GL_RGBA32F:
    case GL_R11F_G11F_B10F:
    case GL_RGB10_A2:
        return true;
    default:
        return false;
    }
}

std::size_t maxStorageBlockBytes() {
    GLint64 bytes = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &bytes);
    return std::size_t(std::max<GLint64>(bytes, 1 << 27)); // GL 4.5's minimum, 128 MiB
}

std::size_t storageOffsetAlignment() {
    GLint alignment = 0;
    glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &alignment);
    return std::size_t(std::max(alignment, 4));
}
} // namespace

TextureReadback::TextureReadback(int slots, std::string_view debugName, Pack pack, std::size_t bandBytes)
    : mSlots(std::size_t(std::max(slots, 1)))
    , mName(debugName)
    , mPack(pack != Pack::Auto     ? pack
            : isSoftwareRenderer() ? Pack::PixelPath
                                   : Pack::Shader)
    , mBandBytes(bandBytes) {}

void TextureReadback::start(const Texture& texture, GLenum type) {
    const std::size_t sample = sampleBytes(type);
    if (!packable(texture.format()))
        throw std::logic_error("TextureReadback '" + mName + "': cannot pack a " +
                               std::string(formatName(texture.format())) + " texture");
    if (mPending == slotCount())
        throw std::logic_error("TextureReadback '" + mName + "': every slot holds a read not yet finished");
    Slot& slot = mSlots[(mOldest + std::size_t(mPending)) % mSlots.size()];
    const Extent extent = texture.extent();
    const std::size_t rowBytes = std::size_t(extent.width) * 4 * sample;
    const std::size_t bytes = rowBytes * std::size_t(extent.height);
    if (slot.buffer.size() < bytes) {
        // Client storage: the GPU writes the packed samples into memory the CPU reads cached, once each.
        const GLbitfield flags = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
        const std::string name = mName + " readback " + std::to_string(&slot - mSlots.data());
        slot.buffer = Buffer({.size = bytes, .flags = flags | GL_CLIENT_STORAGE_BIT, .debugName = name});
        slot.mapped = slot.buffer.mapPersistently(flags, "the read-back buffer '" + name + "'");
    }
    if (mPack == Pack::Shader) {
        packWithShader(texture, slot, sample);
    } else {
        glBindBuffer(GL_PIXEL_PACK_BUFFER, slot.buffer.id());
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        // With a pack buffer bound, the pointer argument is the offset into it.
        glGetTextureImage(texture.id(), 0, GL_RGBA, type, GLsizei(bytes), nullptr);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    }
    // A coherent mapping shows what the GPU wrote once a fence after the write has signalled (after a
    // shader's stores, once it has also passed this barrier).
    glMemoryBarrier(GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
    slot.fence = Fence::insert();
    // Flushed so the GPU starts on it now, not when the CPU first waits.
    glFlush();
    slot.extent = extent;
    slot.type = type;
    ++mPending;
}

void TextureReadback::packWithShader(const Texture& texture, const Slot& slot, std::size_t sample) {
    const Extent extent = texture.extent();
    const std::size_t rowBytes = std::size_t(extent.width) * 4 * sample;
    Program& program = mPrograms[sample == 1 ? 0 : sample == 2 ? 1 : 2];
    if (!program.valid())
        program = makeComputeProgram(kPack, {{"SAMPLE_BYTES", std::to_string(sample)}});
    program.use();
    glBindTextureUnit(0, texture.id());
    glProgramUniform2i(program.id(), 0, extent.width, extent.height);

    // Bands of texel rows whose share of the buffer one storage binding reaches; texel rows [r0, r1) are the
    // image's rows [height - r1, height - r0), contiguous in the buffer, bound from an aligned offset at or
    // before their first byte.
    const std::size_t alignment = storageOffsetAlignment();
    const std::size_t limit = mBandBytes > 0 ? mBandBytes : maxStorageBlockBytes();
    const int bandRows = int(std::max<std::size_t>((limit - std::min(limit, alignment)) / rowBytes, 1));
    for (int r0 = 0; r0 < extent.height; r0 += bandRows) {
        const int r1 = std::min(r0 + bandRows, extent.height);
        const std::size_t first = std::size_t(extent.height - r1) * rowBytes;
        const std::size_t base = first - first % alignment;
        glProgramUniform1i(program.id(), 1, r0);
        glProgramUniform1i(program.id(), 2, r1 - r0);
        glProgramUniform1ui(program.id(), 3, GLuint(base / 4));
        glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 0, slot.buffer.id(), GLintptr(base),
                          GLsizeiptr(first - base + std::size_t(r1 - r0) * rowBytes));
        glDispatchCompute(GLuint((extent.width + kGroup - 1) / kGroup),
                          GLuint((r1 - r0 + kGroup - 1) / kGroup), 1);
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
    glUseProgram(0);
}

TextureReadback::Slot& TextureReadback::waitOldest(GLenum type) {
    if (mPending == 0)
        throw std::logic_error("TextureReadback '" + mName + "': finish() with no read started");
    Slot& slot = mSlots[mOldest];
    if (slot.type != type)
        throw std::logic_error("TextureReadback '" + mName +
                               "': finish() into another sample type than the read was started with");
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
    if (mPack == Pack::Shader) {
        std::memcpy(image.rgba.data(), slot.mapped, image.rgba.size() * sizeof(image.rgba[0]));
        return;
    }
    // GL's pack gives rows bottom to top: its last row is the image's first.
    const std::size_t rowBytes = rowValues * sizeof(image.rgba[0]);
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
