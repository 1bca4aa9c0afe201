// Bloom on the GPU: every step of the chain against its CPU twin, radial symmetry, energy conservation, the
// threshold, and grading reaching the EXR output.

#include "GlTest.h"
#include "PointGlow.h"

#include "core/Bloom.h"
#include "core/Color.h"
#include "core/ColorGrading.h"
#include "gl/Capabilities.h"
#include "gl/ShaderLibrary.h"
#include "gl/TextureIo.h"
#include "passes/Bindings.h"
#include "passes/bloom/BloomPass.h"
#include "passes/tonemap/TonemapPass.h"
#include "pipeline/Pipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

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

float bilinear(const ImageF& image, float x, float y, int ch) {
    // (x, y) in pixel units with centres at +0.5; texels past the edge repeat the edge (GL_CLAMP_TO_EDGE).
    const float fx = x - 0.5f, fy = y - 0.5f;
    const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
    const float tx = fx - float(x0), ty = fy - float(y0);
    auto at = [&](int px, int py) {
        return image.at(std::clamp(px, 0, image.width - 1), std::clamp(py, 0, image.height - 1))[ch];
    };
    return (at(x0, y0) * (1 - tx) + at(x0 + 1, y0) * tx) * (1 - ty) +
           (at(x0, y0 + 1) * (1 - tx) + at(x0 + 1, y0 + 1) * tx) * ty;
}

constexpr float kExposure = 1.5f; ///< the exposure the bloom tests run at

/// A wavy field with fireflies, negative blue values (for the clamp) and a NaN at (5, 7): what the
/// prefilter must handle.
ImageF fireflyField(int width, int height) {
    ImageF image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            float* p = image.at(x, y);
            const float base = 0.5f + 0.5f * std::sin(0.37f * float(x) + 0.21f * float(y * y));
            p[0] = base * 2.0f;
            p[1] = (x * 7 + y * 13) % 17 == 0 ? 40.0f : base;
            p[2] = (x + y) % 11 == 0 ? -0.5f : 0.25f * base;
            p[3] = 1.0f;
        }
    }
    image.at(5, 7)[0] = std::numeric_limits<float>::quiet_NaN();
    return image;
}


/// A bilinear read at texel-centre coordinates (cx, cy) of channel `ch`, with transparent black past the
/// edge (the chain's sampler).
float borderRead(const ImageF& image, float cx, float cy, int ch) {
    const int x0 = int(std::floor(cx)), y0 = int(std::floor(cy));
    const float tx = cx - float(x0), ty = cy - float(y0);
    auto at = [&](int px, int py) {
        return px < 0 || py < 0 || px >= image.width || py >= image.height ? 0.0f : image.at(px, py)[ch];
    };
    return (at(x0, y0) * (1 - tx) + at(x0 + 1, y0) * tx) * (1 - ty) +
           (at(x0, y0 + 1) * (1 - tx) + at(x0 + 1, y0 + 1) * tx) * ty;
}

glm::vec4 borderRead4(const ImageF& image, float cx, float cy) {
    return {borderRead(image, cx, cy, 0), borderRead(image, cx, cy, 1), borderRead(image, cx, cy, 2),
            borderRead(image, cx, cy, 3)};
}

/// One frame texel as the prefilter takes it: sanitised, exposed, clamped, thresholded.
glm::vec3 cpuPrefiltered(const float* t, float exposure, const BloomSettings& settings) {
    glm::vec3 color;
    for (int c = 0; c < 3; ++c) {
        color[c] = std::isfinite(t[c]) ? std::min(std::clamp(t[c], 0.0f, 65000.0f) * exposure, 65000.0f) : 0.0f;
    }
    if (settings.mode == BloomMode::Threshold) {
        color *= bloomPrefilterFactor(std::max({color.r, color.g, color.b}),
                                      bloomKneeConstants(settings.threshold, settings.knee));
    }
    return color;
}

