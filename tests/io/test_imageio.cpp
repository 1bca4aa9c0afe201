#include "io/ImageIO.h"

#include "TestData.h"

#include "common/TempFolder.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace photopic {
namespace {

namespace fs = std::filesystem;

std::string readFileBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeFileBytes(const fs::path& path, std::string_view bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
}

/// Runs `action`, expecting an IoError whose message names `path` and contains `fragment`.
void expectIoError(const std::function<void()>& action, const fs::path& path,
                   const std::string& fragment = "") {
    try {
        action();
        ADD_FAILURE() << "no IoError for " << path;
    } catch (const IoError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(path.string()), std::string::npos)
            << "message does not name the path: " << message;
        EXPECT_NE(message.find(fragment), std::string::npos)
            << "message lacks \"" << fragment << "\": " << message;
    }
}

const ImageF& dataImage(const std::string& name) {
    // Each data image is decoded once per test run: they take tens of ms each.
    static std::map<std::string, ImageF> cache;
    auto it = cache.find(name);
    if (it == cache.end())
        it = cache.emplace(name, readImage(test::dataDir() / name)).first;
    return it->second;
}

struct LumaStats {
    double min = INFINITY;
    double max = -INFINITY;
    double mean = 0.0;
};

/// Rec.709 luma of the stored linear values, as in SOURCES.md.
LumaStats lumaStats(const ImageF& image) {
    LumaStats stats;
    double sum = 0.0;
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        const float* p = image.rgba.data() + i * 4;
        const double y = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
        stats.min = std::min(stats.min, y);
        stats.max = std::max(stats.max, y);
        sum += y;
    }
    stats.mean = sum / double(image.pixelCount());
    return stats;
}

/// A figure as printed in SOURCES.md: matches within 1 % or within half a unit of its last printed digit,
/// whichever is looser (-0.00014 is printed to 2 significant digits, so 1 % would be tighter than the table
/// itself).
struct Printed {
    double value;
    double lastDigit;

    [[nodiscard]] double tolerance() const { return std::max(0.01 * std::abs(value), 0.5 * lastDigit); }
};

struct DataCase {
    const char* file;
    int width;
    int height;
    Printed yMin;
    Printed yMax;
    Printed yMean;
};

class SharedData : public ::testing::TestWithParam<DataCase> {};

TEST_P(SharedData, SizeAndLuminanceMatchSources) {
    const DataCase& c = GetParam();
    ASSERT_TRUE(fs::exists(test::dataDir() / c.file)) << "missing test image " << test::dataDir() / c.file;
    const ImageF& image = dataImage(c.file);
    EXPECT_EQ(image.width, c.width);
    EXPECT_EQ(image.height, c.height);
    ASSERT_EQ(image.rgba.size(), std::size_t(c.width) * std::size_t(c.height) * 4);
    EXPECT_TRUE(std::all_of(image.rgba.begin(), image.rgba.end(), [](float v) { return std::isfinite(v); }));

    const LumaStats stats = lumaStats(image);
    EXPECT_NEAR(stats.min, c.yMin.value, c.yMin.tolerance());
    EXPECT_NEAR(stats.max, c.yMax.value, c.yMax.tolerance());
    EXPECT_NEAR(stats.mean, c.yMean.value, c.yMean.tolerance());
}

// Figures from data/SOURCES.md.
INSTANTIATE_TEST_SUITE_P(
    Sources, SharedData,
    ::testing::Values(DataCase{"GoldenGate.exr", 1262, 860, {0.00099, 1e-5}, {292, 1}, {0.110, 1e-3}},
                      DataCase{"Desk.exr", 644, 874, {-0.0086, 1e-4}, {202, 1}, {5.82, 1e-2}},
                      DataCase{
                          "blender_sunrise.exr", 1024, 512, {-0.00014, 1e-5}, {32744, 1}, {0.486, 1e-3}}),
    [](const auto& testInfo) {
        std::string name = testInfo.param.file;
        name.erase(name.find('.'));
        return name;
    });

TEST(SharedImages, DeskHdrClampsNegativesAndMatchesDeskExr) {
    const ImageF& hdr = dataImage("Desk.hdr");
    const ImageF& exr = dataImage("Desk.exr");
    ASSERT_EQ(hdr.width, 644);
    ASSERT_EQ(hdr.height, 874);
    const LumaStats hdrStats = lumaStats(hdr);
    const LumaStats exrStats = lumaStats(exr);
    EXPECT_LT(exrStats.min, 0.0);
    EXPECT_EQ(hdrStats.min, 0.0) << "RGBE cannot store negatives";
    EXPECT_NEAR(hdrStats.max, exrStats.max, 0.01 * exrStats.max);
    // RGBE keeps 8 mantissa bits per channel: the means agree far better than 1 %.
    EXPECT_NEAR(hdrStats.mean, exrStats.mean, 0.01 * exrStats.mean);
    EXPECT_TRUE(std::all_of(hdr.rgba.begin(), hdr.rgba.end(), [](float v) { return v >= 0.0f; }));
}

