// GPU metering (passes/metering/) against the CPU source of truth (core/Metering.h) on small images. The pass
// reads RGBA32F textures here so the CPU sees exactly the values the GPU reads; pipeline-level tests
// (half-float sanitised input) are in test_autoexposure_gpu.cpp.

#include "GlTest.h"

#include "core/Metering.h"
#include "gl/Capabilities.h"
#include "gl/ReadbackRing.h"
#include "gl/ShaderLibrary.h"
#include "gl/TextureIo.h"
#include "passes/Bindings.h"
#include "passes/metering/MeteringPass.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace photopic::test {

namespace {

/// The first `bytes` of a GPU buffer, through a mapped copy as the pipeline reads them (a direct
/// glGetNamedBufferSubData makes NVIDIA's driver move the working buffer to host memory, which the GL
/// fixture counts as a failure there).
void readBuffer(const Buffer& buffer, std::size_t bytes, void* out) {
    ReadbackRing ring(bytes, 1, "test readback");
    ring.enqueue(buffer, 0, 0);
    for (const ReadbackRing::Result& r : ring.drain()) {
        std::memcpy(out, r.bytes.data(), bytes);
    }
}

/// Log-uniform grey-ish luminance in [2^lo, 2^hi], a few exact zeros (underflow bin) and tinted pixels.
ImageF randomImage(int w, int h, unsigned seed, float lo = -14.0f, float hi = 18.0f) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> stops(lo, hi);
    std::uniform_real_distribution<float> tint(0.5f, 1.5f);
    ImageF image(w, h, 1.0f);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            float* p = image.at(x, y);
            const float v = (x * 7 + y * 3) % 53 == 0 ? 0.0f : std::exp2(stops(rng));
            p[0] = v * tint(rng);
            p[1] = v;
            p[2] = v * tint(rng);
        }
    }
    return image;
}

struct GpuMetering {
    Histogram histogram;
    GpuMeteringHeader header;
};

/// `rows`: which shader meters without a histogram (the row shader, or the block shader; by default the one
/// the device gets).
GpuMetering meterOnGpu(const ImageF& image, const AutoExposureSettings& settings,
                       MeteringPass::Weights weights, bool histogram, const ImageF* mask = nullptr,
                       std::optional<bool> rows = std::nullopt) {
    const Texture texture = makeTexture(image, "metering input");
    Texture maskTexture;
    if (mask) {
        maskTexture = makeTexture(*mask, "metering mask");
    }
    MeteringPass pass;
    if (rows) {
        pass.setRowShaderWithoutHistogram(*rows);
    }
    pass.resize(texture.extent());
    const MeteringPass::Outputs out = pass.execute({.scene = &texture,
                                                    .mask = mask ? &maskTexture : nullptr,
                                                    .settings = &settings,
                                                    .histogram = histogram,
                                                    .weights = weights,
                                                    .timers = nullptr});
    GpuMetering result;
    result.histogram.log2Min = settings.histogramLog2Min;
    result.histogram.log2Max = settings.histogramLog2Max;
    readBuffer(*out.histogram, kGpuHistogramBytes, result.histogram.bins.data());
    readBuffer(*out.metering, sizeof(GpuMeteringHeader), &result.header);
    return result;
}

} // namespace

TEST_F(GlTest, GpuHistogramMatchesCoreBinCounts) {
    AutoExposureSettings settings;
    settings.histogramLog2Min = -10.0f; // narrower than the image: both underflow and overflow bins fill
    settings.histogramLog2Max = 12.0f;
    for (const auto [w, h] : {std::pair{61, 37}, std::pair{200, 130}}) {
        const ImageF image = randomImage(w, h, 7u + unsigned(w));
        const GpuMetering gpu = meterOnGpu(image, settings, MeteringPass::Weights::None, true);
        const Histogram cpu = buildHistogram(image, settings.histogramLog2Min, settings.histogramLog2Max);
        std::uint64_t total = 0;
        std::uint64_t moved = 0;
        for (int b = 0; b < kHistogramBins; ++b) {
            total += gpu.histogram.bins[std::size_t(b)];
            const auto g = std::int64_t(gpu.histogram.bins[std::size_t(b)]);
            const auto c = std::int64_t(cpu.bins[std::size_t(b)]);
            moved += std::uint64_t(std::max<std::int64_t>(0, g - c));
            // A pixel whose log2 lies within an ulp of a bin edge may land in the neighbouring bin (GPU log2
            // is not correctly rounded); anything else is a real difference.
            EXPECT_LE(std::abs(g - c), 2) << "bin " << b << " at " << w << "x" << h;
        }
        EXPECT_EQ(total, std::uint64_t(w) * std::uint64_t(h));
        EXPECT_LE(moved, std::uint64_t(w) * std::uint64_t(h) / 500 + 1) << "too many boundary flips";
        EXPECT_GT(gpu.histogram.bins[0], 0u);
        EXPECT_GT(gpu.histogram.bins[255], 0u);
    }
}

