// gl/TextureReadback against the blocking reads of gl/TextureIo.h: the same values (or, packed by the shader,
// GL's specified conversions of the float read) for every sample type and texture format the CLI reads back
// (8-bit and 16-bit display images, scene-referred floats), at odd sizes, with reads in flight on every slot
// and the texture rewritten between a read's start and its finish (the read holds what the texture held at
// start()); the pack buffer is left unbound, a slot's buffer grows for a larger texture and is kept for a
// smaller one, and misuse is refused. The calls pass the audit of what NVIDIA's driver reports
// (GlCallAudit.h: no CPU read of a buffer's storage).

#include "GlCallAudit.h"
#include "GlTest.h"

#include "gl/Capabilities.h"
#include "gl/TextureIo.h"
#include "gl/TextureReadback.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace photopic {
namespace {

using test::GlTest;
using Pack = TextureReadback::Pack;

std::string packName(Pack pack) {
    return pack == Pack::Shader ? "shader" : "pixel path";
}

/// A texture of `format` holding random values over [-2, 70000) (clamped by unorm formats, rounded by 16F).
Texture randomTexture(Extent extent, GLenum format, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> uniform(-2.0f, 3.0f);
    ImageF image(extent.width, extent.height);
    for (float& v : image.rgba)
        v = random() % 64u == 0 ? 70000.0f : uniform(random);
    return makeTexture(image, "test.readback.source", format);
}

/// Whether `got` is what GLSL's packUnorm makes of `value` at `scale` (255 or 65535): clamped to [0, 1],
/// scaled, rounded to the nearest (a tie either way: GLSL leaves its direction to the implementation).
bool packsTo(float value, float scale, unsigned got) {
    const float x = std::clamp(value, 0.0f, 1.0f) * scale;
    const float below = std::floor(x);
    if (x - below == 0.5f)
        return got == unsigned(below) || got == unsigned(below) + 1u;
    return got == unsigned(std::lround(x));
}

/// The first sample of `got` (8 or 16 bits) that is not the shader pack of the float read `floats`, or -1.
template <class Samples>
long firstPackMismatch(const Samples& got, const ImageF& floats, float scale) {
    if (got.size() != floats.rgba.size())
        return 0;
    for (std::size_t i = 0; i < got.size(); ++i) {
        if (!packsTo(floats.rgba[i], scale, unsigned(got[i])))
            return long(i);
    }
    return -1;
}

/// The first float sample that differs from the blocking float read, or -1. A unorm texture's texels are
/// codes: the texture unit's code / (2^n - 1) and the driver's may be a rounding apart, so its samples
/// compare as the codes they stand for.
long firstFloatMismatch(const ImageF& got, const ImageF& want, GLenum format) {
    if (got.rgba.size() != want.rgba.size())
        return 0;
    const float scale = format == GL_RGBA8 ? 255.0f : format == GL_RGBA16 ? 65535.0f : 0.0f;
    for (std::size_t i = 0; i < got.rgba.size(); ++i) {
        const bool same = scale > 0.0f ? std::lround(got.rgba[i] * scale) == std::lround(want.rgba[i] * scale)
                                       : got.rgba[i] == want.rgba[i];
        if (!same)
            return long(i);
    }
    return -1;
}

// The pixel path is GL's own pack, so it holds the blocking reads' values to the bit. The shader path holds
// GLSL's conversions of the texels, which are what GL specifies for the pack (clamp, then round to nearest):
// NVIDIA's pixel pack leaves floats beyond 1 unclamped (1.66 as an unsigned short reads 43005, not 65535) and
// takes some 16-bit codes to the 8-bit code above the nearest, so the shader path is held to the float read
// and those rules instead.
TEST_F(GlTest, TextureReadbackGivesTheBlockingReadsValuesWithReadsInFlight) {
    struct Case {
        Extent extent;
        GLenum format;
    };
    // Odd widths: rows whose bytes are not a multiple of 16; RGBA8 and RGBA16 as the display images are;
    // 70000 among the values, which a unorm texture clamps and the 8- and 16-bit reads of a float one too.
    for (const Case c : {Case{{97, 61}, GL_RGBA8}, Case{{33, 17}, GL_RGBA16}, Case{{97, 61}, GL_RGBA16F},
                         Case{{20, 9}, GL_RGBA32F}, Case{{7, 3}, GL_R11F_G11F_B10F}}) {
        for (const Pack pack : {Pack::Shader, Pack::PixelPath}) {
            const std::string what = packName(pack) + " " + std::to_string(c.extent.width) + "x" +
                                     std::to_string(c.extent.height) + " format " + std::to_string(c.format);
            TextureReadback readback(2, "test", pack);
            const Texture a = randomTexture(c.extent, c.format, 1u);
            const Texture b = randomTexture(c.extent, c.format, 2u);
            const Image8 a8 = readTexture8(a);
            const ImageF aF = readTextureF(a);
            const bool shader = pack == Pack::Shader;
            {
                test::GlCallAudit audit;
                readback.start(a, GL_UNSIGNED_BYTE);
                readback.start(b, GL_UNSIGNED_SHORT);
                EXPECT_EQ(readback.pending(), 2) << what;
                EXPECT_THROW(readback.start(a, GL_FLOAT), std::logic_error) << what << ": every slot busy";
                // Rewritten after the read started: the read still holds what the texture held then.
                glClearTexImage(a.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
                Image8 got8;
                readback.finish(got8);
                EXPECT_EQ(got8.width, c.extent.width) << what;
                EXPECT_EQ(got8.height, c.extent.height) << what;
                if (shader)
                    EXPECT_EQ(firstPackMismatch(got8.rgba, aF, 255.0f), -1) << what << ": 8-bit";
                else
                    EXPECT_EQ(got8.rgba, a8.rgba) << what << ": 8-bit";
                // The freed slot takes the next read while the other is still pending.
                readback.start(b, GL_FLOAT);
                Image16 got16;
                readback.finish(got16);
                const ImageF bF = readTextureF(b);
                if (shader)
                    EXPECT_EQ(firstPackMismatch(got16.rgba, bF, 65535.0f), -1) << what << ": 16-bit";
                else
                    EXPECT_EQ(got16.rgba, readTexture16(b).rgba) << what << ": 16-bit";
                ImageF gotF;
                readback.finish(gotF);
                if (shader)
                    EXPECT_EQ(firstFloatMismatch(gotF, bF, c.format), -1) << what << ": float";
                else
                    EXPECT_EQ(gotF.rgba, bF.rgba) << what << ": float";
                EXPECT_EQ(readback.pending(), 0) << what;
                EXPECT_EQ(audit.directBufferReads(), 0) << what;
                EXPECT_TRUE(audit.problems().empty()) << what << ": " << audit.problems().front();
            }
        }
    }
}

TEST_F(GlTest, TextureReadbackGrowsItsBuffersAndRefusesMisuse) {
    for (const Pack pack : {Pack::Shader, Pack::PixelPath}) {
        TextureReadback readback(1, "test", pack);
        ImageF image;
        EXPECT_THROW(readback.finish(image), std::logic_error) << "no read started";
        // Small, then larger (the slot's buffer grows), then small again (the larger buffer is kept).
        for (const Extent extent : {Extent{8, 4}, Extent{64, 48}, Extent{5, 3}}) {
            const Texture texture = randomTexture(extent, GL_RGBA32F, unsigned(extent.width));
            readback.start(texture, GL_FLOAT);
            readback.finish(image);
            EXPECT_EQ(image.width, extent.width);
            EXPECT_EQ(image.height, extent.height);
            EXPECT_EQ(image.rgba, readTextureF(texture).rgba)
                << packName(pack) << " " << extent.width << "x" << extent.height;
        }
        // A texture a texel fetch would not read as stored is refused.
        const Texture srgb({.extent = {4, 4}, .format = GL_SRGB8_ALPHA8, .debugName = "test.srgb"});
        EXPECT_THROW(readback.start(srgb, GL_UNSIGNED_BYTE), std::logic_error);
        EXPECT_EQ(readback.pending(), 0);
        // A finish into another sample type than the read's is refused, and the read stays to be finished.
        const Texture texture = randomTexture({4, 4}, GL_RGBA8, 3u);
        readback.start(texture, GL_UNSIGNED_BYTE);
        Image16 wrongType;
        EXPECT_THROW(readback.finish(wrongType), std::logic_error);
        EXPECT_EQ(readback.pending(), 1);
        Image8 right;
        readback.finish(right);
        EXPECT_EQ(right.rgba, readTexture8(texture).rgba) << packName(pack);
    }
}

TEST_F(GlTest, TextureReadbackPacksWithTheShaderOnAGpuAndGlsPixelPathOnASoftwareRenderer) {
    EXPECT_EQ(TextureReadback(1, "test").pack(), isSoftwareRenderer() ? Pack::PixelPath : Pack::Shader);
}

TEST_F(GlTest, TextureReadbackPacksInBandsOfRowsWhereABindingIsSmallerThanTheImage) {
    // Bands of 1000 bytes: 2, 1 and 0 rows of these widths' (at least one row a band), bound from offsets
    // that the storage alignment rounds down, so a band's first row lies inside its binding.
    for (const Extent extent : {Extent{61, 37}, Extent{97, 13}, Extent{300, 5}}) {
        TextureReadback readback(1, "test.bands", Pack::Shader, 1000);
        const Texture texture = randomTexture(extent, GL_RGBA16F, unsigned(extent.width) + 5u);
        const std::string what = std::to_string(extent.width) + "x" + std::to_string(extent.height);
        readback.start(texture, GL_FLOAT);
        ImageF floats;
        readback.finish(floats);
        EXPECT_EQ(floats.rgba, readTextureF(texture).rgba) << what << ": float";
        readback.start(texture, GL_UNSIGNED_BYTE);
        Image8 bytes;
        readback.finish(bytes);
        EXPECT_EQ(bytes.rgba, readTexture8(texture).rgba) << what << ": 8-bit";
        readback.start(texture, GL_UNSIGNED_SHORT);
        Image16 shorts;
        readback.finish(shorts);
        EXPECT_EQ(shorts.rgba, readTexture16(texture).rgba) << what << ": 16-bit";
    }
}

} // namespace
} // namespace photopic
