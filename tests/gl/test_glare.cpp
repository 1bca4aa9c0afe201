// bloom.mode = glare (passes/glare/): the FFT convolution against a direct CPU convolution with the same
// halo kernel, a point's glow against the kernel's analytic profile, roundness of the eye kernel's glow
// (tests/gl/PointGlow.h), the camera kernel's spikes, energy, the kernel's cache, the frame order (the glare
// instead of the mip chain) and the LDR path's warning.

#include "GlCallAudit.h"
#include "PointGlow.h"

#include "core/Glare.h"
#include "core/Log.h"
#include "gl/TextureIo.h"
#include "passes/Bindings.h"
#include "passes/glare/GlarePass.h"
#include "pipeline/Pipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace photopic::test {

namespace {

/// HDR noise: mostly 0..2 with a few hot pixels up to 500.
ImageF randomHdr(int width, int height, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    ImageF image(width, height);
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        const float hot = u(rng) < 0.03f ? 500.0f * u(rng) : 0.0f;
        for (int c = 0; c < 3; ++c)
            image.rgba[i * 4 + std::size_t(c)] = 2.0f * u(rng) + hot * (0.5f + 0.5f * float(c) / 2.0f);
        image.rgba[i * 4 + 3] = 1.0f;
    }
    return image;
}

/// The exposed scene, each pixel the mean of divisor x divisor texels (the last row and column repeated).
ImageF cpuReduce(const ImageF& image, int divisor, float exposure) {
    const int w = (image.width + divisor - 1) / divisor, h = (image.height + divisor - 1) / divisor;
    ImageF out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int j = 0; j < divisor; ++j)
                for (int i = 0; i < divisor; ++i)
                    for (int c = 0; c < 3; ++c)
                        out.at(x, y)[c] += image.at(std::min(x * divisor + i, image.width - 1),
                                                    std::min(y * divisor + j, image.height - 1))[c] *
                                           exposure / float(divisor * divisor);
    return out;
}

/// The pixel of an image `extent` wide that the padding of an FFT line of `size` repeats at `i`: the image's
/// own, or the nearer edge's (across the wrap-around, the first).
int padded(int i, int extent, int size) {
    const int m = ((i % size) + size) % size;
    return m < extent ? m : (m - extent < size - m ? extent - 1 : 0);
}

/// The direct convolution, with the padding of an FFT of `size` around the image.
ImageF cpuConvolve(const ImageF& image, const GlareKernelImage& k, Extent size) {
    ImageF out(image.width, image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            double sum[3] = {};
            for (int dy = -k.radius; dy <= k.radius; ++dy)
                for (int dx = -k.radius; dx <= k.radius; ++dx) {
                    const float* p = image.at(padded(x - dx, image.width, size.width),
                                              padded(y - dy, image.height, size.height));
                    const double w = k.at(dx, dy);
                    for (int c = 0; c < 3; ++c)
                        sum[c] += w * p[c];
                }
            for (int c = 0; c < 3; ++c)
                out.at(x, y)[c] = float(sum[c]);
        }
    return out;
}

BloomSettings glareSettings(GlareKernel kernel, float radiusDeg) {
    BloomSettings b;
    b.mode = BloomMode::Glare;
    b.intensity = 1.0f;
    b.glareKernel = kernel;
    b.glareRadiusDeg = radiusDeg;
    b.glareBlades = 5;
    b.glareBladeRotationDeg = 20.0f;
    return b;
}

Settings glareFrame(float fovDeg, float radiusDeg, GlareKernel kernel = GlareKernel::Eye) {
    Settings s = glow::measured(Settings{});
    s.bloom = glareSettings(kernel, radiusDeg);
    s.bloom.fieldOfViewDeg = fovDeg;
    return s;
}

} // namespace