// A histogram without a weighted mean runs the run-length kernel (metering_histogram.comp.glsl); with a mean,
// the one-pixel-per-invocation block shader, or on a software renderer the row shader beside the run-length
// kernel. All must give the same bins, extremes (and reading) to the bit, on widths that
// end inside a group's span, with non-finite, negative, zero and denormal pixels, and with long runs of one
// bin (a smooth ramp) beside pixels that change bin at every step.
TEST_F(GlTest, HistogramKernelGivesTheSameBinsAndExtremesAsTheMeanKernel) {
    AutoExposureSettings settings;
    settings.histogramLog2Min = -10.0f;
    settings.histogramLog2Max = 12.0f;
    for (const auto [w, h] : {std::pair{61, 37}, std::pair{300, 50}, std::pair{129, 17}}) {
        ImageF image = randomImage(w, h, 11u + unsigned(w));
        for (int y = 0; y < h / 2; ++y) { // the upper half: a smooth ramp, a bin held over many pixels
            for (int x = 0; x < w; ++x) {
                const float v = std::exp2(-12.0f + 26.0f * float(x) / float(w));
                image.at(x, y)[0] = image.at(x, y)[1] = image.at(x, y)[2] = v;
            }
        }
        image.at(1, h - 1)[1] = std::numeric_limits<float>::quiet_NaN();
        image.at(2, h - 1)[0] = std::numeric_limits<float>::infinity();
        image.at(3, h - 1)[2] = -std::numeric_limits<float>::infinity();
        image.at(4, h - 1)[1] = -3.0f;
        image.at(5, h - 1)[1] = 1e-40f; // denormal
        image.at(w - 1, h - 1)[1] = 3e38f;
        const GpuMetering runs = meterOnGpu(image, settings, MeteringPass::Weights::None, true);
        // With a mean: the block shader building both, or the row shader beside the run-length kernel.
        const GpuMetering mean =
            meterOnGpu(image, settings, MeteringPass::Weights::Average, true, nullptr, false);
        const GpuMetering split =
            meterOnGpu(image, settings, MeteringPass::Weights::Average, true, nullptr, true);
        EXPECT_EQ(runs.histogram.bins, mean.histogram.bins) << w << "x" << h;
        EXPECT_EQ(runs.header.minBits, mean.header.minBits) << w << "x" << h;
        EXPECT_EQ(runs.header.maxBits, mean.header.maxBits) << w << "x" << h;
        EXPECT_EQ(split.histogram.bins, mean.histogram.bins) << w << "x" << h;
        EXPECT_EQ(split.header.minBits, mean.header.minBits) << w << "x" << h;
        EXPECT_EQ(split.header.maxBits, mean.header.maxBits) << w << "x" << h;
        EXPECT_EQ(split.header.reading, mean.header.reading) << w << "x" << h;
        EXPECT_GT(mean.header.reading, 0.0f);
        std::uint64_t total = 0;
        for (const auto c : runs.histogram.bins) {
            total += c;
        }
        EXPECT_EQ(total, std::uint64_t(w) * std::uint64_t(h)) << "sanitised, every pixel has a bin";
    }
}

TEST_F(GlTest, GpuHistogramIsClearedEachFrame) {
    const ImageF image = randomImage(40, 24, 3u);
    const Texture texture = makeTexture(image, "input");
    AutoExposureSettings settings;
    MeteringPass pass;
    pass.resize(texture.extent());
    std::array<std::uint32_t, 256> bins{};
    for (int frame = 0; frame < 3; ++frame) {
        const auto out = pass.execute({.scene = &texture, .settings = &settings, .histogram = true});
        readBuffer(*out.histogram, kGpuHistogramBytes, bins.data());
        std::uint64_t total = 0;
        for (auto c : bins) {
            total += c;
        }
        EXPECT_EQ(total, 40u * 24u) << "frame " << frame;
    }
}

TEST_F(GlTest, GpuAverageMatchesMeterAverageEveryPixel) {
    AutoExposureSettings settings;
    for (const auto [w, h] : {std::pair{61, 37}, std::pair{333, 190}}) {
        const ImageF image = randomImage(w, h, 11u + unsigned(h), -8.0f, 8.0f);
        const GpuMetering gpu = meterOnGpu(image, settings, MeteringPass::Weights::Average, false);
        const float cpu = meterAverage(image);
        EXPECT_NEAR(gpu.header.reading / cpu, 1.0f, 1e-3f) << w << "x" << h;
        // Every meterable pixel weighs 1: the weight sum is the meterable pixel count.
        int meterable = 0;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                meterable += isMeterableLuminance(pixelLuminance(image, x, y)) ? 1 : 0;
            }
        }
        EXPECT_FLOAT_EQ(gpu.header.weightSum, float(meterable));
    }
}

