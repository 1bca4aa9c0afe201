// Pipeline v0 behaviour on the GPU: sanitising, exposure, the output transform, the LDR path, adopted
// textures.

#include "GlTest.h"

#include "core/Color.h"
#include "gl/Capabilities.h"
#include "gl/TextureIo.h"
#include "pipeline/Pipeline.h"

#include <cmath>
#include <limits>

namespace photopic::test {

namespace {

ImageF uniformImage(int w, int h, float value) {
    ImageF image(w, h, value);
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) {
        image.rgba[i] = 1;
    }
    return image;
}

Settings linearNoDither(float exposureEV = 0) {
    Settings s;
    s.tonemapping.mode = ToneMapper::Linear;
    s.tonemapping.exposure = exposureEV;
    s.output.dither = false;
    s.bloom.enabled = false; // on by default; with every optional effect off the chain is exposure + curve
    return s;
}

} // namespace

TEST_F(GlTest, ContextIsOpenGL45Core) {
    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_TRUE(major > 4 || (major == 4 && minor >= 5)) << major << "." << minor;
    EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
    EXPECT_FALSE(glContext()->info().renderer.empty());
    EXPECT_FALSE(glContext()->info().platform.empty());
}

TEST_F(GlTest, CapabilitiesChooseHdrUnlessForced) {
    const Capabilities caps = detectCapabilities();
    EXPECT_TRUE(caps.rgba16fRenderable); // llvmpipe and every desktop GPU render to RGBA16F
    EXPECT_EQ(caps.path, ColorPath::Hdr);
    const Capabilities forced = detectCapabilities(true);
    EXPECT_EQ(forced.path, ColorPath::Ldr);
    EXPECT_NE(forced.pathReason.find("forced"), std::string::npos);
}

TEST_F(GlTest, NaNPixelBecomesBlackAndLeavesNeighboursAlone) {
    ImageF image = uniformImage(9, 9, 0.25f);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    image.at(4, 4)[0] = nan;
    image.at(4, 4)[1] = nan;
    image.at(4, 4)[2] = nan;
    image.at(1, 1)[0] = inf; // +Inf in one channel: that channel becomes 0
    image.at(7, 7)[2] = -inf;
    image.at(7, 1)[1] = -3.0f; // negative -> 0
    Pipeline pipeline({.settings = linearNoDither()});
    const Texture input = makeTexture(image, "nan input");
    pipeline.execute({.color = &input}, {});
    const ImageF scene = readTextureF(pipeline.sceneReferred());
    const float* centre = scene.at(4, 4);
    EXPECT_EQ(centre[0], 0.0f);
    EXPECT_EQ(centre[1], 0.0f);
    EXPECT_EQ(centre[2], 0.0f);
    EXPECT_EQ(scene.at(1, 1)[0], 0.0f);
    EXPECT_EQ(scene.at(7, 7)[2], 0.0f);
    EXPECT_EQ(scene.at(7, 1)[1], 0.0f);
    for (auto [x, y] : {std::pair{3, 4}, {5, 4}, {4, 3}, {4, 5}, {3, 3}, {5, 5}}) {
        for (int ch = 0; ch < 3; ++ch) {
            EXPECT_FLOAT_EQ(scene.at(x, y)[ch], 0.25f) << x << "," << y;
        }
    }
}

TEST_F(GlTest, HugeValuesAreClampedBelowHalfMax) {
    ImageF image = uniformImage(4, 4, 1e30f);
    Pipeline pipeline({.settings = linearNoDither()});
    const Texture input = makeTexture(image, "huge input");
    pipeline.execute({.color = &input}, {});
    const ImageF scene = readTextureF(pipeline.sceneReferred());
    EXPECT_TRUE(std::isfinite(scene.at(0, 0)[0]));
    EXPECT_LT(scene.at(0, 0)[0], 65504.0f);
    EXPECT_GT(scene.at(0, 0)[0], 60000.0f);
}

TEST_F(GlTest, LinearModeIsSrgbOfClampedExposedInput) {
    // Proof that there is no hidden second tone mapping or gamma: linear + no dither == sRGB(clamp(x *
    // 2^EV)).
    ImageF image(64, 1);
    for (int x = 0; x < 64; ++x) {
        float* p = image.at(x, 0);
        p[0] = float(x) / 50.0f;
        p[1] = float(x) / 100.0f;
        p[2] = float(63 - x) / 63.0f;
        p[3] = 1;
    }
    const float ev = 0.5f;
    Pipeline pipeline({.settings = linearNoDither(ev)});
    const Image8 out = processImage(pipeline, image);
    for (int x = 0; x < 64; ++x) {
        for (int ch = 0; ch < 3; ++ch) {
            const float v = std::clamp(image.at(x, 0)[ch] * std::exp2(ev), 0.0f, 1.0f);
            EXPECT_NEAR(out.at(x, 0)[ch], std::lround(srgbEncode(v) * 255.0f), 1) << x << " ch " << ch;
        }
    }
}

