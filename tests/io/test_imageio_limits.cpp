// The image readers against declared sizes: a header's width and height are checked against the bytes that
// could hold them and against ImageReadLimits before anything is allocated; outputs are checked before work.

#include "io/ImageIO.h"

#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfTiledOutputFile.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace photopic {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<unsigned char>;

Bytes bytesOf(const std::string& text) {
    return {text.begin(), text.end()};
}

std::string decodeError(const Bytes& bytes, const ImageReadLimits& limits = {}) {
    try {
        (void)decodeImage(bytes, "mem.img", limits);
    } catch (const IoError& e) {
        return e.what();
    }
    return "";
}

// CRC-32 as PNG chunks use it (ISO 3309), to build small valid files by hand.
std::uint32_t crc32(const Bytes& data) {
    std::uint32_t crc = 0xffffffffu;
    for (unsigned char b : data) {
        crc ^= b;
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

void appendChunk(Bytes& png, const std::string& type, const Bytes& data) {
    const auto be32 = [&](std::uint32_t v) {
        for (int s = 24; s >= 0; s -= 8)
            png.push_back(static_cast<unsigned char>(v >> s));
    };
    be32(static_cast<std::uint32_t>(data.size()));
    Bytes typed(type.begin(), type.end());
    typed.insert(typed.end(), data.begin(), data.end());
    png.insert(png.end(), typed.begin(), typed.end());
    be32(crc32(typed));
}

Bytes pngHeader(std::uint32_t width, std::uint32_t height) {
    Bytes png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    Bytes ihdr;
    for (std::uint32_t v : {width, height})
        for (int s = 24; s >= 0; s -= 8)
            ihdr.push_back(static_cast<unsigned char>(v >> s));
    ihdr.insert(ihdr.end(), {8, 0, 0, 0, 0}); // 8-bit grey, no interlace
    appendChunk(png, "IHDR", ihdr);
    return png;
}

TEST(ImageLimits, RadianceHeaderDeclaringMoreThanTheFileHoldsIsRejectedUnallocated) {
    const std::string error =
        decodeError(bytesOf("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 16384 +X 16384\n"));
    EXPECT_NE(error.find("truncated"), std::string::npos) << error;
    EXPECT_NE(error.find("16384x16384"), std::string::npos) << error;
}

TEST(ImageLimits, MaxPixelsIsEnforcedForEveryFormat) {
    const Bytes hdr = bytesOf(std::string("#?RADIANCE\n\n-Y 2 +X 3\n") + std::string(24, '\x80'));
    EXPECT_EQ(decodeImage(hdr, "ok.hdr", {.maxPixels = 6}).width, 3);
    const std::string error = decodeError(hdr, {.maxPixels = 5});
    EXPECT_NE(error.find("more than the limit of 5 pixels"), std::string::npos) << error;

    Bytes png = pngHeader(100000, 100000);
    appendChunk(png, "IDAT", {0x78, 0x9c, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01});
    appendChunk(png, "IEND", {});
    const std::string pngError = decodeError(png, {.maxPixels = 1 << 20});
    EXPECT_NE(pngError.find("more than the limit"), std::string::npos) << pngError;
}

TEST(ImageLimits, PngDeclaringMoreThanItsBytesCanHoldIsRejectedUnallocated) {
    Bytes png = pngHeader(16384, 16384); // 256 Mi samples from a few bytes of IDAT: beyond deflate's 1032:1
    appendChunk(png, "IDAT", {0x78, 0x9c, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01});
    appendChunk(png, "IEND", {});
    const std::string error = decodeError(png);
    EXPECT_NE(error.find("cannot hold the 16384x16384 image"), std::string::npos) << error;
}

TEST(ImageLimits, ZeroLengthIdatChunkIsReadLikeAnyOther) {
    // A 1x1 grey PNG whose pixel data is preceded by an empty IDAT chunk (legal; stb_image once copied from
    // a null pointer on it).
    Bytes png = pngHeader(1, 1);
    appendChunk(png, "IDAT", {});
    appendChunk(png, "IDAT", {0x78, 0x01, 0x63, 0x60, 0x00, 0x00, 0x00, 0x02, 0x00, 0x01}); // row: 0, 0x00
    appendChunk(png, "IEND", {});
    const Image8 image = decodePng8(png, "zero-idat.png");
    ASSERT_EQ(image.width, 1);
    EXPECT_EQ(image.rgba[0], 0);
    EXPECT_EQ(image.rgba[3], 255);
}

TEST(ImageLimits, ExrHeaderDeclaringMoreChunksThanTheFileHoldsIsRejected) {
    // A valid 4x3 file, its data window widened to 4 x 2^24 lines: too many chunks for its bytes.
    ImageF image(4, 3, 0.5f);
    const fs::path path =
        fs::temp_directory_path() / ("photopic-limits-" + std::to_string(::getpid()) + ".exr");
    writeExr(path, image);
    std::ifstream in(path, std::ios::binary);
    Bytes bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    fs::remove(path);
    const std::string name = "dataWindow";
    auto at = std::search(bytes.begin(), bytes.end(), name.begin(), name.end());
    ASSERT_NE(at, bytes.end());
    // name\0 "box2i"\0 size(4) xMin yMin xMax yMax: set yMax to 2^24 - 1.
    const std::size_t yMax = std::size_t(at - bytes.begin()) + name.size() + 1 + 6 + 4 + 12;
    const std::uint32_t lines = (1u << 24) - 1;
    for (int i = 0; i < 4; ++i)
        bytes[yMax + std::size_t(i)] = static_cast<unsigned char>(lines >> (8 * i));
    const std::string error = decodeError(bytes);
    EXPECT_FALSE(error.empty());
    EXPECT_NE(error.find("mem.img"), std::string::npos) << error;
}

/// A tiled 10 x 6 RGB file with `tile` x `tile` tiles, written by OpenEXR.
Bytes tiledExr(unsigned tile) {
    const fs::path path =
        fs::temp_directory_path() / ("photopic-tiled-" + std::to_string(::getpid()) + ".exr");
    const int w = 10, h = 6;
    Imf::Header header(w, h);
    header.setTileDescription(Imf::TileDescription(tile, tile, Imf::ONE_LEVEL));
    for (const char* name : {"R", "G", "B"})
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    std::vector<float> values(std::size_t(w) * h, 0.25f);
    Imf::FrameBuffer frameBuffer;
    for (const char* name : {"R", "G", "B"})
        frameBuffer.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data()), sizeof(float),
                                            sizeof(float) * w));
    {
        Imf::TiledOutputFile file(path.c_str(), header);
        file.setFrameBuffer(frameBuffer);
        file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
    }
    std::ifstream in(path, std::ios::binary);
    Bytes bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    fs::remove(path);
    return bytes;
}

