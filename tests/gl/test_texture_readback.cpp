// gl/TextureReadback against the blocking reads of gl/TextureIo.h: the same values for every sample type and
// texture format the CLI reads back (8-bit and 16-bit display images, scene-referred floats), at odd sizes,
// with reads in flight on every slot and the texture rewritten between a read's start and its finish (the
// read holds what the texture held at start()); the pack buffer is left unbound, a slot's buffer grows for a
// larger texture and is kept for a smaller one, and misuse is refused. The calls pass the audit of what
// NVIDIA's driver reports (GlCallAudit.h: no CPU read of a buffer's storage).

#include "GlCallAudit.h"
#include "GlTest.h"

#include "gl/TextureIo.h"
#include "gl/TextureReadback.h"

#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace photopic {
namespace {

using test::GlTest;

/// A texture of `format` holding random values over [-2, 70000) (clamped by unorm formats, rounded by 16F).
Texture randomTexture(Extent extent, GLenum format, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> uniform(-2.0f, 3.0f);
    ImageF image(extent.width, extent.height);
    for (float& v : image.rgba)
        v = random() % 64u == 0 ? 70000.0f : uniform(random);
    return makeTexture(image, "test.readback.source", format);
}

GLint packBufferBinding() {
    GLint bound = -1;
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &bound);
    return bound;
}

TEST_F(GlTest, TextureReadbackGivesTheBlockingReadsValuesWithReadsInFlight) {
    struct Case {
        Extent extent;
        GLenum format;
    };
    // Odd widths: rows whose bytes are not a multiple of 16; RGBA8 and RGBA16 as the display images are.
    for (const Case c : {Case{{97, 61}, GL_RGBA8}, Case{{33, 17}, GL_RGBA16}, Case{{97, 61}, GL_RGBA16F},
                         Case{{20, 9}, GL_RGBA32F}}) {
        const std::string what = std::to_string(c.extent.width) + "x" + std::to_string(c.extent.height) +
                                 " format " + std::to_string(c.format);
        TextureReadback readback(2, "test");
        const Texture a = randomTexture(c.extent, c.format, 1u);
        const Texture b = randomTexture(c.extent, c.format, 2u);
        const Image8 a8 = readTexture8(a);
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
            EXPECT_EQ(got8.rgba, a8.rgba) << what << ": 8-bit";
            // The freed slot takes the next read while the other is still pending.
            readback.start(b, GL_FLOAT);
            Image16 got16;
            readback.finish(got16);
            EXPECT_EQ(got16.rgba, readTexture16(b).rgba) << what << ": 16-bit";
            ImageF gotF;
            readback.finish(gotF);
            EXPECT_EQ(gotF.rgba, readTextureF(b).rgba) << what << ": float";
            EXPECT_EQ(readback.pending(), 0) << what;
            EXPECT_EQ(audit.directBufferReads(), 0) << what;
            EXPECT_TRUE(audit.problems().empty()) << what << ": " << audit.problems().front();
        }
        EXPECT_EQ(packBufferBinding(), 0) << what << ": the pack buffer is left bound";
    }
}

TEST_F(GlTest, TextureReadbackGrowsItsBuffersAndRefusesMisuse) {
    TextureReadback readback(1, "test");
    ImageF image;
    EXPECT_THROW(readback.finish(image), std::logic_error) << "no read started";
    // Small, then larger (the slot's buffer grows), then small again (the larger buffer is kept).
    for (const Extent extent : {Extent{8, 4}, Extent{64, 48}, Extent{5, 3}}) {
        const Texture texture = randomTexture(extent, GL_RGBA32F, unsigned(extent.width));
        readback.start(texture, GL_FLOAT);
        readback.finish(image);
        EXPECT_EQ(image.width, extent.width);
        EXPECT_EQ(image.height, extent.height);
        EXPECT_EQ(image.rgba, readTextureF(texture).rgba) << extent.width << "x" << extent.height;
    }
    // A finish into another sample type than the read's is refused, and the read stays to be finished.
    const Texture texture = randomTexture({4, 4}, GL_RGBA8, 3u);
    readback.start(texture, GL_UNSIGNED_BYTE);
    Image16 wrongType;
    EXPECT_THROW(readback.finish(wrongType), std::logic_error);
    EXPECT_EQ(readback.pending(), 1);
    Image8 right;
    readback.finish(right);
    EXPECT_EQ(right.rgba, readTexture8(texture).rgba);
}

} // namespace
} // namespace photopic
