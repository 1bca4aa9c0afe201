// The ZIP / ZIPS scanline decoder (io/ExrZip.cpp: OpenEXR's core library with libdeflate's inflate) against
// Imf::InputFile::readPixels on the same bytes and the same frame buffer: every value the same to the bit,
// for both compressions, half and float channels (into float slices, and half ones into half slices), odd
// sizes (a last chunk shorter than the others, byte
// counts that do not fill the codec's 16- and 32-byte steps), a data window away from the origin, channels
// the frame buffer does not ask for and slices the file has no channel for. Files it does not decode, and
// damaged ones, are left to Imf::InputFile.

#include "io/ExrDetail.h"
#include "io/ImageIO.h"

#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfThreading.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace photopic {
namespace {

namespace fs = std::filesystem;

struct FileSpec {
    Imf::Compression compression = Imf::ZIP_COMPRESSION;
    Imf::PixelType type = Imf::HALF;
    int width = 37;
    int height = 23;
    Imath::V2i origin{0, 0};
    bool alpha = false; ///< an A channel as well (a renderer's RGBA: A, B, G, R in the file's order)
    bool noise = true;  ///< values over many magnitudes; false: a smooth ramp that deflates well
    bool extras = true; ///< channels Z and "motion.X" besides the colour
};

/// A file with channels B, G, R (of `spec.type`), Z (float) and "motion.X" (half), values spread over many
/// magnitudes with signs, zeros, denormals and non-finite values, written by OpenEXR itself.
std::vector<unsigned char> makeExr(const FileSpec& spec, const fs::path& path) {
    const Imath::Box2i window(spec.origin, spec.origin + Imath::V2i(spec.width - 1, spec.height - 1));
    Imf::Header header(window, window);
    header.compression() = spec.compression;
    for (const char* name : {"R", "G", "B"})
        header.channels().insert(name, Imf::Channel(spec.type));
    if (spec.alpha)
        header.channels().insert("A", Imf::Channel(spec.type));
    if (spec.extras) {
        header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
        header.channels().insert("motion.X", Imf::Channel(Imf::HALF));
    }

    const std::size_t n = std::size_t(spec.width) * std::size_t(spec.height);
    std::mt19937 random(1234u + unsigned(spec.width));
    std::uniform_real_distribution<float> exponent(-20.0f, 15.0f);
    std::vector<float> values(n * 6);
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!spec.noise) {
            values[i] = float(i % 97) * 0.01f;
            continue;
        }
        float v = std::exp2(exponent(random)) * ((random() & 1u) != 0 ? -1.0f : 1.0f);
        switch (random() % 64u) {
        case 0:
            v = 0.0f;
            break;
        case 1:
            v = std::numeric_limits<float>::quiet_NaN();
            break;
        case 2:
            v = std::numeric_limits<float>::infinity();
            break;
        case 3:
            v = 1e-42f;
            break;
        default:
            break;
        }
        values[i] = v;
    }
    std::vector<half> halves(values.begin(), values.end());
    Imf::FrameBuffer frameBuffer;
    const char* names[] = {"R", "G", "B", "Z", "motion.X", "A"};
    for (int c = 0; c < (spec.alpha ? 6 : 5); ++c) {
        if (!spec.extras && (c == 3 || c == 4))
            continue;
        const bool isHalf = ((c < 3 || c == 5) && spec.type == Imf::HALF) || c == 4;
        char* base = isHalf ? reinterpret_cast<char*>(halves.data() + std::size_t(c) * n)
                            : reinterpret_cast<char*>(values.data() + std::size_t(c) * n);
        const std::size_t element = isHalf ? sizeof(half) : sizeof(float);
        frameBuffer.insert(names[c], Imf::Slice::Make(isHalf ? Imf::HALF : Imf::FLOAT, base, window, element,
                                                      element * std::size_t(spec.width)));
    }
    {
        Imf::OutputFile file(path.c_str(), header);
        file.setFrameBuffer(frameBuffer);
        file.writePixels(spec.height);
    }
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// RGBA interleaved (A absent from the file: filled with 1) and Z planar, as the readers lay them out, plus a
/// slice "W" the file lacks (filled with 0.25). "motion.X" is in the file and not asked for.
struct Pixels {
    std::vector<float> rgba;
    std::vector<float> z;
    std::vector<float> w;