TEST_F(GlTest, GpuMinMaxLuminanceAreTheImagesExtremes) {
    const ImageF image = randomImage(45, 30, 5u, -6.0f, 6.0f);
    float lo = 1e30f, hi = 0.0f;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const float l = pixelLuminance(image, x, y);
            if (isMeterableLuminance(l)) {
                lo = std::min(lo, l);
                hi = std::max(hi, l);
            }
        }
    }
    const GpuMetering gpu = meterOnGpu(image, AutoExposureSettings{}, MeteringPass::Weights::Average, false);
    EXPECT_NEAR(std::bit_cast<float>(gpu.header.minBits) / lo, 1.0f, 1e-5f);
    EXPECT_NEAR(std::bit_cast<float>(gpu.header.maxBits) / hi, 1.0f, 1e-5f);
}

TEST_F(GlTest, GpuCenterAndMaskMeteringMatchCore) {
    const ImageF image = randomImage(64, 36, 21u, -6.0f, 6.0f);
    AutoExposureSettings settings;
    const GpuMetering centre = meterOnGpu(image, settings, MeteringPass::Weights::Center, false);
    EXPECT_NEAR(centre.header.reading / meterCenter(image), 1.0f, 1e-3f);

    // A mask of a different size: left third weight 0, the rest a ramp; one NaN weight (ignored).
    ImageF mask(10, 7, 0.0f);
    for (int y = 0; y < mask.height; ++y) {
        for (int x = 0; x < mask.width; ++x) {
            const float w = x < 3 ? 0.0f : float(x + y) / 10.0f;
            mask.at(x, y)[0] = mask.at(x, y)[1] = mask.at(x, y)[2] = w;
        }
    }
    mask.at(5, 2)[1] = std::nanf("");
    const GpuMetering masked = meterOnGpu(image, settings, MeteringPass::Weights::Mask, false, &mask);
    EXPECT_NEAR(masked.header.reading / meterMasked(image, mask), 1.0f, 1e-3f);
}

TEST_F(GlTest, GpuSpotFollowsItsDisc) {
    // Dark frame, one bright disc at (0.25, 0.3) in image UV (v down): the spot reads the disc only when it
    // is over it, whatever the tap count, and always agrees with core's meterSpot.
    const int w = 96, h = 64;
    ImageF image(w, h, 0.01f);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float u = (float(x) + 0.5f) / float(w);
            const float v = (float(y) + 0.5f) / float(h);
            const float dx = (u - 0.25f) * float(w) / float(h);
            const float dy = v - 0.3f;
            if (dx * dx + dy * dy <= 0.15f * 0.15f) {
                image.at(x, y)[0] = image.at(x, y)[1] = image.at(x, y)[2] = 4.0f;
            }
        }
    }
    AutoExposureSettings settings;
    settings.spot.radius = 0.1f;
    for (int taps : {1, 5, 9, 13}) {
        settings.spot.taps = taps;
        settings.spot.u = 0.25f;
        settings.spot.v = 0.3f;
        const GpuMetering on = meterOnGpu(image, settings, MeteringPass::Weights::Spot, false);
        EXPECT_NEAR(on.header.reading, 4.0f, 4e-3f) << taps << " taps";
        EXPECT_NEAR(on.header.reading / meterSpot(image, settings.spot), 1.0f, 1e-4f);
        settings.spot.v = 0.7f; // mirrored below: a v that ran up would land on the disc
        const GpuMetering off = meterOnGpu(image, settings, MeteringPass::Weights::Spot, false);
        EXPECT_NEAR(off.header.reading, 0.01f, 1e-5f) << taps << " taps";
        EXPECT_NEAR(off.header.reading / meterSpot(image, settings.spot), 1.0f, 1e-4f);
    }
    // Half on the disc's edge: some taps bright, some dark, still the same geometric mean as core.
    settings.spot = {.u = 0.25f + 0.15f * float(h) / float(w), .v = 0.3f, .radius = 0.1f, .taps = 13};
    const GpuMetering edge = meterOnGpu(image, settings, MeteringPass::Weights::Spot, false);
    EXPECT_NEAR(edge.header.reading / meterSpot(image, settings.spot), 1.0f, 1e-4f);
    EXPECT_GT(edge.header.reading, 0.02f);
    EXPECT_LT(edge.header.reading, 3.0f);
}

} // namespace photopic::test

