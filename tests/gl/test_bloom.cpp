// Bloom on the GPU: the downsample against its CPU twin, radial symmetry, energy conservation, the threshold,
// and grading reaching the EXR output.

#include "GlTest.h"

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

/// CPU twin of one target texel of bloom_downsample.comp.glsl: 13 bilinear taps (clamp to edge) around the
/// texel's centre, one tap step apart, as five boxes; on level 0 (`prefilter`) each box sanitised and
/// exposed, the boxes weighted by Karis's 1 / (1 + luma), and the soft knee in threshold mode.
glm::vec3 cpuDownsample(const ImageF& source, int width, int height, int x, int y, float step, bool prefilter,
                        float exposure, const BloomSettings& settings) {
    auto tap = [&](float u, float v) {
        const float px = u * float(source.width), py = v * float(source.height);
        return glm::vec3(bilinear(source, px, py, 0), bilinear(source, px, py, 1),
                         bilinear(source, px, py, 2));
    };
    const float u = (float(x) + 0.5f) / float(width), v = (float(y) + 0.5f) / float(height);
    const float tu = step / float(source.width), tv = step / float(source.height);
    auto box = [&](float cx, float cy, float half) {
        const glm::vec3 mean = (tap(u + (cx - half) * tu, v + (cy - half) * tv) +
                                tap(u + (cx + half) * tu, v + (cy - half) * tv) +
                                tap(u + (cx - half) * tu, v + (cy + half) * tv) +
                                tap(u + (cx + half) * tu, v + (cy + half) * tv)) *
                               0.25f;
        if (!prefilter) {
            return mean;
        }
        glm::vec3 clean;
        for (int c = 0; c < 3; ++c) {
            clean[c] = std::isfinite(mean[c]) ? std::clamp(mean[c], 0.0f, 65000.0f) : 0.0f;
        }
        return clean * exposure;
    };
    const glm::vec3 boxes[5] = {box(0, 0, 1), box(-1, 1, 1), box(1, 1, 1), box(-1, -1, 1), box(1, -1, 1)};
    glm::vec3 sum(0.0f);
    float weights = 0.0f;
    for (int i = 0; i < 5; ++i) {
        const float w = (i == 0 ? 0.5f : 0.125f) * (prefilter ? 1.0f / (1.0f + luma709(boxes[i])) : 1.0f);
        sum += boxes[i] * w;
        weights += w;
    }
    glm::vec3 color = sum / weights;
    if (prefilter && settings.mode == BloomMode::Threshold) {
        const glm::vec4 k = bloomKneeConstants(settings.threshold, settings.knee);
        const float br = std::max({color.r, color.g, color.b});
        float rq = std::clamp(br - k.y, 0.0f, k.z);
        rq = rq * rq * k.w;
        color *= std::max(rq, br - k.x) / std::max(br, 1e-4f);
    }
    return color;
}

/// Per channel, the largest minus the smallest sanitised value (non-finite as 0, clamped to [0, 65000]) of
/// the texels in [x0, x1] x [y0, y1], clamped to the image as the samplers clamp.
glm::vec3 spread(const ImageF& image, int x0, int y0, int x1, int y1) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const float* t = image.at(std::clamp(x, 0, image.width - 1), std::clamp(y, 0, image.height - 1));
            for (int c = 0; c < 3; ++c) {
                const float v = std::isfinite(t[c]) ? std::clamp(t[c], 0.0f, 65000.0f) : 0.0f;
                lo[c] = std::min(lo[c], v);
                hi[c] = std::max(hi[c], v);
            }
        }
    }
    return hi - lo;
}

/// An exposure state of `exposure` in a buffer, as the bloom and tone-map passes read it.
Buffer exposureState(float exposure, std::string_view name) {
    GpuExposureState state;
    state.exposure = exposure;
    return Buffer({.size = sizeof(state), .data = &state, .debugName = name});
}

constexpr float kExposure = 1.5f; ///< the exposure the bloom tests run at

