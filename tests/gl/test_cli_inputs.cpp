// The CLI's input upload (apps/cli/InputTextures.cpp): what reaches the GL textures, and that a sequence
// creates its textures for the first frame only.

#include "ImageInputs.h"

#include "GlTest.h"

#include "gl/Objects.h"

#include <vector>

namespace photopic {
namespace {

using test::GlTest;

cli::DecodedFrame makeFrame(int width, int height, int index) {
    cli::DecodedFrame frame;
    frame.color = ImageF(width, height, 0.5f + float(index));
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    frame.depth.resize(pixels);
    frame.normals.assign(pixels * 3, 0.0f);
    frame.motion.resize(pixels * 2);
    for (std::size_t i = 0; i < pixels; ++i) {
        frame.depth[i] = 1.0f + float(i) + float(index);
        frame.normals[i * 3 + 2] = 1.0f;
        frame.motion[i * 2 + 0] = 0.25f;
        frame.motion[i * 2 + 1] = -0.125f * float(index);
    }
    frame.camera = Camera{};
    frame.camera->cut = index == 0;
    return frame;
}

std::vector<float> readRed(const Texture& texture) {
    std::vector<float> values(std::size_t(texture.extent().width) * std::size_t(texture.extent().height));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(texture.id(), 0, GL_RED, GL_FLOAT, GLsizei(values.size() * sizeof(float)),
                      values.data());
    return values;
}

TEST_F(GlTest, CliInputUploadCreatesTexturesForTheFirstFrameOnly) {
    constexpr int kWidth = 16;
    constexpr int kHeight = 8;
    cli::InputTextures textures;
    GlObjectCounts afterFirst;
    for (int i = 0; i < 10; ++i) {
        const cli::DecodedFrame frame = makeFrame(kWidth, kHeight, i);
        const FrameInputs inputs = textures.upload(frame);
        ASSERT_NE(inputs.color, nullptr);
        ASSERT_NE(inputs.depth, nullptr);
        ASSERT_NE(inputs.normals, nullptr);
        ASSERT_NE(inputs.motion, nullptr);
        ASSERT_NE(inputs.camera, nullptr);
        EXPECT_EQ(inputs.depthKind, DepthKind::LinearView);
        EXPECT_EQ(inputs.normalEncoding, NormalEncoding::ViewXyz);
        EXPECT_EQ(inputs.depth->format(), GLenum(GL_R32F));
        EXPECT_EQ(inputs.normals->format(), GLenum(GL_RGBA16F));
        EXPECT_EQ(inputs.motion->format(), GLenum(GL_RG16F));
        EXPECT_EQ(inputs.camera->cut, i == 0);
        // Rows are flipped on upload: texel row 0 (GL's bottom) holds the image's last row.
        const std::vector<float> depth = readRed(*inputs.depth);
        EXPECT_EQ(depth[0], frame.depth[std::size_t(kHeight - 1) * kWidth]);
        EXPECT_EQ(depth.back(), frame.depth[kWidth - 1]);
        if (i == 0)
            afterFirst = glObjectCounts();
        else
            EXPECT_EQ(glObjectCounts(), afterFirst) << "frame " << i << " created GL objects";
    }
    // A new extent makes new textures.
    (void)textures.upload(makeFrame(kWidth * 2, kHeight, 0));
    EXPECT_GT(glObjectCounts().textures, afterFirst.textures);
}

} // namespace
} // namespace photopic