TEST_F(GlTest, DitherIsTpdfOfOneCodeValueAndDeterministic) {
    const ImageF image = uniformImage(64, 64, 0.2f);
    Settings s = linearNoDither();
    s.output.dither = true;
    Pipeline pipeline({.settings = s});
    const Image8 a = processImage(pipeline, image, {.dt = 0.1f, .frameIndex = 3});
    const Image8 b = processImage(pipeline, image, {.dt = 0.1f, .frameIndex = 3});
    const Image8 c = processImage(pipeline, image, {.dt = 0.1f, .frameIndex = 4});
    EXPECT_EQ(a.rgba, b.rgba);
    EXPECT_NE(a.rgba, c.rgba);
    const double exact = srgbEncode(0.2f) * 255.0;
    double sum = 0;
    int minV = 255, maxV = 0;
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            const int v = a.at(x, y)[1];
            sum += v;
            minV = std::min(minV, v);
            maxV = std::max(maxV, v);
        }
    }
    EXPECT_NEAR(sum / (64 * 64), exact, 0.1); // dither is unbiased
    EXPECT_GE(minV, int(std::floor(exact)) - 1);
    EXPECT_LE(maxV, int(std::ceil(exact)) + 1);
    EXPECT_GT(maxV, minV);
}

TEST_F(GlTest, DitherIsTriangularAndIndependentBetweenChannels) {
    // On a value that is exactly a code, triangular noise of +-1 code rounds to the code below or above with
    // probability 1/8 each (the tails past half a code: (1/2)^2 / 2); rectangular noise of the same width would
    // give 1/4 each, no noise never. 16,384 pixels: a count's standard deviation is under 0.3 percentage points.
    constexpr int kSize = 128;
    const ImageF image = uniformImage(kSize, kSize, srgbDecode(128.0f / 255.0f));
    Settings s = linearNoDither();
    s.output.dither = true;
    Pipeline pipeline({.settings = s});
    const Image8 out = processImage(pipeline, image, {.dt = 0.1f, .frameIndex = 9});
    const double n = kSize * kSize;
    double mean[3] = {}, product = 0;
    for (int ch = 0; ch < 3; ++ch) {
        int below = 0, at = 0, above = 0;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                const int v = out.at(x, y)[ch];
                below += v == 127 ? 1 : 0;
                at += v == 128 ? 1 : 0;
                above += v == 129 ? 1 : 0;
                mean[ch] += v - 128;
            }
        }
        EXPECT_EQ(below + at + above, kSize * kSize) << "channel " << ch << ": beyond one code";
        EXPECT_NEAR(below / n, 0.125, 0.015) << "channel " << ch;
        EXPECT_NEAR(above / n, 0.125, 0.015) << "channel " << ch;
        mean[ch] /= n;
    }
    // Channels dithered alike would tint the noise: the red and green offsets are uncorrelated.
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            product += (out.at(x, y)[0] - 128 - mean[0]) * (out.at(x, y)[1] - 128 - mean[1]);
        }
    }
    const double variance = 0.25; // (1/8 + 1/8) codes^2
    EXPECT_LT(std::abs(product / n / variance), 0.05);
}

TEST_F(GlTest, ForcedLdrPathRendersTheSameImageWithoutHdrTargets) {
    ImageF image(32, 8);
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 32; ++x) {
            float* p = image.at(x, y);
            p[0] = p[1] = p[2] = float(x * x) / 64.0f;
            p[3] = 1;
        }
    }
    Settings s;
    s.output.dither = false;
    s.bloom.enabled = false; // the LDR path has no bloom
    Pipeline hdr({.settings = s});
    Pipeline ldr({.settings = s, .forceLdr = true});
    EXPECT_EQ(ldr.capabilities().path, ColorPath::Ldr);
    const Image8 a = processImage(hdr, image);
    const Image8 b = processImage(ldr, image);
    for (std::size_t i = 0; i < a.rgba.size(); ++i) {
        ASSERT_LE(std::abs(int(a.rgba[i]) - int(b.rgba[i])), 1) << i;
    }
}

TEST_F(GlTest, AdoptedHostTextureIsNotDeleted) {
    GLuint host = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &host);
    glTextureStorage2D(host, 1, GL_RGBA16F, 8, 8);
    {
        const Texture adopted = Texture::adopt(host, {8, 8}, GL_RGBA16F);
        Pipeline pipeline;
        pipeline.execute({.color = &adopted}, {});
    }
    EXPECT_TRUE(glIsTexture(host));
    glDeleteTextures(1, &host);
}

} // namespace photopic::test