/// What a GPU's filtering may add to a target texel's error: bilinear weights are fixed point on GPUs (8
/// fractional bits under D3D's rules, which their GL drivers follow), so a tap between texel centres can be
/// off by 2^-9 of the spread of the texels it reads; summed over the 13 taps, at most 2^-8 of the spread of
/// the texel's footprint (half its taps' weight is in the centre box). Taps on texel corners (levels that
/// halve exactly) have weights of 1/2, exact in any fixed point, so only the other levels use this. The
/// prefilter (`karis`) weights each group of taps by 1/(1 + its luma), so a group's error moves its weight
/// too: up to as much again (NVIDIA's H200 reaches 1.15 times the plain bound on a 61x37 scene). A software
/// renderer filters in float and gets no slack.
glm::vec3 filterWeightSlack(const ImageF& source, int width, int height, int x, int y, float step,
                            bool karis) {
    if (isSoftwareRenderer() || (source.width == 2 * width && source.height == 2 * height && step == 1.0f)) {
        return glm::vec3(0.0f);
    }
    const float cx = (float(x) + 0.5f) * float(source.width) / float(width);
    const float cy = (float(y) + 0.5f) * float(source.height) / float(height);
    const float reach =
        2.0f * step + 1.0f; // the outer taps' centres, and the texel each tap reaches past them
    return spread(source, int(std::floor(cx - reach)), int(std::floor(cy - reach)),
                  int(std::ceil(cx + reach)), int(std::ceil(cy + reach))) *
           (karis ? 2.0f / 256.0f : 1.0f / 256.0f);
}

/// A wavy field with fireflies (for the Karis weights), negative blue values (for the box clamp) and a NaN at
/// (5, 7): what the prefilter must handle.
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

} // namespace

// Every downsampled level against the CPU filter, on sizes whose levels halve exactly (2x2 and 4x4 blocks
// of target texels sharing their taps, and the prefilter from shared-memory tiles of texels or of taps;
// odd-sized targets among them) and sizes whose levels do not (one texel
// per invocation), with both first divisors, both modes, and fireflies, negative values and a NaN in the
// scene.
// Each level is checked from the GPU's own level above, so rounding to half floats does not accumulate.
TEST_F(GlTest, BloomDownsampleLevelsMatchTheCpuFilter) {
    struct Case {
        int width, height, divisor;
        BloomMode mode;
    };
    const Case cases[] = {{64, 48, 2, BloomMode::EnergyConserving},
                          {70, 46, 2, BloomMode::Threshold},
                          {64, 48, 4, BloomMode::Threshold},
                          {61, 37, 2, BloomMode::EnergyConserving}};
    struct Kernels {
        int side;
        BloomPrefilterKernel prefilter;
    };
    for (const Kernels kernels :
         {Kernels{1, BloomPrefilterKernel::Taps}, Kernels{2, BloomPrefilterKernel::Taps},
          Kernels{4, BloomPrefilterKernel::Taps}, Kernels{2, BloomPrefilterKernel::Tiles},
          Kernels{2, BloomPrefilterKernel::SharedTaps}, Kernels{2, BloomPrefilterKernel::SharedTexels}}) {
        const int side = kernels.side;
        for (const Case& k : cases) {
            const ImageF image = fireflyField(k.width, k.height);
            const Texture input = makeTexture(image, "bloom twin input");
            const Buffer exposure = exposureState(kExposure, "bloom twin exposure");
            BloomSettings settings;
            settings.mode = k.mode;
            BloomPass pass;
            pass.setBlockSide(side);
            pass.setPrefilterKernel(kernels.prefilter);
            pass.resize({k.width, k.height});
            pass.execute({.scene = &input,
                          .exposureState = &exposure,
                          .settings = &settings,
                          .firstDivisor = k.divisor,
                          .mipCount = 6});
            ASSERT_GE(pass.levels(), 3);
            for (int level = 0; level < pass.levels(); ++level) {
                const ImageF source = readTextureF(level == 0 ? input : pass.downsampled(level - 1));
                const ImageF gpu = readTextureF(pass.downsampled(level));
                const float step = level == 0 ? float(k.divisor) * 0.5f : 1.0f;
                float worst = 0.0f;
                for (int y = 0; y < gpu.height; ++y) {
                    for (int x = 0; x < gpu.width; ++x) {
                        const glm::vec3 want = cpuDownsample(source, gpu.width, gpu.height, x, y, step,
                                                             level == 0, kExposure, settings);
                        const glm::vec3 spread =
                            filterWeightSlack(source, gpu.width, gpu.height, x, y, step, level == 0) *
                            (level == 0 ? kExposure : 1.0f);
                        for (int c = 0; c < 3; ++c) {
                            // A half float holds 11 significant bits (relative step 2^-11, about 5e-4).
                            const float allowed = 2e-3f * (std::abs(want[c]) + 1e-3f) + spread[c];
                            const float d = std::abs(gpu.at(x, y)[c] - want[c]) / allowed;
                            worst = std::max(worst, std::isfinite(gpu.at(x, y)[c]) ? d : 1e9f);
                        }
                    }
                }
                EXPECT_LT(worst, 1.0f)
                    << k.width << "x" << k.height << " divisor " << k.divisor << " level " << level << " ("
                    << gpu.width << "x" << gpu.height << "), blocks of " << side << ", prefilter "
                    << bloomPrefilterKernelName(kernels.prefilter);
            }
        }
    }
}