/// CPU twin of a level texel of bloom_downsample.comp.glsl, from the geometry alone: the frame's region of
/// every level starts kBloomMargin texels in; level texel t covers frame pixels from (t - margin) * scale.
/// Per axis the binomial weights (core/Bloom.h bloomPrefilterWeights) over the source texels around the
/// texel's centre, transparent black outside; on level 0 (`prefilter`) each frame texel prefiltered, alpha
/// the share of the weights on frame texels.
glm::vec4 cpuDownsample(const ImageF& source, int x, int y, int divisor, bool prefilter, float exposure,
                        const BloomSettings& settings) {
    const float margin = float(kBloomMargin);
    // The centre of level texel t in the source's texel-centre coordinates.
    const auto centre = [&](int t) {
        return prefilter ? (float(t) - margin + 0.5f) * float(divisor) - 0.5f
                         : (float(t) - margin + 0.5f) * 2.0f - 0.5f + margin;
    };
    const std::span<const float> w = bloomPrefilterWeights(prefilter ? divisor : 2);
    const int n = int(w.size());
    const int fx = int(std::lround(centre(x) - 0.5f * float(n - 1)));
    const int fy = int(std::lround(centre(y) - 0.5f * float(n - 1)));
    glm::dvec4 sum(0.0);
    double insideX = 0.0, insideY = 0.0;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const int sx = fx + i, sy = fy + j;
            if (sx < 0 || sy < 0 || sx >= source.width || sy >= source.height)
                continue;
            const float* t = source.at(sx, sy);
            const glm::vec4 v = prefilter ? glm::vec4(cpuPrefiltered(t, exposure, settings), 0.0f)
                                          : glm::vec4(t[0], t[1], t[2], t[3]);
            sum += glm::dvec4(v) * double(w[std::size_t(i)] * w[std::size_t(j)]);
        }
        insideX += (fx + j >= 0 && fx + j < source.width) ? w[std::size_t(j)] : 0.0f;
        insideY += (fy + j >= 0 && fy + j < source.height) ? w[std::size_t(j)] : 0.0f;
    }
    if (prefilter) {
        sum.a = insideX * insideY;
    }
    return glm::vec4(sum);
}

/// The Gaussian's weight at `k` texels, of the truncated and renormalised kernel every level is blurred by.
double blurWeight(int k) {
    double total = 0.0;
    for (int i = -kBloomBlurReach; i <= kBloomBlurReach; ++i) {
        total += std::exp(-double(i * i) / (2.0 * kBloomBlurSigma * kBloomBlurSigma));
    }
    return std::exp(-double(k * k) / (2.0 * kBloomBlurSigma * kBloomBlurSigma)) / total;
}

/// CPU twin of bloom_blur.comp.glsl: the Gaussian along the row, every texel weighed by itself (the
/// shader's bilinear pairs are the same sums), transparent black past the edge.
glm::vec4 cpuBlurRow(const ImageF& source, int x, int y) {
    glm::dvec4 sum(0.0);
    for (int k = -kBloomBlurReach; k <= kBloomBlurReach; ++k) {
        if (x + k >= 0 && x + k < source.width) {
            const float* t = source.at(x + k, y);
            sum += glm::dvec4(t[0], t[1], t[2], t[3]) * blurWeight(k);
        }
    }
    return glm::vec4(sum);
}

/// CPU twin of bloom_upsample.comp.glsl at target texel (x, y): the Gaussian along the column of the rows'
/// blur, mixed by `radius` with a bilinear read of the coarser result (when there is one) at the same frame
/// position. `offset`: the level texel of target texel 0 (the margin, for the chain's result).
glm::vec4 cpuUpsample(const ImageF& rows, const ImageF* coarse, int x, int y, int offset, float radius) {
    const int qx = x + offset, qy = y + offset;
    glm::dvec4 sum(0.0);
    for (int k = -kBloomBlurReach; k <= kBloomBlurReach; ++k) {
        if (qy + k >= 0 && qy + k < rows.height) {
            const float* t = rows.at(qx, qy + k);
            sum += glm::dvec4(t[0], t[1], t[2], t[3]) * blurWeight(k);
        }
    }
    const glm::vec4 blurred(sum);
    if (coarse == nullptr) {
        return blurred;
    }
    // Level texel q sits at frame position (q - margin + 1/2) s; coarse texel Q at (Q - margin + 1/2) 2s.
    const float m = float(kBloomMargin);
    const auto toCoarse = [&](int q) { return (float(q) - m + 0.5f) * 0.5f + m - 0.5f; };
    return glm::mix(blurred, borderRead4(*coarse, toCoarse(qx), toCoarse(qy)), radius);
}

/// What filtering may add to a texel's error besides its own rounding: the largest value read is stored in
/// a half float (2^-11 of it), and that rounding enters every sum near it, however small; on GPUs bilinear
/// weights are also fixed point (8 fractional bits under D3D's rules, which their GL drivers follow), so a
/// footprint's sum can be off by 2^-8 of the largest value read.
float filterSlack(float largest) {
    return largest / (isSoftwareRenderer() ? 2048.0f : 256.0f);
}