// (a) The FFT convolution of small HDR images within 1e-3 of the direct one, with kernels smaller than the
// image, larger than it (padding to 128) and the camera's, at full and half resolution.
TEST_F(GlTest, GlareFftMatchesTheDirectConvolution) {
    const ImageF image = randomHdr(48, 40, 7);
    const float exposure = 1.5f;
    const Buffer state = exposureState(exposure);
    const Texture input = makeTexture(image, "glare twin input");
    struct Case {
        GlareKernel kernel;
        float radiusDeg, fovDeg;
        int divisor;
    };
    for (const Case c : {Case{GlareKernel::Eye, 3.0f, 20.0f, 1}, Case{GlareKernel::Eye, 22.0f, 20.0f, 1},
                         Case{GlareKernel::Camera, 4.0f, 10.0f, 1}, Case{GlareKernel::Eye, 6.0f, 20.0f, 2}}) {
        GlarePass pass;
        pass.setDivisor(c.divisor);
        pass.resize({image.width, image.height});
        const BloomSettings b = glareSettings(c.kernel, c.radiusDeg);
        const ImageF gpu = readTextureF(pass.execute(
            {.scene = &input, .exposureState = &state, .settings = &b, .verticalFovDeg = c.fovDeg}));
        const GlareKernelImage halo =
            glareHalo(sampleGlareKernel(pass.kernelParameters(), pass.kernelRadius()));
        const ImageF cpu = cpuConvolve(cpuReduce(image, c.divisor, exposure), halo, pass.paddedSize());
        ASSERT_EQ(gpu.width, cpu.width);
        ASSERT_EQ(gpu.height, cpu.height);
        const Extent padded = pass.paddedSize();
        EXPECT_GE(padded.width, cpu.width + pass.kernelRadius());
        EXPECT_GE(padded.height, cpu.height + pass.kernelRadius());
        double worst = 0.0;
        for (std::size_t i = 0; i < cpu.pixelCount(); ++i)
            for (std::size_t ch = 0; ch < 3; ++ch) {
                // The glare image holds the halo's share of the glare: the convolution times s.
                const double want = cpu.rgba[i * 4 + ch] * pass.haloShare(), got = gpu.rgba[i * 4 + ch];
                worst = std::max(worst, std::abs(got - want) / want);
            }
        EXPECT_LT(worst, 1e-3) << "radius " << c.radiusDeg << ", divisor " << c.divisor;
        EXPECT_NEAR(gpu.at(3, 5)[3], pass.haloShare(), 1e-3f) << "the halo's share in alpha";
    }
}

// (b) A one-pixel light's glow is the kernel's analytic radial profile: PSF(r) pitch^2 / energy (the kernel's
// normalisation), on the axes and the diagonals, within the glare image's half floats.
TEST_F(GlTest, GlareOfAPointFollowsTheAnalyticProfile) {
    const int size = 96;
    ImageF image(size, size);
    const float value = 1000.0f;
    for (int c = 0; c < 3; ++c)
        image.at(48, 48)[c] = value;
    const Buffer state = exposureState(1.0f);
    const Texture input = makeTexture(image, "glare point");
    GlarePass pass;
    pass.resize({size, size});
    const BloomSettings b = glareSettings(GlareKernel::Eye, 5.0f);
    const ImageF glow = readTextureF(
        pass.execute({.scene = &input, .exposureState = &state, .settings = &b, .verticalFovDeg = 24.0f}));
    const GlareKernelParameters& p = pass.kernelParameters();
    const double pitch = p.degreesPerPixel;
    ASSERT_NEAR(pitch, 0.25, 1e-6);
    const double energy = sampleGlareKernel(p, pass.kernelRadius()).energy; // the kernel's normalisation
    for (const int d : {1, 3, 6, 10, 13}) {
        for (const auto& [dx, dy] : {std::pair{d, 0}, {0, -d}, {d, d}, {-d, d}}) {
            const double r = std::hypot(double(dx), double(dy)) * pitch;
            const double want = value * glarePsf(p, r, 0.0) * pitch * pitch / energy;
            EXPECT_NEAR(glow.at(48 + dx, 48 + dy)[1], want, 2e-3 * want) << dx << ", " << dy;
        }
    }
}