// The tiled prefilters (unfiltered texels in shared memory, boxes built in arithmetic; or filtered taps
// fetched once into shared memory) give the filtered taps' level 0 on scenes a host may hand over raw: NaN,
// infinities of both signs, negative values, 1e30 and a 4x4 block of 3e38, whose plain sum in a box would
// overflow; on sizes with partial tiles at the right and bottom.
TEST_F(GlTest, TiledPrefilterMatchesTheFilteredTapsOnHostileScenes) {
    for (const Extent size : {Extent{64, 48}, Extent{100, 70}, Extent{162, 98}}) {
        ImageF image = fireflyField(size.width, size.height);
        image.at(20, 9)[1] = std::numeric_limits<float>::infinity();
        image.at(33, 17)[0] = -std::numeric_limits<float>::infinity();
        image.at(40, 30)[2] = 1e30f;
        image.at(size.width - 1, size.height - 1)[0] = std::numeric_limits<float>::quiet_NaN();
        for (int y = 12; y < 16; ++y) {
            for (int x = 24; x < 28; ++x) {
                image.at(x, y)[1] = 3e38f;
            }
        }
        const Texture input = makeTexture(image, "tiled prefilter input");
        const Buffer exposure = exposureState(kExposure, "tiled prefilter exposure");
        for (const BloomMode mode : {BloomMode::EnergyConserving, BloomMode::Threshold}) {
            BloomSettings settings;
            settings.mode = mode;
            std::vector<ImageF> level0;
            for (const BloomPrefilterKernel kernel :
                 {BloomPrefilterKernel::Taps, BloomPrefilterKernel::Tiles, BloomPrefilterKernel::SharedTaps,
                  BloomPrefilterKernel::SharedTexels}) {
                BloomPass pass;
                pass.setBlockSide(2);
                pass.setPrefilterKernel(kernel);
                ASSERT_EQ(pass.prefilterKernel(), kernel);
                pass.resize(size);
                pass.execute(
                    {.scene = &input, .exposureState = &exposure, .settings = &settings, .mipCount = 3});
                level0.push_back(readTextureF(pass.downsampled(0)));
            }
            const ImageF& taps = level0[0];
            for (std::size_t k = 1; k < level0.size(); ++k) {
                const ImageF& tiled = level0[k];
                ASSERT_EQ(tiled.width, size.width / 2);
                float worst = 0.0f, largest = 0.0f;
                for (std::size_t i = 0; i < taps.rgba.size(); ++i) {
                    ASSERT_TRUE(std::isfinite(tiled.rgba[i])) << i;
                    // Half floats: a relative step of 2^-11, twice over (the two sums round apart).
                    const float allowed = 2e-3f * (std::abs(taps.rgba[i]) + 1e-3f);
                    worst = std::max(worst, std::abs(tiled.rgba[i] - taps.rgba[i]) / allowed);
                    largest = std::max(largest, tiled.rgba[i]);
                }
                const char* name = k == 1 ? "tiles" : k == 2 ? "shared taps" : "shared texels";
                EXPECT_LT(worst, 1.0f) << size.width << "x" << size.height << " " << name;
                // The 3e38 block's boxes are clamped, not dropped as an overflow would make them.
                EXPECT_GT(largest, 1000.0f) << size.width << "x" << size.height << " " << name;
            }
        }
    }
}