/// The largest finite value of the image's colour channels, clamped as the prefilter clamps: the slack's
/// scale.
float largestValue(const ImageF& image) {
    float largest = 0.0f;
    for (std::size_t i = 0; i < image.rgba.size(); ++i) {
        if (i % 4 != 3 && std::isfinite(image.rgba[i]))
            largest = std::max(largest, std::min(image.rgba[i], 65000.0f));
    }
    return largest;
}

/// Worst |gpu - want| over the allowed error (half floats: relative 2^-11 with headroom, plus the slack) of
/// every texel and channel, alpha included.
template <class Want>
float worstError(const ImageF& gpu, Want want, float slack) {
    float worst = 0.0f;

    for (int y = 0; y < gpu.height; ++y) {
        for (int x = 0; x < gpu.width; ++x) {
            const glm::vec4 w = want(x, y);
            for (int c = 0; c < 4; ++c) {
                const float allowed = 2e-3f * (std::abs(w[c]) + 1e-3f) + slack;
                const float d = std::abs(gpu.at(x, y)[c] - w[c]) / allowed;
                worst = std::max(worst, std::isfinite(gpu.at(x, y)[c]) ? d : 1e9f);
            }
        }
    }
    return worst;
}

/// `texture` read back with its rows in GL's order (row 0 at the bottom; readTextureF turns images top-down):
/// the chain's levels start at the frame's bottom-left corner, and odd sizes leave their partial texel at
/// the top.
ImageF readGlOrder(const Texture& texture) {
    const ImageF image = readTextureF(texture);
    ImageF out(image.width, image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            std::copy_n(image.at(x, image.height - 1 - y), 4, out.at(x, y));
    return out;
}

/// fireflyField and, with `hostile`, infinities of both signs, 1e30 and a 4x4 block of 3e38 whose plain
/// weighted sum would overflow: what a host may hand the prefilter raw.
ImageF hostileField(int width, int height, bool hostile) {
    ImageF image = fireflyField(width, height);
    if (hostile) {
        image.at(20, 9)[1] = std::numeric_limits<float>::infinity();
        image.at(33, 17)[0] = -std::numeric_limits<float>::infinity();
        image.at(40, 30)[2] = 1e30f;
        for (int y = 12; y < 16; ++y)
            for (int x = 24; x < 28; ++x)
                image.at(x, y)[1] = 3e38f;
    }
    return image;
}

} // namespace

// Every step of every level against its CPU twin, each from the GPU's own input to it (so half-float
// rounding does not accumulate): the downsample (level 0 the prefilter, with both first divisors and both
// modes), the row blur and the upsample with its column blur, on sizes whose levels halve exactly and odd
// ones, on scenes with fireflies, negative values, a NaN and, in two, infinities and values whose sums would
// overflow. The twins place every texel from the geometry alone (frame regions, bands, scales), so a wrong
// mapping fails here.
TEST_F(GlTest, BloomStepsMatchTheirCpuTwins) {
    struct Case {
        int width, height, divisor;
        BloomMode mode;
        bool hostile;
    };
    const Case cases[] = {{64, 48, 2, BloomMode::EnergyConserving, false},
                          {70, 46, 2, BloomMode::Threshold, true},
                          {64, 48, 4, BloomMode::Threshold, false},
                          {61, 37, 2, BloomMode::EnergyConserving, true},
                          {61, 37, 4, BloomMode::EnergyConserving, false}};
    for (const Case& k : cases) {
        const ImageF image = hostileField(k.width, k.height, k.hostile);
        const Texture input = makeTexture(image, "bloom twin input");
        const Buffer exposure = exposureState(kExposure, "bloom twin exposure");
        BloomSettings settings;
        settings.mode = k.mode;
        settings.radius = 0.7f;
        BloomPass pass;
        pass.resize({k.width, k.height});
        const Texture& result = pass.execute({.scene = &input,
                                              .exposureState = &exposure,
                                              .settings = &settings,
                                              .firstDivisor = k.divisor,
                                              .mipCount = 6});
        ASSERT_GE(pass.levels(), 2);
        const glm::ivec2 frame0 = bloomLevelFrame({k.width, k.height}, k.divisor, 0);
        EXPECT_EQ(result.extent(), (Extent{frame0.x, frame0.y})) << "the result covers the frame alone";
        const std::string name = std::to_string(k.width) + "x" + std::to_string(k.height) + " divisor " +
                                 std::to_string(k.divisor) + " level ";
        for (int level = 0; level < pass.levels(); ++level) {
            const ImageF source = readGlOrder(level == 0 ? input : pass.downsampled(level - 1));
            const ImageF down = readGlOrder(pass.downsampled(level));
            const glm::ivec2 frame = bloomLevelFrame({k.width, k.height}, k.divisor, level);
            ASSERT_EQ(down.width, frame.x + 2 * kBloomMargin);
            const float exposed = level == 0 ? kExposure : 1.0f;

            EXPECT_LT(worstError(down,
                                 [&](int x, int y) {
                                     return cpuDownsample(source, x, y, k.divisor, level == 0, kExposure,
                                                          settings);
                                 },
                                 filterSlack(largestValue(source) * exposed)),
                      1.0f)
                << name << level << " downsample";
            const ImageF rows = readGlOrder(pass.blurredRows(level));
            EXPECT_LT(worstError(rows, [&](int x, int y) { return cpuBlurRow(down, x, y); },
                                 filterSlack(largestValue(down))),
                      1.0f)
                << name << level << " rows";
            const bool coarsest = level + 1 == pass.levels();
            const ImageF coarse = coarsest ? ImageF(1, 1) : readGlOrder(pass.upsampled(level + 1));
            const ImageF up = readGlOrder(pass.upsampled(level));
            const int offset = level == 0 ? kBloomMargin : 0;
            EXPECT_LT(worstError(up,
                                 [&](int x, int y) {
                                     return cpuUpsample(rows, coarsest ? nullptr : &coarse, x, y, offset,
                                                        settings.radius);
                                 },
                                 filterSlack(std::max(largestValue(rows), largestValue(coarse)))),
                      1.0f)
                << name << level << " upsample";
        }
    }
}

