// The GL textures a decoded frame is uploaded to (ImageInputs.h InputTextures), through one persistently
// mapped upload slot.
#include "ImageInputs.h"

#include "core/HalfFloat.h"
#include "gl/TextureIo.h"

#include <algorithm>
#include <cstring>
#include <utility>

namespace photopic::cli {

namespace {

/// Makes `texture` `extent` x `format` unless it already is.
void ensure(Texture& texture, Extent extent, GLenum format, std::string_view name) {
    if (!texture.valid() || texture.extent() != extent || texture.format() != format)
        texture = Texture({.extent = extent, .format = format, .debugName = name});
}

/// Where each layer's texels sit in an upload slot (offsets in bytes, each on a 256-byte boundary, so that
/// every layer starts on a cache line and a multiple of any value's size), and the bytes the slot needs.
struct SlotLayout {
    std::size_t color = 0;
    std::size_t depth = 0;
    std::size_t normals = 0;
    std::size_t motion = 0;
    std::size_t objectId = 0;
    std::size_t bytes = 0;
};

SlotLayout slotLayout(const DecodedFrame& frame, bool halfColor) {
    const std::size_t pixels = std::size_t(frame.width()) * std::size_t(frame.height());
    SlotLayout layout;
    const auto place = [&](std::size_t& offset, std::size_t texelBytes) {
        offset = layout.bytes;
        layout.bytes += (pixels * texelBytes + 255) / 256 * 256;
    };
    place(layout.color, halfColor ? 4 * sizeof(std::uint16_t) : 4 * sizeof(float));
    if (!frame.depth.empty())
        place(layout.depth, sizeof(float));
    if (!frame.normals.empty())
        place(layout.normals, 4 * sizeof(std::uint16_t));
    if (!frame.motion.empty())
        place(layout.motion, 2 * sizeof(std::uint16_t));
    if (!frame.objectId.empty())
        place(layout.objectId, sizeof(std::uint32_t));
    return layout;
}

// The writers below fill slot memory (write-only, front to back) with image rows bottom to top, GL's order,
// so that texel (x, y) is image pixel (x, height - 1 - y), as Texture::uploadRgba32f has it.

/// `components` values a pixel as they are: floats for a 32F texture (a float colour, the depth), halves for
/// a 16F one (a half colour).
template <class Value>
void copyRows(std::byte* out, const Value* values, Extent extent, int components) {
    const std::size_t row = std::size_t(extent.width) * std::size_t(components);
    for (int y = 0; y < extent.height; ++y) {
        std::memcpy(out + std::size_t(y) * row * sizeof(Value),
                    values + std::size_t(extent.height - 1 - y) * row, row * sizeof(Value));
    }
}

/// `components` floats a pixel as halves, rounded to nearest with ties to even (core/HalfFloat.h), for a
/// 16F texture: the motion. The rounding is
/// done here because GL's conversion of floats is the driver's own: Mesa's RGBA16F store rounds toward
/// zero and clamps, and NVIDIA's rounds floats from an unpack buffer otherwise than from client memory.
void writeHalfRows(std::byte* out, const float* values, Extent extent, int components) {
    const std::size_t row = std::size_t(extent.width) * std::size_t(components);
    auto* halves = reinterpret_cast<std::uint16_t*>(out);
    for (int y = 0; y < extent.height; ++y) {
        floatToHalf(values + std::size_t(extent.height - 1 - y) * row, halves + std::size_t(y) * row, row);
    }
}

/// RGBA halves widened to floats (exactly), for a 32F texture; `scratch` holds a row.
void writeHalvesAsFloatRows(std::byte* out, const std::uint16_t* halves, Extent extent,
                            std::vector<float>& scratch) {
    const std::size_t row = std::size_t(extent.width) * 4;
    scratch.resize(row);
    for (int y = 0; y < extent.height; ++y) {
        // Widened in cached memory, then copied: the slot may be write-combined.
        halfToFloat(halves + std::size_t(extent.height - 1 - y) * row, scratch.data(), row);
        std::memcpy(out + std::size_t(y) * row * sizeof(float), scratch.data(), row * sizeof(float));
    }
}

/// Object ids stored as floats (Cycles' IndexOB) as unsigned integers, rounded; negative or non-finite: 0.
void writeIdRows(std::byte* out, const float* ids, Extent extent) {
    const std::size_t width = std::size_t(extent.width);
    for (int y = 0; y < extent.height; ++y) {
        const float* row = ids + std::size_t(extent.height - 1 - y) * width;
        for (std::size_t x = 0; x < width; ++x) {
            const float id = row[x];
            const std::uint32_t value =
                id >= 0.5f && id < 4.0e9f ? std::uint32_t(std::lround(double(id))) : 0u;
            std::memcpy(out + (std::size_t(y) * width + x) * sizeof(value), &value, sizeof(value));
        }
    }
}

/// Three floats a pixel as four halves (alpha 0), rounded as writeHalfRows rounds; `scratch` holds a row.
void writeNormalRows(std::byte* out, const float* normals, Extent extent,
                     std::vector<std::uint16_t>& scratch) {
    const std::size_t width = std::size_t(extent.width);
    scratch.resize(width * 3);
    auto* texel = reinterpret_cast<std::uint16_t*>(out);
    for (int y = 0; y < extent.height; ++y) {
        floatToHalf(normals + std::size_t(extent.height - 1 - y) * width * 3, scratch.data(), width * 3);
        for (std::size_t x = 0; x < width; ++x, texel += 4) {
            const std::uint16_t four[4] = {scratch[3 * x], scratch[3 * x + 1], scratch[3 * x + 2], 0};
            std::memcpy(texel, four, sizeof(four));
        }
    }
}

} // namespace

std::byte* InputTextures::beginSlot(std::size_t bytes) {
    // Made anew when a frame needs more, or under half of it (a sequence whose later frames lack a layer).
    if (!mRing.valid() || mRing.bytes() < bytes || bytes < mRing.bytes() / 2) {
        mRing = UploadRing(); // the old slot goes first: never both at once
        mRing = UploadRing(bytes, kUploadSlots, "cli.input");
    }
    return mRing.begin().data();
}

void InputTextures::releaseMissingLayers(const DecodedFrame& frame) {
    for (auto [texture, present] :
         {std::pair{&mDepth, !frame.depth.empty()}, std::pair{&mNormals, !frame.normals.empty()},
          std::pair{&mMotion, !frame.motion.empty()}, std::pair{&mObjectId, !frame.objectId.empty()}}) {
        if (!present && texture->valid())
            *texture = Texture();
    }
}

FrameInputs InputTextures::upload(const DecodedFrame& frame, bool halfTexture) {
    const Extent extent{frame.width(), frame.height()};
    const bool halfColor = halfTexture && frame.halfColor();
    const SlotLayout layout = slotLayout(frame, halfColor);
    std::byte* slot = beginSlot(layout.bytes);
    FrameInputs inputs{.color = &mColor};

    ensure(mColor, extent, halfColor ? GL_RGBA16F : GL_RGBA32F, "cli.input.color");
    if (halfColor) {
        copyRows(slot + layout.color, frame.colorHalves.rgba.data(), extent, 4);
        mRing.upload(mColor, layout.color, GL_RGBA, GL_HALF_FLOAT);
    } else {
        if (frame.halfColor())
            writeHalvesAsFloatRows(slot + layout.color, frame.colorHalves.rgba.data(), extent, mFloatRow);
        else
            copyRows(slot + layout.color, frame.color.rgba.data(), extent, 4);
        mRing.upload(mColor, layout.color, GL_RGBA, GL_FLOAT);
    }
    if (!frame.depth.empty()) {
        ensure(mDepth, extent, GL_R32F, "cli.input.depth");
        copyRows(slot + layout.depth, frame.depth.data(), extent, 1);
        mRing.upload(mDepth, layout.depth, GL_RED, GL_FLOAT);
        inputs.depth = &mDepth;
        inputs.depthKind = DepthKind::LinearView;
    }
    if (!frame.normals.empty()) {
        ensure(mNormals, extent, GL_RGBA16F, "cli.input.normals");
        writeNormalRows(slot + layout.normals, frame.normals.data(), extent, mHalfRow);
        mRing.upload(mNormals, layout.normals, GL_RGBA, GL_HALF_FLOAT);
        inputs.normals = &mNormals;
        inputs.normalEncoding = NormalEncoding::ViewXyz;
    }
    if (!frame.motion.empty()) {
        ensure(mMotion, extent, GL_RG16F, "cli.input.motion");
        writeHalfRows(slot + layout.motion, frame.motion.data(), extent, 2);
        mRing.upload(mMotion, layout.motion, GL_RG, GL_HALF_FLOAT);
        inputs.motion = &mMotion;
    }
    if (!frame.objectId.empty()) {
        ensure(mObjectId, extent, GL_R32UI, "cli.input.objectId");
        writeIdRows(slot + layout.objectId, frame.objectId.data(), extent);
        mRing.upload(mObjectId, layout.objectId, GL_RED_INTEGER, GL_UNSIGNED_INT);
        inputs.objectId = &mObjectId;
    }
    mRing.end();
    releaseMissingLayers(frame);
    if (frame.camera) {
        mCamera = *frame.camera;
        inputs.camera = &mCamera;
    }
    inputs.sunDirection = frame.sunDirection;
    return inputs;
}

} // namespace photopic::cli
