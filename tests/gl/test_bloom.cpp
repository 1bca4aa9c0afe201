// Bloom on the GPU: radial symmetry, energy conservation, the threshold, and grading reaching the EXR output.

#include "GlTest.h"

#include "core/ColorGrading.h"
#include "gl/TextureIo.h"
#include "pipeline/Pipeline.h"

#include <cmath>

namespace photopic::test {

namespace {

/// A disc of `value` on black, centred on the image.
ImageF disc(int size, float radius, float value) {
    ImageF image(size, size);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            float* p = image.at(x, y);
            const float dx = float(x) + 0.5f - 0.5f * float(size), dy = float(y) + 0.5f - 0.5f * float(size);
            const float v = std::hypot(dx, dy) < radius ? value : 0.0f;
            p[0] = p[1] = p[2] = v;
            p[3] = 1;
        }
    }
    return image;
}

Settings bloomOnly() {
    Settings s;
    s.tonemapping.mode = ToneMapper::Linear;
    s.output.dither = false;
    s.bloom.mode = BloomMode::EnergyConserving;
    s.bloom.intensity = 1.0f; // mix(scene, bloom, 1): the output is the bloom image alone
    return s;
}

ImageF sceneOf(Pipeline& pipeline, const ImageF& image) {
    const Texture input = makeTexture(image, "bloom test input");
    pipeline.execute({.color = &input}, {});
    return readTextureF(pipeline.sceneReferred());
}

double sumRgb(const ImageF& image) {
    double sum = 0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        sum += double(image.rgba[i]) + image.rgba[i + 1] + image.rgba[i + 2];
    }
    return sum;
}

float bilinear(const ImageF& image, float x, float y, int ch) {
    // (x, y) in pixel units with centres at +0.5.
    const float fx = x - 0.5f, fy = y - 0.5f;
    const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
    const float tx = fx - float(x0), ty = fy - float(y0);
    auto at = [&](int px, int py) { return image.at(px, py)[ch]; };
    return (at(x0, y0) * (1 - tx) + at(x0 + 1, y0) * tx) * (1 - ty) +
           (at(x0, y0 + 1) * (1 - tx) + at(x0 + 1, y0 + 1) * tx) * ty;
}

} // namespace

TEST_F(GlTest, BrightDiscBloomsWithRadialSymmetry) {
    // 256 px and 5 levels (128 .. 8 texels): the coarsest level still has texels to spare around the disc; a
    // 2x2 level would be a bilinear square and no longer round. With the default radius (0.85) most of the
    // glow comes from levels blurred many times, which are close to Gaussian and so round; at radius 0.5 the
    // box-shaped first levels dominate and diagonals run ~8% brighter than axes.
    const int size = 256;
    Settings s = bloomOnly();
    s.bloom.mipCount = 5;
    Pipeline pipeline({.settings = s});
    const ImageF out = sceneOf(pipeline, disc(size, 3.0f, 1000.0f));
    const float c = 0.5f * float(size);
    for (float r : {8.0f, 14.0f, 24.0f}) {
        float values[8];
        for (int i = 0; i < 8; ++i) {
            const float a = float(i) * 0.78539816f;
            values[i] = bilinear(out, c + r * std::cos(a), c + r * std::sin(a), 1);
        }
        const float ref = values[0];
        ASSERT_GT(ref, 0.0f) << "no bloom at distance " << r;
        for (int i = 1; i < 8; ++i) {
            EXPECT_NEAR(values[i] / ref, 1.0f, 0.05f) << "distance " << r << " direction " << i;
        }
    }
}

TEST_F(GlTest, EnergyConservingBloomKeepsTheImageSum) {
    // A bright disc and a dim textured field. The Karis average on the first level down-weights boxes by
    // 1 / (1 + luma), so at a hard edge between very different values it moves some energy from the bright
    // side to the dark side's weight (it is meant to tame fireflies and does that by taking energy from
    // them): the sum holds within 2% for contrasts of a few stops, not for a lone firefly.
    // Energy that spreads past the image border is lost, so the image is large against the chain's reach.
    ImageF image = disc(256, 6.0f, 4.0f);
    for (int y = 0; y < 256; ++y) {
        for (int x = 0; x < 256; ++x) {
            image.at(x, y)[1] += 0.1f + 0.05f * float((x / 5 + y / 7) % 3);
        }
    }
    const float ev = -1.0f;
    for (float intensity : {0.04f, 0.5f}) {
        Settings s = bloomOnly();
        s.bloom.intensity = intensity;
        s.tonemapping.exposure = ev;
        Pipeline pipeline({.settings = s});
        const ImageF out = sceneOf(pipeline, image);
        const double exposedInput = sumRgb(image) * std::exp2(ev);
        EXPECT_NEAR(sumRgb(out) / exposedInput, 1.0, 0.02) << "intensity " << intensity;
    }
}