// OpenEXR allocates a row of tiles (the image's width times the tile height) and a tile per thread by what
// the header says: a tile size beyond the image (and beyond 256) is refused before, naming the file and the
// size.
TEST(ImageLimits, ExrTilesLargerThanTheImageAreRejectedUnallocated) {
    EXPECT_EQ(decodeImage(tiledExr(64), "tiles64.exr").width, 10) << "tiles up to 256 fit any image";
    Bytes bytes = tiledExr(4);
    const std::string name = "tiledesc";
    auto at = std::search(bytes.begin(), bytes.end(), name.begin(), name.end());
    ASSERT_NE(at, bytes.end());
    // "tiledesc"\0 size(4) xSize(4) ySize(4) mode(1): set ySize to 2^24, which OpenEXR itself accepts (a row
    // of tiles of this file would be 10 x 2^24 floats per channel, 2 GB).
    const std::size_t ySize = std::size_t(at - bytes.begin()) + name.size() + 1 + 4 + 4;
    const std::uint32_t huge = 1u << 24;
    for (int i = 0; i < 4; ++i)
        bytes[ySize + std::size_t(i)] = static_cast<unsigned char>(huge >> (8 * i));
    const std::string error = decodeError(bytes);
    EXPECT_NE(error.find("mem.img"), std::string::npos) << error;
    EXPECT_NE(error.find("tile size 4 x 16777216"), std::string::npos) << error;
}

TEST(OutputChecks, RequireWritableFileNamesWhatIsWrong) {
    const fs::path dir = fs::temp_directory_path() / ("photopic-out-" + std::to_string(::getpid()));
    fs::create_directories(dir / "sub");
    EXPECT_NO_THROW(requireWritableFile(dir / "new.csv"));
    EXPECT_THROW(requireWritableFile(dir / "sub"), IoError);
    EXPECT_THROW(requireWritableFile(dir / "missing" / "x.csv"), IoError);
    EXPECT_TRUE(fs::is_empty(dir / "sub"));
    fs::remove_all(dir);
}

TEST(OutputChecks, DevicesAndStandardOutputAreStreamed) {
    const fs::path dir = fs::temp_directory_path() / ("photopic-stream-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "file.png") << "x";
    EXPECT_TRUE(isStreamOutput("-"));
    EXPECT_TRUE(isStreamOutput("/dev/null"));
    EXPECT_FALSE(isStreamOutput(dir / "file.png"));
    EXPECT_FALSE(isStreamOutput(dir / "new.png"));
    EXPECT_FALSE(isStreamOutput(dir));
    EXPECT_NO_THROW(requireWritableFile("/dev/null"));
    // Written through, not renamed over: /dev/null is still the device, and no temporary is left in /dev.
    Image8 image;
    image.width = 2;
    image.height = 1;
    image.rgba.assign(8, 255);
    EXPECT_NO_THROW(writePng("/dev/null", image));
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
    fs::remove_all(dir);
}

TEST(OutputChecks, AtomicFileWriterPublishesOnlyOnCommit) {
    const fs::path dir = fs::temp_directory_path() / ("photopic-atomic-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    {
        AtomicFileWriter abandoned(dir / "a.csv");
        abandoned.write("half");
    }
    EXPECT_TRUE(fs::is_empty(dir)) << "an abandoned writer leaves nothing";
    {
        AtomicFileWriter file(dir / "b.csv");
        file.write("one,");
        file.write("two\n");
        EXPECT_FALSE(fs::exists(dir / "b.csv"));
        file.commit();
    }
    std::ifstream in(dir / "b.csv");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text, "one,two\n");
    EXPECT_THROW(AtomicFileWriter{dir}, IoError);
    fs::remove_all(dir);
}

} // namespace
} // namespace photopic