    Pixels(const Imath::Box2i& window, Imf::FrameBuffer& frameBuffer) {
        const std::size_t width = std::size_t(window.max.x - window.min.x + 1);
        const std::size_t n = width * std::size_t(window.max.y - window.min.y + 1);
        rgba.assign(n * 4, -7.0f);
        z.assign(n, -7.0f);
        w.assign(n, -7.0f);
        const auto add = [&](const char* name, float* base, std::size_t stride, double fill) {
            frameBuffer.insert(name, Imf::Slice::Make(Imf::FLOAT, base, window, stride * sizeof(float),
                                                      stride * sizeof(float) * width, 1, 1, fill));
        };
        add("R", rgba.data(), 4, 0.0);
        add("G", rgba.data() + 1, 4, 0.0);
        add("B", rgba.data() + 2, 4, 0.0);
        add("A", rgba.data() + 3, 4, 1.0);
        add("Z", z.data(), 1, 0.0);
        add("W", w.data(), 1, 0.25);
    }
};

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

/// What Imf::InputFile::readPixels gives for `bytes`, through the same frame buffer layout (Pixels or
/// HalfPixels).
template <class Layout = Pixels>
Layout readWithImf(const fs::path& path, const std::vector<unsigned char>& bytes) {
    detail::MemoryIStream stream(path, bytes);
    Imf::InputFile file(stream);
    const Imath::Box2i window = file.header().dataWindow();
    Imf::FrameBuffer frameBuffer;
    Layout pixels(window, frameBuffer);
    file.setFrameBuffer(frameBuffer);
    file.readPixels(window.min.y, window.max.y);
    return pixels;
}

class ExrZipTest : public ::testing::TestWithParam<int> {
protected:
    void SetUp() override {
        mPath = fs::temp_directory_path() / ("photopic_exrzip_" + std::to_string(::getpid()) + ".exr");
        Imf::setGlobalThreadCount(GetParam());
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove(mPath, ignored);
        Imf::setGlobalThreadCount(0);
    }

    /// Decodes `bytes` both ways: the fast path must take the file and match Imf bit for bit.
    void expectSameAsImf(const std::vector<unsigned char>& bytes) {
        const Pixels expected = readWithImf(mPath, bytes);
        detail::MemoryIStream stream(mPath, bytes);
        Imf::InputFile file(stream);
        const Imath::Box2i window = file.header().dataWindow();
        Imf::FrameBuffer frameBuffer;
        Pixels actual(window, frameBuffer);
        ASSERT_TRUE(detail::readZipScanlines(bytes, file.header(), frameBuffer));
        EXPECT_TRUE(sameBits(actual.rgba, expected.rgba));
        EXPECT_TRUE(sameBits(actual.z, expected.z));
        EXPECT_TRUE(sameBits(actual.w, expected.w));
        if (file.header().channels().findChannel("A") == nullptr)
            EXPECT_EQ(actual.rgba[3], 1.0f);
        EXPECT_EQ(actual.w[0], 0.25f);
    }

    fs::path mPath;
};

TEST_P(ExrZipTest, ZipHalfMatchesOpenExrBitForBit) {
    expectSameAsImf(makeExr({Imf::ZIP_COMPRESSION, Imf::HALF, 37, 23, {0, 0}}, mPath));
}

TEST_P(ExrZipTest, ZipFloatMatchesOpenExrBitForBit) {
    expectSameAsImf(makeExr({Imf::ZIP_COMPRESSION, Imf::FLOAT, 37, 23, {0, 0}}, mPath));
}

TEST_P(ExrZipTest, ZipsMatchesOpenExrBitForBit) {
    expectSameAsImf(makeExr({Imf::ZIPS_COMPRESSION, Imf::HALF, 19, 40, {0, 0}}, mPath));
    expectSameAsImf(makeExr({Imf::ZIPS_COMPRESSION, Imf::FLOAT, 19, 40, {0, 0}}, mPath));
}