// The bloom chain and the tone-map pass take their invocation shape from pixelGroup(): rows of 64 on a
// software renderer, 8x8 on a GPU. Results must not depend on it: with either shape forced, every step of
// every bloom level and the display image, dithered, are the same to the bit, on a size whose levels halve
// exactly and on an odd one.
TEST_F(GlTest, PixelGroupShapesGiveTheSameBloomAndDisplay) {
    for (const Extent size : {Extent{128, 64}, Extent{97, 61}}) {
        const ImageF image = fireflyField(size.width, size.height);
        const Texture input = makeTexture(image, "pixel group input");
        const Buffer exposure = exposureState(kExposure, "pixel group exposure");
        const BloomSettings settings;
        std::vector<std::vector<ImageF>> levels;
        std::vector<Image8> displays;
        for (const PixelGroup group : {kPixelGroupSquare, kPixelGroupRow}) {
            forcePixelGroup(group);
            BloomPass pass;
            pass.resize(size);
            pass.execute({.scene = &input, .exposureState = &exposure, .settings = &settings});
            std::vector<ImageF> read;
            for (int level = 0; level < pass.levels(); ++level) {
                read.push_back(readTextureF(pass.downsampled(level)));
                read.push_back(readTextureF(pass.blurredRows(level)));
                read.push_back(readTextureF(pass.upsampled(level)));
            }
            levels.push_back(std::move(read));
            Pipeline pipeline({.settings = Settings{}});
            displays.push_back(processImage(pipeline, image));
        }
        ASSERT_EQ(levels[0].size(), levels[1].size());
        for (std::size_t i = 0; i < levels[0].size(); ++i) {
            EXPECT_EQ(levels[0][i].rgba, levels[1][i].rgba)
                << size.width << "x" << size.height << ", level " << i / 3 << " step " << i % 3;
        }
        EXPECT_EQ(displays[0].rgba, displays[1].rgba) << size.width << "x" << size.height << " display image";
    }
}

// A uniform image is left as it is by energy-conserving bloom, to its borders and corners: each pixel gives
// up the share of its glow that stays in the frame and receives as much from its neighbours (the result's
// alpha), where a clamped or black border would brighten or darken the edges.
TEST_F(GlTest, EnergyConservingBloomLeavesAUniformImageAsItIs) {
    ImageF image(77, 45);
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        image.rgba[i] = 0.7f;
        image.rgba[i + 1] = 0.4f;
        image.rgba[i + 2] = 0.2f;
        image.rgba[i + 3] = 1.0f;
    }
    for (const int mips : {1, 6}) {
        Settings s = bloomOnly();
        s.bloom.intensity = 0.5f;
        s.bloom.mipCount = mips;
        Pipeline pipeline({.settings = s});
        const ImageF out = sceneOf(pipeline, image);
        float worst = 0.0f;
        for (std::size_t i = 0; i < out.rgba.size(); ++i) {
            if (i % 4 != 3)
                worst = std::max(worst, std::abs(out.rgba[i] / image.rgba[i] - 1.0f));
        }
        EXPECT_LT(worst, 3e-3f) << mips << " levels"; // the chain's half floats
    }
}