// ---------------------------------------------------------------------------------------------------------------
// Round trips

TEST(ImageIO, ExrRoundTripKeepsHalfPrecision) {
    test::TempFolder dir;
    ImageF image(37, 23);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            float* p = image.at(x, y);
            p[0] = float(x - 5) * 0.37f;                             // negatives
            p[1] = std::pow(2.0f, float(y) - 12.0f) * 1.2345f;       // 2^-12 .. 2^10
            p[2] = float(x * y) * 31.7f;                             // up to ~25000
            p[3] = float(x + y) / float(image.width + image.height); // alpha 0..1
        }
    }
    const fs::path path = dir / "round.exr";
    writeExr(path, image);
    EXPECT_EQ(dir.listing(), std::vector<std::string>{"round.exr"});

    const ImageF back = readImage(path);
    ASSERT_EQ(back.width, image.width);
    ASSERT_EQ(back.height, image.height);
    float maxRelative = 0.0f;
    for (std::size_t i = 0; i < image.rgba.size(); ++i) {
        // Half keeps 11 significant bits: relative error <= 2^-11 after rounding, and ~6e-8 absolute near
        // zero.
        const float expected = image.rgba[i];
        EXPECT_NEAR(back.rgba[i], expected, std::abs(expected) * 0x1p-11f + 6e-8f) << "value " << i;
        if (expected != 0.0f)
            maxRelative = std::max(maxRelative, std::abs(back.rgba[i] - expected) / std::abs(expected));
    }
    EXPECT_LE(maxRelative, 0x1p-11f);
}

TEST(ImageIO, ExrClampsBeyondHalfRange) {
    test::TempFolder dir;
    ImageF image(2, 1);
    image.rgba = {1e6f, -1e6f, INFINITY, 1.0f, NAN, 65504.0f, 0.0f, 1.0f};
    writeExr(dir / "range.exr", image);
    const ImageF back = readImage(dir / "range.exr");
    EXPECT_EQ(back.rgba[0], 65504.0f);
    EXPECT_EQ(back.rgba[1], -65504.0f);
    EXPECT_EQ(back.rgba[2], INFINITY);
    EXPECT_TRUE(std::isnan(back.rgba[4]));
    EXPECT_EQ(back.rgba[5], 65504.0f);
}

Image8 patternImage(int width, int height, bool opaque) {
    Image8 image(width, height);
    for (std::size_t i = 0; i < image.rgba.size(); ++i)
        image.rgba[i] = std::uint8_t((i * 7919u + i / 4 * 31u) % 256u);
    if (opaque)
        for (std::size_t i = 3; i < image.rgba.size(); i += 4)
            image.rgba[i] = 255;
    return image;
}

TEST(ImageIO, PngRoundTripIsExact) {
    test::TempFolder dir;
    for (const bool opaque : {false, true}) {
        const Image8 image = patternImage(41, 17, opaque);
        const fs::path path = dir / (opaque ? "rgb.png" : "rgba.png");
        writePng(path, image);
        const Image8 back = readPng8(path);
        ASSERT_EQ(back.width, image.width);
        ASSERT_EQ(back.height, image.height);
        EXPECT_EQ(back.rgba, image.rgba) << (opaque ? "RGB" : "RGBA") << " PNG";
    }
    EXPECT_EQ(dir.listing(), (std::vector<std::string>{"rgb.png", "rgba.png"}));
}