// (c) The eye kernel's glow is round (8 sectors of each annulus within 3% of their mean) and falls off
// monotonically, for points off the pixel grid, small and large, dim and bright, on black and on grey, and
// near a border. The eye's halo falls as 1/r^3 near a light: there a sub-pixel light's few pixels meet the
// kernel sampled at pixel centres, and the annulus 1-3 pixels past the disc's edge is 6.7% out of round at
// worst, where the measure itself reads a continuous, exactly round 1/(r + 0.3)^3 glow of the same discs up to
// 4.2% (a CPU model of the measure): annuli are held to 3% from 2.7 pixels past the disc's edge (from 3.4 for
// the small disc, 5.2 for the large) and the closer annulus to 8%.
TEST_F(GlTest, GlareOfAPointIsRound) {
    std::vector<glow::Source> sources;
    for (const float radius : {0.7f, 2.5f})
        for (const float value : {100.0f, 2000.0f})
            for (const float background : {0.0f, 0.18f})
                for (const auto& [dx, dy] : {std::pair{0.0f, 0.0f}, {0.25f, 0.5f}, {0.5f, 0.5f}})
                    sources.push_back({.x = 80.0f + dx,
                                       .y = 80.0f + dy,
                                       .radius = radius,
                                       .value = value,
                                       .background = background});
    sources.push_back({.x = 14.3f, .y = 80.6f, .radius = 2.5f, .value = 2000.0f});
    sources.push_back({.x = 80.5f, .y = 149.25f, .radius = 0.7f, .value = 100.0f, .background = 0.18f});
    Pipeline pipeline({.settings = glareFrame(20.0f, 8.0f)});
    double worst = 0.0, worstNear = 0.0;
    for (const glow::Source& s : sources) {
        const ImageF point = glow::pointLight(s);
        const ImageF with = sceneOf(pipeline, point);
        const glow::Figures f = glow::measure(with, point, s, s.radius + 2.7f);
        EXPECT_GE(f.annuli, 8) << s.x << ", " << s.y;
        EXPECT_LE(f.worstSpread, 0.03)
            << s.x << ", " << s.y << " r " << s.radius << " v " << s.value << " bg " << s.background;
        EXPECT_LE(f.worstRise, 0.0) << s.x << ", " << s.y << " r " << s.radius;
        const glow::Figures near = glow::measure(with, point, s);
        EXPECT_LE(near.worstSpread, 0.08) << "from the disc's edge + 1: " << s.x << ", " << s.y;
        EXPECT_LE(near.worstRise, 0.0) << s.x << ", " << s.y << " r " << s.radius;
        worstNear = std::max(worstNear, near.worstSpread);
        worst = std::max(worst, f.worstSpread);
    }
    std::printf("glare roundness: worst sector spread %.2f%% (from the disc's edge + 2.7), %.2f%% (+ 1)\n",
                100.0 * worst, 100.0 * worstNear);
    EXPECT_EQ(pipeline.status().bloomLevels, 0) << "the mip chain does not run in glare mode";
    const auto& ran = pipeline.status().ran;
    EXPECT_NE(std::find(ran.begin(), ran.end(), "glare"), ran.end());
    EXPECT_EQ(std::find(ran.begin(), ran.end(), "bloom"), ran.end());
}

// The camera kernel's spikes: as many as the blades (even) or twice (odd), at the blades' angles, alike; and
// between them the veil alone, far below.
TEST_F(GlTest, GlareCameraKernelHasItsSpikes) {
    for (const int blades : {6, 5}) {
        Settings s = glareFrame(10.0f, 6.0f, GlareKernel::Camera);
        s.bloom.glareBlades = blades;
        s.bloom.glareBladeRotationDeg = 0.0f;
        const glow::Source source{.x = 80.5f, .y = 80.5f, .radius = 0.7f, .value = 2000.0f};
        const ImageF point = glow::pointLight(source);
        Pipeline pipeline({.settings = s});
        const ImageF with = sceneOf(pipeline, point);
        const int spikes = blades % 2 == 0 ? blades : 2 * blades;
        // The largest glow of the 3x3 pixels about the point 30 pixels out at `degrees` (a ray is about a
        // pixel wide; the nearest pixel centre may lie half a pixel off it).
        const auto glowAt = [&](double degrees) {
            const double a = degrees * 3.14159265358979 / 180.0, r = 30.0;
            const int x = int(std::floor(source.x + r * std::cos(a))),
                      y = int(std::floor(source.y + r * std::sin(a)));
            double most = 0.0;
            for (int j = -1; j <= 1; ++j)
                for (int i = -1; i <= 1; ++i)
                    most =
                        std::max(most, double(with.at(x + i, y + j)[1]) - double(point.at(x + i, y + j)[1]));
            return most;
        };
        const double first = glowAt(0.0);
        for (int k = 0; k < spikes; ++k) {
            const double on = 360.0 * k / spikes;
            EXPECT_GT(glowAt(on), 3.0 * glowAt(on + 180.0 / spikes)) << blades << " blades, spike " << k;
            EXPECT_NEAR(glowAt(on), first, 0.15 * first) << blades << " blades, spike " << k;
        }
    }
}

// (d) The image sum is kept (1e-3) where the kernel's reach stays inside the image, at any intensity; and
// the frame's GL calls pass the audit.
TEST_F(GlTest, GlareKeepsTheImageSum) {
    const glow::Source source{.x = 80.3f, .y = 79.6f, .radius = 2.5f, .value = 2000.0f, .background = 0.0f};
    ImageF image = glow::pointLight(source);
    for (float intensity : {0.3f, 1.0f}) {
        Settings s = glareFrame(30.0f, 8.0f); // 43 pixels: the glow stays inside
        s.bloom.intensity = intensity;
        Pipeline pipeline({.settings = s});
        GlCallAudit audit; // and its calls break none of the rules NVIDIA's driver reports
        const ImageF out = sceneOf(pipeline, image);
        for (const std::string& problem : audit.problems())
            ADD_FAILURE() << problem;
        EXPECT_NEAR(sumRgb(out) / sumRgb(image), 1.0, 1e-3) << intensity;
        EXPECT_GT(out.at(80, 110)[1], 1e-3f) << "light reaches 30 pixels out";
    }
}