TEST_F(GlTest, BrightDiscBloomsWithRadialSymmetry) {
    // The glow of a disc read along 8 directions at three distances: every level's kernel is a Gaussian, so
    // the glow is round whichever levels dominate (radius 0.5: the first ones; 0.85: the wide ones).
    // test_bloom_roundness.cpp holds every look to it over whole annuli.
    const int size = 256;
    for (const float radius : {0.5f, 0.85f}) {
        Settings s = bloomOnly();
        s.bloom.mipCount = 5;
        s.bloom.radius = radius;
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
                EXPECT_NEAR(values[i] / ref, 1.0f, 0.02f)
                    << "radius " << radius << ", distance " << r << ", direction " << i;
            }
        }
    }
}

TEST_F(GlTest, EnergyConservingBloomKeepsTheImageSum) {
    // A bright disc and a dim textured field: bloom moves light and adds none, and the light that would
    // glow past the border stays where it was (the result's alpha), so the sum holds to the chain's half
    // floats, on a frame the widest level's glow reaches across.
    ImageF image = disc(160, 6.0f, 4.0f);
    for (int y = 0; y < 160; ++y) {
        for (int x = 0; x < 160; ++x) {
            image.at(x, y)[1] += 0.1f + 0.05f * float((x / 5 + y / 7) % 3);
        }
    }
    const float ev = -1.0f;
    for (float intensity : {0.04f, 0.5f, 1.0f}) {
        Settings s = bloomOnly();
        s.bloom.intensity = intensity;
        s.tonemapping.exposure = ev;
        Pipeline pipeline({.settings = s});
        const ImageF out = sceneOf(pipeline, image);
        const double exposedInput = sumRgb(image) * std::exp2(ev);
        EXPECT_NEAR(sumRgb(out) / exposedInput, 1.0, 0.002) << "intensity " << intensity;
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

namespace photopic::test {

// The tone-map pass composites the bloom either by one bilinear tap per pixel or, where the bloom is exactly
// half the frame, in 4x4 blocks from the 16 bloom texels their taps share (software renderers): the same
// composite within float rounding, on a frame whose sides are multiples of 4 and on one whose blocks run past
// the edge, in both bloom modes.
TEST_F(GlTest, TonemapBloomBlocksCompositeTheSameAsTheTaps) {
    for (const Extent size : {Extent{64, 48}, Extent{70, 46}}) {
        const ImageF scene = fireflyField(size.width, size.height);
        const ImageF bloom = fireflyField(size.width / 2, size.height / 2);
        const Texture sceneTexture = makeTexture(scene, "tonemap blocks scene");
        const Texture bloomTexture = makeTexture(bloom, "tonemap blocks bloom");
        const Buffer exposure = exposureState(kExposure, "tonemap blocks exposure");
        for (const BloomMode mode : {BloomMode::EnergyConserving, BloomMode::Threshold}) {
            const ToneMappingSettings tonemapping;
            const OutputSettings output;
            BloomSettings bloomSettings;
            bloomSettings.mode = mode;
            const ColorGradingSettings grading;
            const TonemapPass::Inputs in{.scene = &sceneTexture,
                                         .exposureState = &exposure,
                                         .tonemapping = &tonemapping,
                                         .output = &output,
                                         .bloom = &bloomTexture,
                                         .bloomSettings = &bloomSettings,
                                         .grading = &grading};
            const Capabilities caps = detectCapabilities();
            ImageF out[2];
            for (const bool blocks : {false, true}) {
                TonemapPass pass(caps);
                pass.setBloomBlocks(blocks);
                out[blocks ? 1 : 0] = readTextureF(pass.renderScene(in));
            }
            float worst = 0.0f;
            for (std::size_t i = 0; i < out[0].rgba.size(); ++i) {
                const float a = out[0].rgba[i], b = out[1].rgba[i];
                worst = std::max(worst, std::abs(a - b) / (std::abs(a) + 1e-3f));
            }
            // The taps' positions come from normalised coordinates, exact only where 1 / size is (64x48), so
            // their fractions can be a few float steps off 1/4 and 3/4: 1.6e-5 at 70x46 on llvmpipe.
            EXPECT_LT(worst, 1e-4f) << size.width << "x" << size.height << " mode " << int(mode);
        }
    }
}

} // namespace photopic::test