TEST_P(ExrZipTest, RgbaMatchesOpenExrBitForBit) {
    FileSpec spec{Imf::ZIP_COMPRESSION, Imf::HALF, 64, 40, {0, 0}};
    spec.alpha = true;
    expectSameAsImf(makeExr(spec, mPath));
    spec.type = Imf::FLOAT;
    expectSameAsImf(makeExr(spec, mPath));
    spec.noise = false;
    expectSameAsImf(makeExr(spec, mPath));
    // Colour alone: the four channels land interleaved in one RGBA buffer (A, B, G, R at descending offsets).
    spec.extras = false;
    expectSameAsImf(makeExr(spec, mPath));
    spec.type = Imf::HALF;
    spec.noise = true;
    expectSameAsImf(makeExr(spec, mPath));
}

TEST_P(ExrZipTest, DataWindowAwayFromTheOriginMatchesOpenExr) {
    expectSameAsImf(makeExr({Imf::ZIP_COMPRESSION, Imf::HALF, 45, 33, {-3, 5}}, mPath));
    expectSameAsImf(makeExr({Imf::ZIPS_COMPRESSION, Imf::FLOAT, 8, 3, {100, -40}}, mPath));
}

TEST_P(ExrZipTest, OneColumnAndOneRowMatchOpenExr) {
    expectSameAsImf(makeExr({Imf::ZIP_COMPRESSION, Imf::HALF, 1, 17, {0, 0}}, mPath));
    expectSameAsImf(makeExr({Imf::ZIP_COMPRESSION, Imf::FLOAT, 300, 1, {0, 0}}, mPath));
}

TEST_P(ExrZipTest, OtherCompressionsAreLeftToOpenExr) {
    for (const Imf::Compression c : {Imf::NO_COMPRESSION, Imf::PIZ_COMPRESSION, Imf::RLE_COMPRESSION}) {
        const std::vector<unsigned char> bytes = makeExr({c, Imf::HALF, 16, 16, {0, 0}}, mPath);
        detail::MemoryIStream stream(mPath, bytes);
        Imf::InputFile file(stream);
        Imf::FrameBuffer frameBuffer;
        Pixels pixels(file.header().dataWindow(), frameBuffer);
        EXPECT_FALSE(detail::readZipScanlines(bytes, file.header(), frameBuffer)) << int(c);
    }
}

// A damaged chunk fails the fast path, and readImage then reports the file as OpenEXR would, naming it.
TEST_P(ExrZipTest, ADamagedChunkFallsBackAndIsReported) {
    FileSpec spec{Imf::ZIP_COMPRESSION, Imf::HALF, 64, 64, {0, 0}};
    spec.noise = false; // deflated chunks (noise would be stored raw, where damage is only other values)
    std::vector<unsigned char> bytes = makeExr(spec, mPath);
    for (std::size_t i = bytes.size() / 2; i < bytes.size() / 2 + 64; ++i)
        bytes[i] ^= 0x5a;
    {
        detail::MemoryIStream stream(mPath, bytes);
        Imf::InputFile file(stream);
        Imf::FrameBuffer frameBuffer;
        Pixels pixels(file.header().dataWindow(), frameBuffer);
        EXPECT_FALSE(detail::readZipScanlines(bytes, file.header(), frameBuffer));
    }
    {
        std::ofstream out(mPath, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    }
    try {
        (void)readImage(mPath);
        FAIL() << "a damaged chunk was read";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find(mPath.string()), std::string::npos) << e.what();
    }
}

// readImage goes through the fast path for a ZIP file and gives what OpenEXR's own reader gives.
TEST_P(ExrZipTest, ReadImageOfAZipFileMatchesOpenExr) {
    const std::vector<unsigned char> bytes =
        makeExr({Imf::ZIP_COMPRESSION, Imf::HALF, 50, 20, {0, 0}}, mPath);
    const ImageF image = readImage(mPath);
    EXPECT_TRUE(sameBits(image.rgba, readWithImf(mPath, bytes).rgba));
}

/// The colour into half slices (RGBA interleaved, 8-byte pixels; A filled with 1 when absent), Z into a float
/// one, and a half slice "W" the file lacks (filled with 0.25), read by Imf or by the fast path.
struct HalfPixels {
    std::vector<std::uint16_t> rgba;
    std::vector<float> z;
    std::vector<std::uint16_t> w;

