// The CLI's streamed upload (apps/cli/InputTextures.cpp through gl/UploadRing.h) against a plain upload from
// client memory: each texture must hold the frame's floats as they are (the float textures) or rounded to
// the nearest half, ties to even (the half textures: core/HalfFloat.h's rounding, which the upload does on
// the CPU because drivers convert floats to halves each their own way), for a half-float colour frame (kept
// as halves, as the decoder keeps a half EXR's colour: to an RGBA16F texture as they are, to an RGBA32F one
// widened), a float one, an odd size, and the depth, normals and motion layers; over several frames in a row,
// so that the slot is reused once its fence has passed (and, on their own, a ring of two slots takes them in
// turn, each texture holding what was written for it); the unpack buffer binding is left as it was found,
// unbound; and the upload's calls pass the audit of what NVIDIA's driver reports (GlCallAudit.h: no CPU read
// of a buffer).

#include "ImageInputs.h"

#include "GlCallAudit.h"
#include "GlTest.h"

#include "core/HalfFloat.h"
#include "gl/Objects.h"
#include "gl/UploadRing.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <span>
#include <string>
#include <vector>

namespace photopic {
namespace {

using test::GlTest;

/// Colour values that are halves exactly (as an EXR of half channels decodes): normal, denormal, zero,
/// negative, the largest half and infinity.
float halfValue(std::mt19937& random) {
    switch (random() % 16u) {
    case 0:
        return halfToFloat(std::uint16_t(random() % 0x400u)); // a denormal (or zero)
    case 1:
        return -65504.0f;
    case 2:
        return std::numeric_limits<float>::infinity();
    case 3:
        return -0.0f;
    default:
        return halfToFloat(std::uint16_t(random() % 0x7c00u | ((random() & 1u) << 15)));
    }
}

/// Values that are not halves: they round, some exactly half-way between two halves (ties go to even).
float roundedValue(std::mt19937& random) {
    std::uniform_real_distribution<float> uniform(-2.0f, 2.0f);
    switch (random() % 8u) {
    case 0:
        return 1.0f + std::ldexp(1.0f, -11); // half-way between 1 and the next half: rounds down to 1
    case 1:
        return 1.0f + 3.0f * std::ldexp(1.0f, -11); // half-way, rounds up to even
    case 2:
        return 70000.0f; // beyond the largest half
    default:
        return uniform(random);
    }
}

cli::DecodedFrame makeFrame(int width, int height, bool halfColor, unsigned seed) {
    std::mt19937 random(seed);
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    cli::DecodedFrame frame;
    if (halfColor) { // as the decoder keeps a half EXR's colour: the halves as stored
        frame.colorHalves = ImageH{.width = width, .height = height, .rgba = {}};
        frame.colorHalves.rgba.resize(pixels * 4);
        for (std::uint16_t& v : frame.colorHalves.rgba)
            v = floatToHalf(halfValue(random));
    } else {
        frame.color = ImageF(width, height);
        for (float& v : frame.color.rgba)
            v = std::uniform_real_distribution<float>(-1e6f, 1e6f)(random);
    }
    frame.depth.resize(pixels);
    for (float& v : frame.depth)
        v = std::uniform_real_distribution<float>(0.1f, 1000.0f)(random);
    frame.depth[0] = std::numeric_limits<float>::infinity(); // the background
    frame.normals.resize(pixels * 3);
    for (float& v : frame.normals)
        v = roundedValue(random);
    frame.motion.resize(pixels * 2);
    for (float& v : frame.motion)
        v = roundedValue(random) * 0.01f;
    frame.camera = Camera{};
    return frame;
}

/// The texture the upload must give: `components` floats a pixel, one glTextureSubImage2D a row from client
/// memory, rows flipped; for a half texture the floats rounded to halves one at a time (floatToHalf of a
/// single value, not the runs the upload converts with) and uploaded as halves, which GL stores as they are.
Texture referenceTexture(const Texture& like, std::span<const float> values, int components) {
    const Extent extent = like.extent();
    Texture texture({.extent = extent, .format = like.format(), .debugName = "test.reference"});
    const std::size_t row = std::size_t(extent.width) * std::size_t(components);
    const GLenum format = components == 1 ? GL_RED : components == 2 ? GL_RG : GL_RGBA;
    const bool half = like.format() == GL_RGBA16F || like.format() == GL_RG16F;
    std::vector<std::uint16_t> halves(half ? row : 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    for (int y = 0; y < extent.height; ++y) {
        const float* source = values.data() + std::size_t(extent.height - 1 - y) * row;
        if (half) {
            for (std::size_t i = 0; i < row; ++i)
                halves[i] = floatToHalf(source[i]);
            glTextureSubImage2D(texture.id(), 0, 0, y, extent.width, 1, format, GL_HALF_FLOAT, halves.data());
        } else {
            glTextureSubImage2D(texture.id(), 0, 0, y, extent.width, 1, format, GL_FLOAT, source);
        }
    }
    return texture;
}

/// Level 0 as stored: halves for the 16F formats, floats for the 32F ones.
std::vector<std::uint8_t> texels(const Texture& texture) {
    const GLenum format = texture.format();
    const bool half = format == GL_RGBA16F || format == GL_RG16F;
    const int components = format == GL_R32F ? 1 : format == GL_RG16F ? 2 : 4;
    const std::size_t bytes = std::size_t(texture.extent().width) * std::size_t(texture.extent().height) *
                              std::size_t(components) * (half ? 2 : 4);
    std::vector<std::uint8_t> out(bytes);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(texture.id(), 0,
                      components == 1   ? GL_RED
                      : components == 2 ? GL_RG
                                        : GL_RGBA,
                      half ? GL_HALF_FLOAT : GL_FLOAT, GLsizei(bytes), out.data());
    return out;
}

/// The first texel that differs (NaNs, should any arise, count as equal whatever their payload), or -1.
long firstDifference(const Texture& actual, const Texture& expected) {
    const std::vector<std::uint8_t> a = texels(actual);
    const std::vector<std::uint8_t> e = texels(expected);
    if (a.size() != e.size())
        return 0;
    const bool half = actual.format() == GL_RGBA16F || actual.format() == GL_RG16F;
    const std::size_t step = half ? 2 : 4;
    for (std::size_t i = 0; i < a.size(); i += step) {
        float x = 0.0f;
        float y = 0.0f;
        if (half) {
            std::uint16_t hx = 0;
            std::uint16_t hy = 0;
            std::memcpy(&hx, a.data() + i, 2);
            std::memcpy(&hy, e.data() + i, 2);
            x = halfToFloat(hx);
            y = halfToFloat(hy);
        } else {
            std::memcpy(&x, a.data() + i, 4);
            std::memcpy(&y, e.data() + i, 4);
        }
        if (std::isnan(x) && std::isnan(y))
            continue;
        if (std::memcmp(a.data() + i, e.data() + i, step) != 0)
            return long(i / step);
    }
    return -1;
}

GLint unpackBufferBinding() {
    GLint bound = -1;
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &bound);
    return bound;
}

void expectSameAsGlConversion(cli::InputTextures& textures, const cli::DecodedFrame& frame, bool halfTexture,
                              const std::string& what) {
    std::optional<FrameInputs> uploaded;
    {
        // What NVIDIA's driver would report and llvmpipe does not: the mapping is for writing only.
        test::GlCallAudit audit;
        uploaded = textures.upload(frame, halfTexture);
        EXPECT_EQ(audit.directBufferReads(), 0) << what;
        EXPECT_TRUE(audit.problems().empty()) << what << ": " << audit.problems().front();
    }
    const FrameInputs& inputs = *uploaded;
    EXPECT_EQ(unpackBufferBinding(), 0) << what << ": the unpack buffer is left bound";
    ASSERT_TRUE(inputs.color && inputs.depth && inputs.normals && inputs.motion) << what;
    EXPECT_EQ(inputs.color->format(), GLenum(halfTexture && frame.halfColor() ? GL_RGBA16F : GL_RGBA32F));
    std::vector<float> color = frame.color.rgba;
    if (frame.halfColor()) {
        color.resize(frame.colorHalves.rgba.size());
        for (std::size_t i = 0; i < color.size(); ++i)
            color[i] = halfToFloat(frame.colorHalves.rgba[i]);
    }
    std::vector<float> normals(frame.normals.size() / 3 * 4, 0.0f);
    for (std::size_t i = 0, j = 0; i < frame.normals.size(); i += 3, j += 4)
        std::copy_n(frame.normals.data() + i, 3, normals.data() + j);
    EXPECT_EQ(firstDifference(*inputs.color, referenceTexture(*inputs.color, color, 4)), -1)
        << what << ": colour";
    EXPECT_EQ(firstDifference(*inputs.depth, referenceTexture(*inputs.depth, frame.depth, 1)), -1)
        << what << ": depth";
    EXPECT_EQ(firstDifference(*inputs.normals, referenceTexture(*inputs.normals, normals, 4)), -1)
        << what << ": normals";
    EXPECT_EQ(firstDifference(*inputs.motion, referenceTexture(*inputs.motion, frame.motion, 2)), -1)
        << what << ": motion";
}

TEST_F(GlTest, CliStreamedUploadMatchesGlConversionOverConsecutiveFrames) {
    struct Case {
        int width;
        int height;
        bool halfColor;
        bool halfTexture;
    };
    // Odd sizes: rows whose bytes are not a multiple of the converters' eight values or of 16 bytes.
    for (const Case c : {Case{97, 61, true, true}, Case{97, 61, false, false}, Case{64, 36, true, false},
                         Case{33, 17, true, true}}) {
        cli::InputTextures textures;
        // Three frames through the one slot, each written once the copies from the frame before are done.
        for (unsigned frame = 0; frame < 3; ++frame) {
            const std::string what = std::to_string(c.width) + "x" + std::to_string(c.height) +
                                     (c.halfColor ? " half" : " float") +
                                     (c.halfTexture ? " RGBA16F" : " RGBA32F") + " frame " +
                                     std::to_string(frame);
            expectSameAsGlConversion(textures, makeFrame(c.width, c.height, c.halfColor, 7u + frame),
                                     c.halfTexture, what);
        }
    }
}

TEST_F(GlTest, CliStreamedUploadLeavesTheUnpackBufferUnbound) {
    cli::InputTextures textures;
    cli::DecodedFrame frame = makeFrame(16, 8, true, 1u);
    frame.normals.clear();
    frame.motion.clear();
    (void)textures.upload(frame, true);
    EXPECT_EQ(unpackBufferBinding(), 0);
    // A client-memory upload after it reads client memory, not the ring's buffer.
    const std::vector<float> texel{0.25f, 0.5f, 0.75f, 1.0f};
    Texture scratch({.extent = {1, 1}, .format = GL_RGBA32F, .debugName = "test.scratch"});
    glTextureSubImage2D(scratch.id(), 0, 0, 0, 1, 1, GL_RGBA, GL_FLOAT, texel.data());
    std::vector<float> back(4);
    glGetTextureImage(scratch.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(back.size() * sizeof(float)), back.data());
    EXPECT_EQ(back, texel);
}

TEST_F(GlTest, UploadRingTakesItsSlotsInTurn) {
    // Five frames through two slots (the CLI uses one): the slots alternate, each written again only once
    // the copies from its previous frame are done, and every texture holds the texels written for it.
    const Extent extent{37, 11};
    const std::size_t bytes = std::size_t(extent.width) * std::size_t(extent.height) * 4 * sizeof(float);
    UploadRing ring(bytes, 2, "test.ring");
    ASSERT_EQ(ring.slotCount(), 2);
    std::vector<Texture> textures;
    std::vector<std::vector<std::uint8_t>> written;
    std::set<const std::byte*> slots;
    std::mt19937 random(5u);
    for (int frame = 0; frame < 5; ++frame) {
        const std::span<std::byte> slot = ring.begin();
        ASSERT_EQ(slot.size(), bytes);
        slots.insert(slot.data());
        std::vector<float> values(bytes / sizeof(float));
        for (float& v : values)
            v = std::uniform_real_distribution<float>(-100.0f, 100.0f)(random);
        std::memcpy(slot.data(), values.data(), bytes);
        written.emplace_back(bytes);
        std::memcpy(written.back().data(), values.data(), bytes);
        textures.emplace_back(
            TextureCreateInfo{.extent = extent, .format = GL_RGBA32F, .debugName = "test.ring.texture"});
        ring.upload(textures.back(), 0, GL_RGBA, GL_FLOAT);
        ring.end();
    }
    EXPECT_EQ(slots.size(), 2u);
    for (std::size_t frame = 0; frame < textures.size(); ++frame)
        EXPECT_EQ(texels(textures[frame]), written[frame]) << "frame " << frame;
    EXPECT_EQ(unpackBufferBinding(), 0);
}

} // namespace
} // namespace photopic