double srgbEotf(double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

TEST(ImageIO, PngDecodesToLinearWithExactSrgbEotf) {
    test::TempFolder dir;
    Image8 image(256, 1);
    for (int x = 0; x < 256; ++x) {
        std::uint8_t* p = image.at(x, 0);
        p[0] = std::uint8_t(x);
        p[1] = std::uint8_t(255 - x);
        p[2] = 10; // the linear segment (10 / 255 < 0.04045)
        p[3] = std::uint8_t(x);
    }
    writePng(dir / "ramp.png", image);
    const ImageF linear = readImage(dir / "ramp.png");
    ASSERT_EQ(linear.width, 256);
    for (int x = 0; x < 256; ++x) {
        const float* p = linear.at(x, 0);
        EXPECT_NEAR(p[0], srgbEotf(x / 255.0), 1e-6);
        EXPECT_NEAR(p[1], srgbEotf((255 - x) / 255.0), 1e-6);
        EXPECT_NEAR(p[2], 10.0 / 255.0 / 12.92, 1e-7);
        EXPECT_NEAR(p[3], x / 255.0, 1e-7) << "alpha is not sRGB encoded";
    }
}

// A minimal PNG encoder (stored deflate blocks) for what writePng does not make: 16-bit and grey files.
std::uint32_t crc32(std::string_view bytes) {
    std::uint32_t crc = 0xffffffffu;
    for (const char c : bytes) {
        crc ^= std::uint8_t(c);
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

void appendBigEndian(std::string& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8)
        out.push_back(char(v >> shift & 0xffu));
}

std::string pngChunk(std::string_view type, std::string_view data) {
    std::string chunk;
    appendBigEndian(chunk, std::uint32_t(data.size()));
    const std::string body = std::string(type) + std::string(data);
    chunk += body;
    appendBigEndian(chunk, crc32(body));
    return chunk;
}

/// rows: filter-free sample bytes per row (big-endian for 16 bit).
std::string makePng(int width, int height, int bitDepth, int colorType,
                    const std::vector<std::string>& rows) {
    std::string header;
    appendBigEndian(header, std::uint32_t(width));
    appendBigEndian(header, std::uint32_t(height));
    header += {char(bitDepth), char(colorType), 0, 0, 0};
    std::string raw;
    for (const std::string& row : rows)
        raw += '\0' + row;                                   // filter type 0
    std::string zlib = {char(0x78), char(0x01), char(0x01)}; // one final stored block (raw < 64 KiB)
    zlib += {char(raw.size() & 0xff), char(raw.size() >> 8), char(~raw.size() & 0xff),
             char(~raw.size() >> 8 & 0xff)};
    zlib += raw;
    std::uint32_t a = 1, b = 0; // Adler-32
    for (const char c : raw) {
        a = (a + std::uint8_t(c)) % 65521u;
        b = (b + a) % 65521u;
    }
    appendBigEndian(zlib, b << 16 | a);
    return "\x89PNG\r\n\x1a\n" + pngChunk("IHDR", header) + pngChunk("IDAT", zlib) + pngChunk("IEND", "");
}

TEST(ImageIO, Png16BitDecodesAllSixteenBits) {
    test::TempFolder dir;
    // 2x1 RGB, 16 bit: (0x8000, 0xffff, 0x0001) and (0x0000, 0x1234, 0xfedc)
    const std::string row = {char(0x80), 0, char(0xff), char(0xff), 0,          1,
                             0,          0, 0x12,       0x34,       char(0xfe), char(0xdc)};
    writeFileBytes(dir / "deep.png", makePng(2, 1, 16, 2, {row}));
    const ImageF image = readImage(dir / "deep.png");
    ASSERT_EQ(image.width, 2);
    ASSERT_EQ(image.height, 1);
    const std::array<int, 6> samples{0x8000, 0xffff, 0x0001, 0x0000, 0x1234, 0xfedc};
    for (std::size_t i = 0; i < 6; ++i)
        EXPECT_NEAR(image.rgba[i / 3 * 4 + i % 3], srgbEotf(samples[i] / 65535.0), 1e-6) << "sample " << i;
    EXPECT_EQ(image.rgba[3], 1.0f) << "alpha 1 when absent";
    EXPECT_EQ(image.rgba[7], 1.0f);
}

TEST(ImageIO, GreyPngWithoutAlphaExpandsToRgbWithOpaqueAlpha) {
    test::TempFolder dir;
    writeFileBytes(dir / "grey.png", makePng(3, 2, 8, 0, {std::string("\x00\x80\xff", 3), "\x40\x40\x40"}));
    const ImageF image = readImage(dir / "grey.png");
    ASSERT_EQ(image.width, 3);
    ASSERT_EQ(image.height, 2);
    EXPECT_NEAR(image.at(1, 0)[0], srgbEotf(128 / 255.0), 1e-6);
    EXPECT_EQ(image.at(1, 0)[0], image.at(1, 0)[1]);
    EXPECT_EQ(image.at(1, 0)[0], image.at(1, 0)[2]);
    EXPECT_EQ(image.at(2, 0)[0], 1.0f);
    for (std::size_t i = 3; i < image.rgba.size(); i += 4)
        EXPECT_EQ(image.rgba[i], 1.0f);
    const Image8 raw = readPng8(dir / "grey.png");
    EXPECT_EQ(raw.at(1, 0)[0], 0x80);
    EXPECT_EQ(raw.at(1, 0)[3], 255);
}

TEST(ImageIO, ReadDispatchesOnContentNotExtension) {
    test::TempFolder dir;
    writePng(dir / "actually-a-png.exr", patternImage(5, 4, true));
    const ImageF image = readImage(dir / "actually-a-png.exr");
    EXPECT_EQ(image.width, 5);
    EXPECT_EQ(image.height, 4);
}

TEST(ImageIO, WritingReplacesAnExistingFile) {
    test::TempFolder dir;
    writePng(dir / "out.png", patternImage(8, 8, false));
    const Image8 second = patternImage(3, 2, true);
    writePng(dir / "out.png", second);
    EXPECT_EQ(readPng8(dir / "out.png").rgba, second.rgba);
    EXPECT_EQ(dir.listing(), std::vector<std::string>{"out.png"});
}

// ---------------------------------------------------------------------------------------------------------------
// Errors

TEST(ImageIOErrors, TruncatedFilesAreRejected) {
    test::TempFolder dir;
    for (const char* name : {"GoldenGate.exr", "Desk.exr", "blender_sunrise.exr", "Desk.hdr"}) {
        const std::string bytes = readFileBytes(test::dataDir() / name);
        ASSERT_GT(bytes.size(), 2000u) << name;
        // Cut in the header/offset table, and in the middle of the pixel data (where stb_image's RGBE reader
        // hangs).
        for (const std::size_t length : {std::size_t(1000), bytes.size() / 2}) {
            const fs::path path = dir / ("cut-" + std::to_string(length) + "-" + name);
            writeFileBytes(path, std::string_view(bytes).substr(0, length));
            expectIoError([&] { (void)readImage(path); }, path);
        }
    }
}

TEST(ImageIOErrors, TruncatedPngIsRejected) {
    test::TempFolder dir;
    writePng(dir / "whole.png", patternImage(64, 64, false));
    const std::string bytes = readFileBytes(dir / "whole.png");
    for (const std::size_t length : {std::size_t(30), bytes.size() / 2, bytes.size() - 1}) {
        const fs::path path = dir / ("cut-" + std::to_string(length) + ".png");
        writeFileBytes(path, std::string_view(bytes).substr(0, length));
        expectIoError([&] { (void)readImage(path); }, path);
        expectIoError([&] { (void)readPng8(path); }, path);
    }
}

TEST(ImageIOErrors, TextFileNamedExrIsRejected) {
    test::TempFolder dir;
    const fs::path path = dir / "notes.exr";
    writeFileBytes(path, "These are not the pixels you are looking for.\n");
    expectIoError([&] { (void)readImage(path); }, path, "not an OpenEXR");
}

TEST(ImageIOErrors, MissingEmptyAndFolderPathsAreRejected) {
    test::TempFolder dir;
    expectIoError([&] { (void)readImage(dir / "nope.exr"); }, dir / "nope.exr", "does not exist");
    expectIoError([&] { (void)readPng8(dir / "nope.png"); }, dir / "nope.png", "does not exist");
    writeFileBytes(dir / "empty.hdr", "");
    expectIoError([&] { (void)readImage(dir / "empty.hdr"); }, dir / "empty.hdr", "empty");
    expectIoError([&] { (void)readImage(dir.path()); }, dir.path(), "folder");
}

TEST(ImageIOErrors, ZeroSizeImageIsRejected) {
    test::TempFolder dir;
    const fs::path path = dir / "zero.hdr";
    writeFileBytes(path, "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 0 +X 16\n");
    expectIoError([&] { (void)readImage(path); }, path, "no pixels");
}

TEST(ImageIOErrors, WritingIntoMissingFolderFailsAndCreatesNothing) {
    test::TempFolder dir;
    const fs::path path = dir / "missing" / "out.png";
    expectIoError([&] { writePng(path, patternImage(4, 4, true)); }, path, "does not exist");
    expectIoError([&] { writeExr(dir / "missing" / "out.exr", ImageF(4, 4, 1.0f)); },
                  dir / "missing" / "out.exr", "does not exist");
    EXPECT_FALSE(fs::exists(dir / "missing"));
    EXPECT_TRUE(dir.listing().empty());
}

TEST(ImageIOErrors, FailedWriteLeavesNoTemporaryBehind) {
    test::TempFolder dir;
    // The destination is an existing folder: the temporary is written, then the rename fails.
    fs::create_directory(dir / "taken.png");
    fs::create_directory(dir / "taken.exr");
    expectIoError([&] { writePng(dir / "taken.png", patternImage(16, 16, false)); }, dir / "taken.png");
    expectIoError([&] { writeExr(dir / "taken.exr", ImageF(16, 16, 0.5f)); }, dir / "taken.exr");
    EXPECT_EQ(dir.listing(), (std::vector<std::string>{"taken.exr", "taken.png"}));
    EXPECT_TRUE(fs::is_empty(dir / "taken.png"));
}

TEST(ImageIOErrors, EmptyOrInconsistentImageIsNotWritten) {
    test::TempFolder dir;
    expectIoError([&] { writePng(dir / "empty.png", Image8()); }, dir / "empty.png", "empty");
    ImageF inconsistent(4, 4);
    inconsistent.rgba.resize(10);
    expectIoError([&] { writeExr(dir / "bad.exr", inconsistent); }, dir / "bad.exr");
    EXPECT_TRUE(dir.listing().empty());
}

} // namespace
} // namespace photopic