    HalfPixels(const Imath::Box2i& window, Imf::FrameBuffer& frameBuffer) {
        const std::size_t width = std::size_t(window.max.x - window.min.x + 1);
        const std::size_t n = width * std::size_t(window.max.y - window.min.y + 1);
        rgba.assign(n * 4, 0x7777);
        z.assign(n, -7.0f);
        w.assign(n, 0x7777);
        const auto add = [&](const char* name, char* base, Imf::PixelType type, std::size_t stride,
                             double fill) {
            frameBuffer.insert(name,
                               Imf::Slice::Make(type, base, window, stride, stride * width, 1, 1, fill));
        };
        const auto rgbaBase = [&](int c) { return reinterpret_cast<char*>(rgba.data() + c); };
        add("R", rgbaBase(0), Imf::HALF, 8, 0.0);
        add("G", rgbaBase(1), Imf::HALF, 8, 0.0);
        add("B", rgbaBase(2), Imf::HALF, 8, 0.0);
        add("A", rgbaBase(3), Imf::HALF, 8, 1.0);
        add("Z", reinterpret_cast<char*>(z.data()), Imf::FLOAT, 4, 0.0);
        add("W", reinterpret_cast<char*>(w.data()), Imf::HALF, 2, 0.25);
    }
};

// Half channels into half slices: the bits as stored, as Imf gives them, with or without an A channel (four
// lanes of a pixel, or three and a fill), colour alone or with other channels, at odd widths.
TEST_P(ExrZipTest, HalfSlicesOfHalfChannelsMatchOpenExrBitForBit) {
    for (const bool alpha : {false, true}) {
        for (const bool extras : {false, true}) {
            for (const int width : {37, 64, 1}) {
                FileSpec spec{Imf::ZIP_COMPRESSION, Imf::HALF, width, 19, {2, -3}};
                spec.alpha = alpha;
                spec.extras = extras;
                const std::vector<unsigned char> bytes = makeExr(spec, mPath);
                const std::string what = std::string(alpha ? "RGBA" : "RGB") + (extras ? " + Z" : "") +
                                         ", width " + std::to_string(width);
                const HalfPixels expected = readWithImf<HalfPixels>(mPath, bytes);
                detail::MemoryIStream stream(mPath, bytes);
                Imf::InputFile file(stream);
                Imf::FrameBuffer fastBuffer;
                HalfPixels actual(file.header().dataWindow(), fastBuffer);
                ASSERT_TRUE(detail::readZipScanlines(bytes, file.header(), fastBuffer)) << what;
                EXPECT_EQ(actual.rgba, expected.rgba) << what;
                EXPECT_TRUE(sameBits(actual.z, expected.z)) << what;
                EXPECT_EQ(actual.w, expected.w) << what;
                EXPECT_EQ(actual.w[0], 0x3400) << what; // 0.25
                if (!alpha)
                    EXPECT_EQ(actual.rgba[3], 0x3C00) << what; // 1.0
                // The halves are the file's: widened, they are what the float slices read.
                const Pixels floats = readWithImf(mPath, bytes);
                std::vector<float> widened(actual.rgba.size());
                for (std::size_t i = 0; i < widened.size(); ++i) {
                    half h;
                    h.setBits(actual.rgba[i]);
                    widened[i] = float(h);
                }
                EXPECT_TRUE(sameBits(widened, floats.rgba)) << what;
            }
        }
    }
}

// A float channel into a half slice is a rounding: left to Imf.
TEST_P(ExrZipTest, HalfSlicesOfFloatChannelsAreLeftToOpenExr) {
    const std::vector<unsigned char> bytes =
        makeExr({Imf::ZIP_COMPRESSION, Imf::FLOAT, 16, 16, {0, 0}}, mPath);
    detail::MemoryIStream stream(mPath, bytes);
    Imf::InputFile file(stream);
    Imf::FrameBuffer frameBuffer;
    HalfPixels pixels(file.header().dataWindow(), frameBuffer);
    EXPECT_FALSE(detail::readZipScanlines(bytes, file.header(), frameBuffer));
}

// With no worker threads the chunks decode on the caller's thread; with several, on OpenEXR's pool.
INSTANTIATE_TEST_SUITE_P(Threads, ExrZipTest, ::testing::Values(0, 3));

} // namespace
} // namespace photopic