// PHOTOPIC_BLOOM_BLOCK_SIDE and PHOTOPIC_BLOOM_PREFILTER pick the kernels of a pass made while they are set
// (for measuring them against each other on one device); a bad value leaves the renderer's defaults.
TEST_F(GlTest, BloomEnvironmentOverridesPickTheKernels) {
    // Unset before (a run of the suite with an override set still tests the defaults) and after.
    struct Unset {
        Unset() { clear(); }
        ~Unset() { clear(); }
        static void clear() {
            unsetenv("PHOTOPIC_BLOOM_BLOCK_SIDE");
            unsetenv("PHOTOPIC_BLOOM_PREFILTER");
        }
    } unset;
    const BloomPass defaults;
    EXPECT_EQ(defaults.prefilterKernel(), BloomPrefilterKernel::Taps);
    const int otherSide = defaults.blockSide() == 2 ? 4 : 2;
    setenv("PHOTOPIC_BLOOM_BLOCK_SIDE", otherSide == 2 ? "2" : "4", 1);
    setenv("PHOTOPIC_BLOOM_PREFILTER", "tiles", 1);
    const BloomPass overridden;
    EXPECT_EQ(overridden.blockSide(), otherSide);
    EXPECT_EQ(overridden.prefilterKernel(), BloomPrefilterKernel::Tiles);
    setenv("PHOTOPIC_BLOOM_PREFILTER", "shared", 1);
    EXPECT_EQ(BloomPass().prefilterKernel(), BloomPrefilterKernel::SharedTaps);
    setenv("PHOTOPIC_BLOOM_PREFILTER", "shared-texels", 1);
    EXPECT_EQ(BloomPass().prefilterKernel(), BloomPrefilterKernel::SharedTexels);
    setenv("PHOTOPIC_BLOOM_BLOCK_SIDE", "3", 1);
    setenv("PHOTOPIC_BLOOM_PREFILTER", "fast", 1);
    const BloomPass ignored;
    EXPECT_EQ(ignored.blockSide(), defaults.blockSide());
    EXPECT_EQ(ignored.prefilterKernel(), BloomPrefilterKernel::Taps);
}

namespace {

/// CPU twin of one texel of bloom_upsample.comp.glsl: mix(fine, tent(coarse), radius), the 3x3 tent over the
/// coarser level at the texel's centre as four texels per axis with weights (1 - f) / 4, 1/2 - f/4, 1/4 + f/4
/// and f/4 (clamp to edge).
glm::vec3 cpuUpsample(const ImageF& coarse, const ImageF& fine, int x, int y, float radius) {
    auto axis = [](int p, int fineSize, int coarseSize, int(&texels)[4], float(&w)[4]) {
        const float c = (float(p) + 0.5f) * float(coarseSize) / float(fineSize) - 0.5f;
        const int i = int(std::floor(c));
        const float f = c - float(i);
        const float weights[4] = {(1.0f - f) * 0.25f, 0.5f - f * 0.25f, 0.25f + f * 0.25f, f * 0.25f};
        for (int k = 0; k < 4; ++k) {
            texels[k] = std::clamp(i - 1 + k, 0, coarseSize - 1);
            w[k] = weights[k];
        }
    };
    int tx[4], ty[4];
    float wx[4], wy[4];
    axis(x, fine.width, coarse.width, tx, wx);
    axis(y, fine.height, coarse.height, ty, wy);
    glm::vec3 tent(0.0f);
    for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) {
            const float* t = coarse.at(tx[i], ty[j]);
            tent += glm::vec3(t[0], t[1], t[2]) * (wx[i] * wy[j]);
        }
    }
    const float* f = fine.at(x, y);
    return glm::mix(glm::vec3(f[0], f[1], f[2]), tent, radius);
}

/// The spread of the coarse texels a fine texel's tent reads, over 256: a GPU's fixed-point bilinear weights
/// on the pair taps (filterWeightSlack). Levels that upsample in 4x4 blocks fetch texels and weigh them in
/// float; a software renderer filters in float too.
glm::vec3 tentWeightSlack(const ImageF& coarse, const ImageF& fine, int x, int y) {
    if (isSoftwareRenderer()) {
        return glm::vec3(0.0f);
    }
    const int cx = int(std::floor((float(x) + 0.5f) * float(coarse.width) / float(fine.width)));
    const int cy = int(std::floor((float(y) + 0.5f) * float(coarse.height) / float(fine.height)));
    return spread(coarse, cx - 2, cy - 2, cx + 2, cy + 2) * (1.0f / 256.0f);
}

} // namespace