TEST_F(GlTest, ThresholdAboveEveryValueLeavesTheExposedInput) {
    ImageF image = disc(64, 6.0f, 8.0f);
    for (int y = 0; y < 64; ++y) {
        image.at(y, y)[0] = 0.3f;
    }
    Settings s = bloomOnly();
    s.bloom.mode = BloomMode::Threshold;
    s.bloom.intensity = 5.0f;
    s.bloom.threshold = 100.0f; // T - knee = 50 lies above every exposed value (16)
    s.tonemapping.exposure = 1.0f;
    Pipeline pipeline({.settings = s});
    const ImageF out = sceneOf(pipeline, image);
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            for (int ch = 0; ch < 3; ++ch) {
                // Exact up to the half-float storage of the sanitised input.
                ASSERT_NEAR(out.at(x, y)[ch], image.at(x, y)[ch] * 2.0f, 2e-3f * image.at(x, y)[ch] + 1e-6f)
                    << x << "," << y;
            }
        }
    }
}

TEST_F(GlTest, ThresholdModeBloomsOnlyWhatIsAboveThreshold) {
    Settings s = bloomOnly();
    s.bloom.mode = BloomMode::Threshold;
    s.bloom.intensity = 1.0f;
    s.bloom.threshold = 1.0f;
    Pipeline pipeline({.settings = s});
    const ImageF out = sceneOf(pipeline, disc(64, 3.0f, 100.0f));
    EXPECT_GT(out.at(32 + 10, 32)[1], 0.01f); // glare around the bright disc
    Pipeline dim({.settings = s});
    const ImageF dimOut = sceneOf(dim, disc(64, 3.0f, 0.4f)); // below T - knee: no glare at all
    EXPECT_EQ(dimOut.at(32 + 10, 32)[1], 0.0f);
}

TEST_F(GlTest, GradingMatchesCpuAndReachesTheExrOutput) {
    ImageF image(16, 1);
    for (int x = 0; x < 16; ++x) {
        float* p = image.at(x, 0);
        p[0] = 0.05f * float(x);
        p[1] = 0.02f * float(x) + 0.1f;
        p[2] = 0.3f;
        p[3] = 1;
    }
    Settings s;
    s.bloom.enabled = false;
    s.colorGrading = {.enabled = true,
                      .temperature = 0.3f,
                      .tint = -0.2f,
                      .contrast = 1.2f,
                      .saturation = 0.8f,
                      .lift = glm::vec3(0.01f),
                      .gamma = glm::vec3(1.1f),
                      .gain = glm::vec3(1.2f, 1.0f, 0.9f)};
    Pipeline pipeline({.settings = s});
    const ImageF out = sceneOf(pipeline, image);
    for (int x = 0; x < 16; ++x) {
        const float* p = image.at(x, 0);
        const glm::vec3 want = gradeColor({p[0], p[1], p[2]}, s.colorGrading);
        for (int ch = 0; ch < 3; ++ch) {
            EXPECT_NEAR(out.at(x, 0)[ch], want[ch], 2e-3f * want[ch] + 1e-4f) << x << " ch " << ch;
        }
    }
}

TEST_F(GlTest, LegacyTierGlowsAroundABrightDiscWithoutTheBloomChain) {
    // The legacy tier: no bloom chain, a single cheap glow of the bright parts. A disc of 20 on black:
    // with bloom.enabled the pixels just outside it light up, evenly left/right/up/down; without, they stay
    // 0.
    const int size = 96;
    const float radius = 6.0f;
    const ImageF image = disc(size, radius, 20.0f);
    Settings s;
    s.quality = Quality::Legacy;
    s.tonemapping.mode = ToneMapper::Linear;
    s.output.dither = false;
    s.bloom.mode = BloomMode::Threshold;
    s.bloom.intensity = 0.5f;
    Pipeline pipeline({.settings = s});
    ASSERT_EQ(pipeline.status().path, ColorPath::Ldr);
    const ImageF glow = sceneOf(pipeline, image);
    const float c = 0.5f * float(size), r = radius + 2.0f; // the ring's inner taps reach 2 px past the edge
    const float right = bilinear(glow, c + r, c, 1), left = bilinear(glow, c - r, c, 1);
    const float up = bilinear(glow, c, c + r, 1), down = bilinear(glow, c, c - r, 1);
    EXPECT_GT(right, 0.05f);
    for (const float v : {left, up, down}) {
        EXPECT_NEAR(v, right, 0.15f * right);
    }
    EXPECT_LT(bilinear(glow, 4.0f, 4.0f, 1), 1e-4f) << "the corner stays black";

    s.bloom.enabled = false;
    pipeline.setSettings(s);
    const ImageF none = sceneOf(pipeline, image);
    EXPECT_LT(bilinear(none, c + r, c, 1), 1e-4f) << "bloom.enabled=false turns the glow off";
    const Image8 display = processImage(pipeline, image);
    EXPECT_EQ(display.width, size);
}

} // namespace photopic::test