namespace photopic::test {

// Without a histogram, a software renderer meters with the barrier-free row shader and a GPU with the block
// shader: the same reading in every weighted mode (odd size: partial blocks at two edges). Bit for bit on a
// software renderer, where the row shader runs; a GPU's compiler may fuse the two shaders' multiply-adds
// differently (an NVIDIA H200 differed in the last bits), so there within a few float steps.
TEST_F(GlTest, RowAndBlockMeteringShadersGiveTheSameReading) {
    const ImageF image = randomImage(157, 93, 7u);
    ImageF mask(157, 93, 0.0f);
    for (int y = 0; y < 93; ++y) {
        for (int x = 0; x < 157; ++x) {
            mask.at(x, y)[0] = float((x * 3 + y) % 11) / 10.0f;
        }
    }
    AutoExposureSettings settings;
    for (const MeteringPass::Weights weights :
         {MeteringPass::Weights::Average, MeteringPass::Weights::Center, MeteringPass::Weights::Mask}) {
        const ImageF* m = weights == MeteringPass::Weights::Mask ? &mask : nullptr;
        const GpuMetering rows = meterOnGpu(image, settings, weights, false, m, true);
        const GpuMetering block = meterOnGpu(image, settings, weights, false, m, false);
        EXPECT_GT(rows.header.reading, 0.0f);
        if (isSoftwareRenderer()) {
            EXPECT_EQ(rows.header.reading, block.header.reading) << int(weights);
            EXPECT_EQ(rows.header.weightSum, block.header.weightSum) << int(weights);
        } else {
            EXPECT_NEAR(rows.header.reading / block.header.reading, 1.0f, 1e-6f) << int(weights);
            EXPECT_NEAR(rows.header.weightSum / block.header.weightSum, 1.0f, 1e-6f) << int(weights);
        }
        EXPECT_EQ(rows.header.minBits, block.header.minBits);
        EXPECT_EQ(rows.header.maxBits, block.header.maxBits);
    }
}

// divideRounded (passes/metering/metering.h.glsl), which the histogram statistics divide with, is the CPU's
// division to the bit: GLSL lets a GPU's division be 2.5 ulp off (NVIDIA's is), and a compiler that fused or
// reordered the steps of the remainder would undo the correction. Quotients of both signs across 2^-40..2^40,
// exact ones, a zero dividend, and the statistics' own (the histogram's range over its 254 bins).
TEST_F(GlTest, DivideRoundedIsTheCpusDivisionToTheBit) {
    std::vector<float> pairs = {28.0f, 254.0f, 16.0f - -12.0f, 254.0f, 0.0f, 3.0f, 1.0f,
                                3.0f,  -7.0f,  7.0f,           1e6f,   3.0f, 2.0f, 10.0f};
    std::mt19937 rng(29u);
    std::uniform_real_distribution<float> exponent(-20.0f, 20.0f);
    while (pairs.size() < 2 * 4096) {
        pairs.push_back(std::exp2(exponent(rng)) * ((rng() & 1u) != 0u ? -1.0f : 1.0f));
        pairs.push_back(std::exp2(exponent(rng)) * ((rng() & 1u) != 0u ? -1.0f : 1.0f));
    }
    const std::size_t count = pairs.size() / 2;
    const std::string source = preprocessShader("passes/metering/metering.h.glsl") + R"(
        layout(local_size_x = 64) in;
        layout(std430, binding = 0) readonly buffer Pairs { vec2 uPairs[]; };
        layout(std430, binding = 1) writeonly buffer Quotients { float uQuotients[]; };
        void main() {
            uint i = gl_GlobalInvocationID.x;
            if (i < uint(uPairs.length())) {
                uQuotients[i] = divideRounded(uPairs[i].x, uPairs[i].y);
            }
        })";
    const Program program = makeComputeProgramFromSource(source, "test divideRounded");

    const Buffer in({.size = pairs.size() * sizeof(float),
                     .flags = 0,
                     .data = pairs.data(),
                     .debugName = "test divideRounded pairs"});
    const Buffer out(
        {.size = count * sizeof(float), .flags = 0, .debugName = "test divideRounded quotients"});
    program.use();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
    glDispatchCompute(GLuint((count + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glUseProgram(0);
    std::vector<float> quotients(count);
    readBuffer(out, count * sizeof(float), quotients.data());
    int wrong = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const float want = pairs[2 * i] / pairs[2 * i + 1];
        if (std::memcmp(&quotients[i], &want, sizeof(float)) != 0 && ++wrong <= 5) {
            ADD_FAILURE() << pairs[2 * i] << " / " << pairs[2 * i + 1] << ": " << quotients[i] << ", the CPU "
                          << want;
        }
    }
    EXPECT_EQ(wrong, 0) << "of " << count << " quotients";
}

} // namespace photopic::test