// Every upsampled level against the CPU tent, each from the GPU's own coarser level and downsampled level, on
// sizes whose levels double exactly (the 4x4-block upsample where the block side is 4) and sizes whose levels
// do not, with both block sides and the scene's fireflies.
TEST_F(GlTest, BloomUpsampleLevelsMatchTheCpuTent) {
    for (const int side : {1, 2, 4}) {
        for (const Extent size : {Extent{64, 48}, Extent{72, 40}, Extent{70, 46}, Extent{61, 37}}) {
            const ImageF image = fireflyField(size.width, size.height);
            const Texture input = makeTexture(image, "bloom upsample twin input");
            const Buffer exposure = exposureState(kExposure, "bloom upsample twin exposure");
            BloomSettings settings;
            settings.radius = 0.7f;
            BloomPass pass;
            pass.setBlockSide(side);
            pass.resize(size);
            pass.execute({.scene = &input, .exposureState = &exposure, .settings = &settings, .mipCount = 5});
            ASSERT_GE(pass.levels(), 3);
            for (int level = pass.levels() - 2; level >= 0; --level) {
                const ImageF coarse = readTextureF(level == pass.levels() - 2 ? pass.downsampled(level + 1)
                                                                              : pass.upsampled(level + 1));
                const ImageF fine = readTextureF(pass.downsampled(level));
                const ImageF gpu = readTextureF(pass.upsampled(level));
                float worst = 0.0f;
                for (int y = 0; y < gpu.height; ++y) {
                    for (int x = 0; x < gpu.width; ++x) {
                        const glm::vec3 want = cpuUpsample(coarse, fine, x, y, settings.radius);
                        const glm::vec3 slack = tentWeightSlack(coarse, fine, x, y);
                        for (int c = 0; c < 3; ++c) {
                            // Half floats: a relative step of 2^-11.
                            const float allowed = 2e-3f * (std::abs(want[c]) + 1e-3f) + slack[c];
                            const float d = std::abs(gpu.at(x, y)[c] - want[c]) / allowed;
                            worst = std::max(worst, std::isfinite(gpu.at(x, y)[c]) ? d : 1e9f);
                        }
                    }
                }
                EXPECT_LT(worst, 1.0f) << size.width << "x" << size.height << " level " << level << " ("
                                       << gpu.width << "x" << gpu.height << "), blocks of " << side;
            }
        }
    }
}

// The bloom chain and the tone-map pass take their invocation shape from pixelGroup(): rows of 64 on a
// software renderer, 8x8 on a GPU. Results must not depend on it: with either shape forced, every bloom level
// (both block sizes) and the display image, dithered, are the same to the bit, on a size whose levels halve
// exactly and on an odd one.
TEST_F(GlTest, PixelGroupShapesGiveTheSameBloomAndDisplay) {
    struct ByRendererAgain { // the tests after this one get the renderer's shape, even after a failure here
        ~ByRendererAgain() { forcePixelGroup(std::nullopt); }
    } restore;
    for (const Extent size : {Extent{128, 64}, Extent{97, 61}}) {
        const ImageF image = fireflyField(size.width, size.height);
        const Texture input = makeTexture(image, "pixel group input");
        const Buffer exposure = exposureState(kExposure, "pixel group exposure");
        const BloomSettings settings;
        std::vector<std::vector<ImageF>> levels;
        std::vector<Image8> displays;
        for (const PixelGroup group : {kPixelGroupSquare, kPixelGroupRow}) {
            forcePixelGroup(group);
            for (const int side : {2, 4}) {
                BloomPass pass;
                ASSERT_EQ(pass.group(), group);
                pass.setBlockSide(side);
                pass.resize(size);
                const Texture& bloom =
                    pass.execute({.scene = &input, .exposureState = &exposure, .settings = &settings});
                std::vector<ImageF> read;
                for (int level = 0; level < pass.levels(); ++level) {
                    read.push_back(readTextureF(pass.downsampled(level)));
                }
                read.push_back(readTextureF(bloom));
                levels.push_back(std::move(read));
            }
            Pipeline pipeline({.settings = Settings{}});
            displays.push_back(processImage(pipeline, image));
        }
        // levels: square 2, square 4, row 2, row 4.
        for (int side = 0; side < 2; ++side) {
            const auto& square = levels[std::size_t(side)];
            const auto& row = levels[std::size_t(2 + side)];
            ASSERT_EQ(square.size(), row.size());
            for (std::size_t level = 0; level < square.size(); ++level) {
                EXPECT_EQ(square[level].rgba, row[level].rgba)
                    << size.width << "x" << size.height << ", blocks of " << (side == 0 ? 2 : 4) << ", "
                    << (level + 1 == square.size() ? "bloom result" : "level " + std::to_string(level));
            }
        }
        EXPECT_EQ(displays[0].rgba, displays[1].rgba) << size.width << "x" << size.height << " display image";
    }
}

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