// The kernel's spectrum is computed once per kernel parameters, pitch and size.
TEST_F(GlTest, GlareKernelSpectrumIsCached) {
    const ImageF image = randomHdr(40, 32, 3);
    const Buffer state = exposureState(1.0f);
    const Texture input = makeTexture(image, "glare cache input");
    GlarePass pass;
    pass.resize({image.width, image.height});
    BloomSettings b = glareSettings(GlareKernel::Eye, 3.0f);
    const GlarePass::Inputs in{
        .scene = &input, .exposureState = &state, .settings = &b, .verticalFovDeg = 20.0f};
    (void)pass.execute(in);
    (void)pass.execute(in);
    EXPECT_EQ(pass.kernelBuilds(), 1);
    b.glareRadiusDeg = 4.0f;
    (void)pass.execute(in);
    EXPECT_EQ(pass.kernelBuilds(), 2);
    (void)pass.execute({.scene = &input, .exposureState = &state, .settings = &b, .verticalFovDeg = 30.0f});
    EXPECT_EQ(pass.kernelBuilds(), 3) << "a new field of view is a new pitch";
}

// The host's camera gives the field of view (a kernel's angle in pixels); bloom.fieldOfViewDeg only stands in
// without one.
TEST_F(GlTest, GlareTakesTheCamerasFieldOfView) {
    const ImageF image = glow::pointLight({.x = 80.5f, .y = 80.5f, .radius = 1.5f, .value = 500.0f});
    const Texture input = makeTexture(image, "glare camera input");
    Camera camera;
    camera.verticalFov = 20.0f * 3.14159265f / 180.0f;
    camera.projection = perspectiveProjection(camera.verticalFov, 1.0f, camera.nearPlane, camera.farPlane);
    Pipeline withCamera({.settings = glareFrame(60.0f, 6.0f)});
    withCamera.execute({.color = &input, .camera = &camera}, {});
    const ImageF a = readTextureF(withCamera.sceneReferred());
    Pipeline without({.settings = glareFrame(20.0f, 6.0f)});
    const ImageF b = sceneOf(without, image);
    Pipeline wide({.settings = glareFrame(60.0f, 6.0f)});
    const ImageF c = sceneOf(wide, image);
    EXPECT_NEAR(a.at(100, 80)[1], b.at(100, 80)[1], 1e-3f * b.at(100, 80)[1]) << "the camera's 20 degrees";
    EXPECT_GT(std::abs(c.at(100, 80)[1] - b.at(100, 80)[1]), 0.2f * b.at(100, 80)[1]) << "60 degrees differ";
}

// A frame wider than the longest FFT line (4096) has its halo convolved at half its size, and says so.
TEST_F(GlTest, GlareOfAFrameTooWideForTheFftRunsAtHalfSize) {
    const ImageF image = randomHdr(4200, 8, 5);
    const Buffer state = exposureState(1.0f);
    const Texture input = makeTexture(image, "glare wide input");
    GlarePass pass;
    pass.resize({image.width, image.height});
    const BloomSettings b = glareSettings(GlareKernel::Eye, 6.0f);
    const Texture& glare =
        pass.execute({.scene = &input, .exposureState = &state, .settings = &b, .verticalFovDeg = 20.0f});
    EXPECT_EQ(glare.extent(), (Extent{2100, 4}));
    EXPECT_EQ(pass.paddedSize().width, 4096);
    EXPECT_NEAR(pass.kernelParameters().degreesPerPixel, 5.0f, 1e-6f);
}

// (e) On the LDR path an enabled glare cannot run: it says so (once), and the LDR glow stands in.
TEST_F(GlTest, GlareOnTheLdrPathWarns) {
    std::vector<std::string> warnings;
    const LogSink previous = setLogSink([&](LogLevel level, std::string_view m) {
        if (level == LogLevel::Warning)
            warnings.emplace_back(m);
    });
    Settings s = glareFrame(20.0f, 8.0f);
    s.quality = Quality::Legacy;
    Pipeline pipeline({.settings = s});
    const glow::Source source{.x = 80.5f, .y = 80.5f, .radius = 2.5f, .value = 100.0f};
    const ImageF out = sceneOf(pipeline, glow::pointLight(source));
    (void)sceneOf(pipeline, glow::pointLight(source));
    setLogSink(previous);
    EXPECT_EQ(pipeline.status().path, ColorPath::Ldr);
    const auto named = std::count_if(warnings.begin(), warnings.end(), [](const std::string& w) {
        return w.find("bloom.mode = glare") != std::string::npos && w.find("LDR") != std::string::npos;
    });
    EXPECT_EQ(named, 1) << "one warning, naming the mode and the path";
}

} // namespace photopic::test
