#include "io/ImageIO.h"

#include "io/ExrDetail.h"

#include "core/Color.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfPartType.h>
#include <ImfRgbaFile.h>
#include <ImfStdIO.h>
#include <ImfThreading.h>
#include <ImfVersion.h>
#include <libdeflate.h>
#include <png.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <utility>
#include <vector>

namespace photopic {

namespace fs = std::filesystem;

namespace {
/// "\"PATH\": problem", built by appends: GCC 12 warns of a false overlap in `"\"" + std::string`.
std::string ioErrorMessage(const fs::path& path, std::string_view problem) {
    std::string message(1, '"');
    message.append(path.string()).append("\": ").append(problem);
    return message;
}
} // namespace

IoError::IoError(const fs::path& path, std::string_view problem)
    : std::runtime_error(ioErrorMessage(path, problem)) {}

namespace {

using Bytes = std::vector<unsigned char>;

std::string quoted(const fs::path& path) {
    return "\"" + path.string() + "\"";
}
std::string errnoMessage(int err) {
    return std::generic_category().message(err);
}

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

// ---------------------------------------------------------------------------------------------------------------
// Reading files

void requireRegularFile(const fs::path& path) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (status.type() == fs::file_type::not_found)
        throw IoError(path, "file does not exist");
    if (ec)
        throw IoError(path, "cannot access file: " + ec.message());
    if (status.type() == fs::file_type::directory)
        throw IoError(path, "is a folder, not an image file");
    if (status.type() != fs::file_type::regular)
        throw IoError(path, "is not a regular file");
}

/// The first `limit` bytes of the file (all of it by default), into `bytes` (its capacity kept).
void readBytes(const fs::path& path, Bytes& bytes, std::size_t limit = SIZE_MAX) {
    const FilePtr file(std::fopen(path.c_str(), "rb"));
    if (!file)
        throw IoError(path, "cannot open: " + errnoMessage(errno));
    // Sized to the file in one step, not a doubling series (each step copied, the old block left in the
    // heap), and not cleared first: a sequence reads each frame's file into the buffer the frame before
    // left, so only what a larger file adds is allocated and zeroed before fread overwrites it.
    std::size_t size = 0;
    struct stat info {};
    if (::fstat(::fileno(file.get()), &info) == 0 && info.st_size > 0)
        size = std::min(std::size_t(info.st_size), limit);
    bytes.resize(size);
    std::size_t got = std::fread(bytes.data(), 1, size, file.get());
    bytes.resize(got);
    // The rest, should the file have grown since fstat, or have reported no size.
    constexpr std::size_t kChunk = std::size_t(1) << 20;
    while (got == size && bytes.size() < limit) {
        const std::size_t old = bytes.size();
        size = std::min(kChunk, limit - old);
        bytes.resize(old + size);
        got = std::fread(bytes.data() + old, 1, size, file.get());
        bytes.resize(old + got);
    }
    if (std::ferror(file.get()))
        throw IoError(path, "read error: " + errnoMessage(errno));
}

Bytes readBytes(const fs::path& path) {
    Bytes bytes;
    readBytes(path, bytes);
    return bytes;
}

enum class FileFormat { Exr, Rgbe, Png, Unknown };

constexpr std::array<unsigned char, 4> kExrMagic{0x76, 0x2f, 0x31, 0x01};
constexpr std::array<unsigned char, 8> kPngMagic{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

template <std::size_t N>
bool startsWith(std::span<const unsigned char> bytes, const std::array<unsigned char, N>& magic) {
    return bytes.size() >= N && std::equal(magic.begin(), magic.end(), bytes.begin());
}

FileFormat sniff(std::span<const unsigned char> head) {
    if (startsWith(head, kExrMagic))
        return FileFormat::Exr;
    if (startsWith(head, kPngMagic))
        return FileFormat::Png;
    // Radiance files open with "#?" and the writing program's name ("#?RADIANCE", "#?RGBE").
    if (head.size() >= 2 && head[0] == '#' && head[1] == '?')
        return FileFormat::Rgbe;
    return FileFormat::Unknown;
}

std::string unknownFormatMessage(const fs::path& path, std::span<const unsigned char> head) {
    if (head.size() < kPngMagic.size())
        return "file is too short (" + std::to_string(head.size()) + " bytes) to be an image";
    std::string message = "not an OpenEXR, Radiance HDR or PNG file";
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](char c) { return char(std::tolower(c)); });
    if (ext == ".exr" || ext == ".hdr" || ext == ".pic" || ext == ".png")
        message += " despite its " + ext + " extension";
    message += " (first bytes:";
    for (std::size_t i = 0; i < std::min<std::size_t>(head.size(), 8); ++i) {
        std::array<char, 4> hex{};
        std::snprintf(hex.data(), hex.size(), " %02x", head[i]);
        message += hex.data();
    }
    return message + ")";
}

std::string extentText(std::int64_t width, std::int64_t height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

/// The declared size, before anything is allocated for it: some pixels, at most limits.maxPixels.
void checkSize(const fs::path& path, std::int64_t width, std::int64_t height, const ImageReadLimits& limits) {
    if (width <= 0 || height <= 0)
        throw IoError(path, "image has no pixels (" + extentText(width, height) + ")");
    if (width > std::max<std::int64_t>(limits.maxPixels, 1) / height)
        throw IoError(path, "image is " + extentText(width, height) + ", more than the limit of " +
                                std::to_string(limits.maxPixels) + " pixels (--max-pixels)");
}

/// The declared size against the bytes that could hold it: `needed` is a lower bound on the file's size for
/// that image; a file shorter than that is truncated or lies about its size, and is rejected unallocated.
void checkBytesHold(const fs::path& path, std::int64_t width, std::int64_t height, std::uint64_t needed,
                    std::size_t available, const char* format) {
    if (needed > available)
        throw IoError(path, std::string(format) + " file is truncated: " + std::to_string(available) +
                                " bytes cannot hold the " + extentText(width, height) +
                                " image its header declares (at least " + std::to_string(needed) +
                                " needed)");
}

// ---------------------------------------------------------------------------------------------------------------
// OpenEXR

/// The smallest file that can hold the image: the offset table (8 bytes a chunk) and each chunk's own header
/// (a scanline block's y and size, 8 bytes; a tile's 4 coordinates and size, 20), whatever the compression.
std::uint64_t exrMinimumBytes(const Imf::Header& header, std::int64_t width, std::int64_t height) {
    if (header.hasTileDescription()) {
        const Imf::TileDescription& tiles = header.tileDescription();
        const std::uint64_t tx = (std::uint64_t(width) + tiles.xSize - 1) / std::max(tiles.xSize, 1u);
        const std::uint64_t ty = (std::uint64_t(height) + tiles.ySize - 1) / std::max(tiles.ySize, 1u);
        return tx * ty * (8 + 20);
    }
    // Scanlines per chunk, as OpenEXR's compressors define them; an unknown compression takes the largest,
    // which gives the smallest (so still safe) bound.
    std::uint64_t linesPerChunk = 256;
    switch (header.compression()) {
    case Imf::NO_COMPRESSION:
    case Imf::RLE_COMPRESSION:
    case Imf::ZIPS_COMPRESSION:
        linesPerChunk = 1;
        break;
    case Imf::ZIP_COMPRESSION:
    case Imf::PXR24_COMPRESSION:
        linesPerChunk = 16;
        break;
    case Imf::PIZ_COMPRESSION:
    case Imf::B44_COMPRESSION:
    case Imf::B44A_COMPRESSION:
    case Imf::DWAA_COMPRESSION:
        linesPerChunk = 32;
        break;
    default:
        break;
    }
    return (std::uint64_t(height) + linesPerChunk - 1) / linesPerChunk * (8 + 8);
}

/// Luminance/chroma files (Y, RY, BY; chroma subsampled) are always half: RgbaInputFile converts them.
ImageF readExrLuminanceChroma(const fs::path& path, std::span<const unsigned char> bytes, int width,
                              int height) {
    detail::MemoryIStream stream(path, bytes);
    Imf::RgbaInputFile file(stream);
    const Imath::Box2i dataWindow = file.dataWindow();
    std::vector<Imf::Rgba> pixels(std::size_t(width) * std::size_t(height));
    // OpenEXR addresses the frame buffer in data-window coordinates: shift the base by the window's origin.
    file.setFrameBuffer(pixels.data() - dataWindow.min.x - std::ptrdiff_t(dataWindow.min.y) * width, 1,
                        std::size_t(width));
    file.readPixels(dataWindow.min.y, dataWindow.max.y);
    ImageF image(width, height);
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        image.rgba[i * 4 + 0] = pixels[i].r;
        image.rgba[i * 4 + 1] = pixels[i].g;
        image.rgba[i * 4 + 2] = pixels[i].b;
        image.rgba[i * 4 + 3] = pixels[i].a;
    }
    return image;
}

/// The bytes OpenEXR's reader of a value of `type` takes whatever the attribute's declared size says, for the
/// types of a fixed size; nullopt for the others.
std::optional<std::size_t> exrFixedValueSize(std::string_view type) {
    static constexpr std::pair<std::string_view, std::size_t> kSizes[] = {{"box2i", 16},
                                                                          {"box2f", 16},
                                                                          {"chromaticities", 32},
                                                                          {"compression", 1},
                                                                          {"deepImageState", 1},
                                                                          {"double", 8},
                                                                          {"envmap", 1},
                                                                          {"float", 4},
                                                                          {"int", 4},
                                                                          {"keycode", 28},
                                                                          {"lineOrder", 1},
                                                                          {"m33f", 36},
                                                                          {"m33d", 72},
                                                                          {"m44f", 64},
                                                                          {"m44d", 128},
                                                                          {"rational", 8},
                                                                          {"tiledesc", 9},
                                                                          {"timecode", 8},
                                                                          {"v2i", 8},
                                                                          {"v2f", 8},
                                                                          {"v2d", 16},
                                                                          {"v3i", 12},
                                                                          {"v3f", 12},
                                                                          {"v3d", 24}};
    for (const auto& [name, size] : kSizes) {
        if (name == type)
            return size;
    }
    return std::nullopt;
}

/// Whether a channel list (entries of a name, its null and 16 bytes, then an empty name) ends exactly at the
/// end of `value`: OpenEXR reads the list to its empty name, whatever the declared size.
bool exrChannelListFits(std::span<const unsigned char> value) {
    std::size_t pos = 0;
    while (pos < value.size()) {
        const auto end = std::find(value.begin() + std::ptrdiff_t(pos), value.end(), 0);
        if (end == value.end())
            return false;
        const std::size_t nameLength = std::size_t(end - value.begin()) - pos;
        if (nameLength == 0)
            return pos + 1 == value.size();
        pos += nameLength + 1 + 16; // type, pLinear, 3 reserved bytes, x and y sampling
    }
    return false;
}

/// Walks the header attributes (name, type, 32-bit size, value) without OpenEXR and refuses a size beyond the
/// file's end: OpenEXR allocates a value's declared size (up to 2 GiB for an unknown type) before it reads
/// it. Refused too: an attribute named twice in one header, and a known type whose reader takes another
/// number of bytes than the declared size (a fixed-size value, a channel list), after which OpenEXR would
/// go on reading the next attribute from the wrong place, where a size it then trusted was never checked.
void checkExrAttributeSizes(const fs::path& path, std::span<const unsigned char> bytes) {
    const bool multiPart = detail::isMultiPartExr(bytes);
    // Deep data (any number of samples a pixel, version flag 0x800 or a part of type deepscanline or
    // deeptile) has no flat colour to read; refused here, before OpenEXR's deep reader sees the file.
    const auto refuseDeep = [&](const std::string& what) {
        throw IoError(
            path, "OpenEXR deep data is not read (" + what +
                      "): flatten it first, e.g. with your renderer's or compositor's deep-to-image step");
    };
    if (bytes.size() >= 8 && (bytes[5] & 0x08) != 0)
        refuseDeep("the file's version field says it holds deep data");
    std::size_t pos = 8;
    const auto cString = [&]() {
        const auto end =
            std::find(bytes.begin() + std::ptrdiff_t(std::min(pos, bytes.size())), bytes.end(), 0);
        if (end == bytes.end())
            throw IoError(path, "OpenEXR header is truncated");
        const std::string text(bytes.begin() + std::ptrdiff_t(pos), end);
        pos = std::size_t(end - bytes.begin()) + 1;
        return text;
    };
    std::set<std::string> names; // of this header's attributes so far
    for (bool firstInHeader = true;;) {
        const std::string name = cString();
        if (name.empty()) {
            // The end of a header; in a multi-part file an empty header ends the list.
            if (!multiPart || firstInHeader)
                return;
            firstInHeader = true;
            names.clear();
            continue;
        }
        firstInHeader = false;
        // OpenEXR's reader merges a second `channels` into the first, its core library keeps one: the two
        // would read the pixels with different channels.
        if (!names.insert(name).second)
            throw IoError(path, "OpenEXR header is corrupt: attribute \"" + name + "\" appears twice");
        const std::string type = cString();
        if (bytes.size() - pos < 4)
            throw IoError(path, "OpenEXR header is truncated");
        const std::uint32_t size = std::uint32_t(bytes[pos]) | std::uint32_t(bytes[pos + 1]) << 8 |
                                   std::uint32_t(bytes[pos + 2]) << 16 | std::uint32_t(bytes[pos + 3]) << 24;
        pos += 4;
        if (size > bytes.size() - pos)
            throw IoError(path, "OpenEXR header is corrupt: attribute \"" + name + "\" (" + type +
                                    ") declares " + std::to_string(size) + " bytes, the file has " +
                                    std::to_string(bytes.size() - pos) + " left");
        const std::optional<std::size_t> fixed = exrFixedValueSize(type);
        if (fixed && size != *fixed)
            throw IoError(path, "OpenEXR header is corrupt: attribute \"" + name + "\" (" + type +
                                    ") declares " + std::to_string(size) + " bytes, a " + type + " has " +
                                    std::to_string(*fixed));
        if (name == "type" && type == "string") {
            const std::string partType(bytes.begin() + std::ptrdiff_t(pos),
                                       bytes.begin() + std::ptrdiff_t(pos + size));
            if (partType.starts_with("deep"))
                refuseDeep("a part of type " + partType.substr(0, 16));
        }
        if (type == "chlist" && !exrChannelListFits(bytes.subspan(pos, size)))
            throw IoError(path, "OpenEXR header is corrupt: channel list \"" + name +
                                    "\" does not end where its declared " + std::to_string(size) +
                                    " bytes do");
        pos += size;
    }
}

/// Parts a multi-part file may have: renderers write one a layer, tens at most.
constexpr int kMaxExrParts = 1024;

/// Tiles no larger than the image, or than kMaxTileBeyondImage where the image is smaller: Imf::InputFile
/// allocates a buffer of a whole row of tiles (the data window's width times the tile height) and one tile
/// per thread, by what the header says, before it reads a byte of them (a fuzzed 2 x 100663298 tile asked for
/// 2.4 GB for a 6 x 4 image). Common tile sizes (32 to 256) on small images stay valid.
constexpr std::uint64_t kMaxTileBeyondImage = 256;

void checkTileSize(const fs::path& path, const Imf::Header& header, int version, std::int64_t width,
                   std::int64_t height) {
    // A single-part file says it is tiled in its version field, a part of a multi-part file in its type.
    const bool tiled = Imf::isTiled(version) || (header.hasType() && Imf::isTiled(header.type()));
    if (!tiled || !header.hasTileDescription())
        return;
    const Imf::TileDescription& tiles = header.tileDescription();
    if (tiles.xSize < 1 || tiles.ySize < 1 ||
        tiles.xSize > std::max<std::uint64_t>(std::uint64_t(width), kMaxTileBeyondImage) ||
        tiles.ySize > std::max<std::uint64_t>(std::uint64_t(height), kMaxTileBeyondImage))
        throw IoError(path, "OpenEXR tile size " + std::to_string(tiles.xSize) + " x " +
                                std::to_string(tiles.ySize) + " does not fit the image (" +
                                std::to_string(width) + " x " + std::to_string(height) +
                                "): at most the image's size, or " + std::to_string(kMaxTileBeyondImage) +
                                " where the image is smaller");
}

/// The first part's header alone, checked before Imf::InputFile sees the file: opening it allocates offset
/// tables and line buffers sized by the data window, so a corrupt window must be refused first.
void checkExrHeader(const fs::path& path, std::span<const unsigned char> bytes,
                    const ImageReadLimits& limits) {
    checkExrAttributeSizes(path, bytes);
    detail::MemoryIStream stream(path, bytes);
    std::array<char, 8> magicAndVersion{};
    stream.read(magicAndVersion.data(), int(magicAndVersion.size()));
    int version = int(std::uint32_t(std::uint8_t(magicAndVersion[4])) |
                      std::uint32_t(std::uint8_t(magicAndVersion[5])) << 8 |
                      std::uint32_t(std::uint8_t(magicAndVersion[6])) << 16 |
                      std::uint32_t(std::uint8_t(magicAndVersion[7])) << 24);
    // Every part's header: a multi-part reader opens them all, each allocating by its own data window.
    const bool multiPart = Imf::isMultiPart(version);
    for (int part = 0;; ++part) {
        Imf::Header header;
        header.readFrom(stream, version);
        const Imath::Box2i dataWindow = header.dataWindow();
        const std::int64_t width = std::int64_t(dataWindow.max.x) - dataWindow.min.x + 1;
        const std::int64_t height = std::int64_t(dataWindow.max.y) - dataWindow.min.y + 1;
        checkSize(path, width, height, limits);
        checkTileSize(path, header, version, width, height);
        checkBytesHold(path, width, height, exrMinimumBytes(header, width, height), bytes.size(), "OpenEXR");
        if (!multiPart)
            return;
        // An empty header (a lone null byte) ends a multi-part file's list of headers.
        const std::uint64_t next = stream.tellg();
        if (next >= bytes.size() || bytes[next] == 0)
            return;
        if (part + 1 >= kMaxExrParts)
            throw IoError(path, "OpenEXR file has more than " + std::to_string(kMaxExrParts) + " parts");
    }
}

ImageF readExr(const fs::path& path, std::span<const unsigned char> bytes, const ImageReadLimits& limits) {
    try {
        checkExrHeader(path, bytes, limits);
        detail::MemoryIStream stream(path, bytes);
        Imf::InputFile file(stream);
        ImageF image;
        detail::readExrColor(path, bytes, file, image, {}, limits);
        return image;
    } catch (const IoError&) {
        throw;
    } catch (const std::exception& e) {
        // Iex::BaseExc (OpenEXR's exceptions) derive from std::exception.
        throw IoError(path, std::string("cannot read OpenEXR: ") + e.what());
    }
}

std::string encodeExr(const fs::path& path, const ImageF& image) {
    // Finite values clamp to the largest half: an over-bright pixel stays bright instead of turning infinite.
    static constexpr float kHalfMax = 65504.0f;
    const auto toHalf = [](float v) {
        return half(std::isfinite(v) ? std::clamp(v, -kHalfMax, kHalfMax) : v);
    };
    std::vector<Imf::Rgba> pixels(image.pixelCount());
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        const float* p = image.rgba.data() + i * 4;
        pixels[i] = Imf::Rgba(toHalf(p[0]), toHalf(p[1]), toHalf(p[2]), toHalf(p[3]));
    }
    try {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        Imf::StdOSStream stream;
        {
            // The offset table is written when the file object goes: close it before taking the bytes.
            Imf::RgbaOutputFile file(stream, header, Imf::WRITE_RGBA);
            file.setFrameBuffer(pixels.data(), 1, std::size_t(image.width));
            file.writePixels(image.height);
        }
        return stream.str();
    } catch (const std::exception& e) {
        throw IoError(path, std::string("cannot encode OpenEXR: ") + e.what());
    }
}

// ---------------------------------------------------------------------------------------------------------------
// Radiance RGBE
//
// Decoded here rather than by stb_image: stbi_loadf loops forever on a truncated RLE scanline (past the end
// its reader yields zero bytes, and a zero-length literal run makes no progress), and it cannot report
// truncation. Format: Greg Ward, "Real Pixels", Graphics Gems II (1991), and Radiance's color.c.

class RgbeReader {
public:
    RgbeReader(const fs::path& path, std::span<const unsigned char> bytes, const ImageReadLimits& limits)
        : mPath(path)
        , mBytes(bytes)
        , mLimits(limits) {}

    ImageF read() {
        readHeader();
        checkBytesHold(mPath, mWidth, mHeight, std::uint64_t(mHeight) * minimumScanlineBytes(), left(),
                       "Radiance");
        ImageF image(mWidth, mHeight, 1.0f);
        std::vector<unsigned char> scanline(std::size_t(mWidth) * 4);
        for (int y = 0; y < mHeight; ++y) {
            readScanline(scanline, y);
            float* out = image.at(0, y);
            for (int x = 0; x < mWidth; ++x, out += 4) {
                const unsigned char* rgbe = scanline.data() + std::size_t(x) * 4;
                if (rgbe[3] == 0) {
                    out[0] = out[1] = out[2] = 0.0f;
                    continue;
                }
                // As Radiance's colr_color: a mantissa is its bin's lower edge, so decode at the centre.
                const float scale = std::ldexp(1.0f, int(rgbe[3]) - (128 + 8));
                for (int c = 0; c < 3; ++c)
                    out[c] = (float(rgbe[c]) + 0.5f) * scale;
            }
        }
        return image;
    }

private:
    std::string_view nextLine() {
        const auto begin = mBytes.begin() + std::ptrdiff_t(mPos);
        const auto end = std::find(begin, mBytes.end(), '\n');
        if (end == mBytes.end())
            throw IoError(mPath, "Radiance header is truncated");
        mPos = std::size_t(end - mBytes.begin()) + 1;
        return {reinterpret_cast<const char*>(&*begin), std::size_t(end - begin)};
    }

    void readHeader() {
        nextLine(); // "#?RADIANCE": checked by sniff()
        for (std::string_view line = nextLine(); !line.empty(); line = nextLine()) {
            constexpr std::string_view kFormat = "FORMAT=";
            if (line.starts_with(kFormat) && line.substr(kFormat.size()) != "32-bit_rle_rgbe")
                throw IoError(mPath, "unsupported Radiance pixel format \"" +
                                         std::string(line.substr(kFormat.size())) +
                                         "\" (only 32-bit_rle_rgbe)");
        }
        // Resolution string; only the standard orientation (rows top to bottom, columns left to right).
        const std::string_view line = nextLine();
        int height = 0;
        int width = 0;
        const char* p = line.data();
        const char* end = line.data() + line.size();
        bool ok = line.starts_with("-Y ");
        if (ok) {
            const auto [afterHeight, heightError] = std::from_chars(p + 3, end, height);
            ok = heightError == std::errc() &&
                 std::string_view(afterHeight, std::size_t(end - afterHeight)).starts_with(" +X ");
            if (ok) {
                const auto [afterWidth, widthError] = std::from_chars(afterHeight + 4, end, width);
                ok = widthError == std::errc() && afterWidth == end;
            }
        }
        if (!ok)
            throw IoError(mPath, "unsupported Radiance resolution line \"" + std::string(line) +
                                     "\" (expected \"-Y <height> +X <width>\")");
        checkSize(mPath, width, height, mLimits);
        mWidth = width;
        mHeight = height;
    }

    [[noreturn]] void truncated(int y) const {
        throw IoError(mPath, "Radiance file is truncated in scanline " + std::to_string(y) + " of " +
                                 std::to_string(mHeight));
    }

    [[noreturn]] void corrupt(int y) const {
        throw IoError(mPath,
                      "Radiance file is corrupt: bad run-length data in scanline " + std::to_string(y));
    }

    std::size_t left() const { return mBytes.size() - mPos; }

    /// The fewest bytes one scanline can take: flat, 4 a pixel; run-length coded, a 4-byte marker and for
    /// each of the 4 components one 2-byte run per 127 pixels.
    std::uint64_t minimumScanlineBytes() const {
        const std::uint64_t flat = std::uint64_t(mWidth) * 4;
        if (mWidth < 8 || mWidth >= 32768)
            return flat;
        return std::min(flat, 4 + 4 * 2 * ((std::uint64_t(mWidth) + 126) / 127));
    }

    /// One scanline as interleaved RGBE bytes. A new-style RLE scanline opens with 2, 2 and a 15-bit width
    /// and then holds each component's runs in turn; anything else is flat RGBE pixels.
    void readScanline(std::vector<unsigned char>& scanline, int y) {
        const unsigned char* p = mBytes.data() + mPos;
        const bool rle =
            mWidth >= 8 && mWidth < 32768 && left() >= 4 && p[0] == 2 && p[1] == 2 && (p[2] & 0x80) == 0;
        if (!rle) {
            if (left() < scanline.size())
                truncated(y);
            std::copy_n(p, scanline.size(), scanline.begin());
            mPos += scanline.size();
            return;
        }
        if ((int(p[2]) << 8 | int(p[3])) != mWidth)
            corrupt(y);
        mPos += 4;
        for (std::size_t c = 0; c < 4; ++c) {
            for (int x = 0; x < mWidth;) {
                if (left() < 2)
                    truncated(y);
                int count = mBytes[mPos++];
                if (count > 128) { // a run of one value
                    count -= 128;
                    if (count > mWidth - x)
                        corrupt(y);
                    const unsigned char value = mBytes[mPos++];
                    for (int i = 0; i < count; ++i, ++x)
                        scanline[std::size_t(x) * 4 + c] = value;
                } else { // `count` literal values
                    if (count == 0 || count > mWidth - x)
                        corrupt(y);
                    if (left() < std::size_t(count))
                        truncated(y);
                    for (int i = 0; i < count; ++i, ++x)
                        scanline[std::size_t(x) * 4 + c] = mBytes[mPos++];
                }
            }
        }
    }

    const fs::path& mPath;
    std::span<const unsigned char> mBytes;
    ImageReadLimits mLimits;
    std::size_t mPos = 0;
    int mWidth = 0;
    int mHeight = 0;
};

// ---------------------------------------------------------------------------------------------------------------
// PNG: decoded by libpng's full API (raw samples, no gamma handling), encoded by its simplified API.
//
// libpng reports errors by longjmp. The functions that call into it under setjmp hold no object with a
// destructor, so a longjmp out of them skips nothing; everything they fill is owned by their callers.

struct PngSource {
    std::span<const unsigned char> bytes;
    std::size_t pos = 0;
    std::array<char, 256> error{};
};

void pngReadBytes(png_structp png, png_bytep out, png_size_t count) {
    auto* source = static_cast<PngSource*>(png_get_io_ptr(png));
    if (count > source->bytes.size() - source->pos)
        png_error(png, "PNG file is truncated");
    std::memcpy(out, source->bytes.data() + source->pos, count);
    source->pos += count;
}

void pngFail(png_structp png, png_const_charp message) {
    auto* source = static_cast<PngSource*>(png_get_error_ptr(png));
    std::snprintf(source->error.data(), source->error.size(), "%s", message);
    png_longjmp(png, 1);
}

void pngWarn(png_structp, png_const_charp) {} // ancillary-chunk complaints; the pixels are still good

/// Reads the header and sets the transforms to RGBA at 8 bits (`eightBit`: a 16-bit file keeps its high
/// byte) or at the file's own depth; `minimumBytes` is pngMinimumEncodedBytes of the header.
bool pngReadInfo(png_structp png, png_infop info, bool eightBit, std::uint64_t& minimumBytes) {
    if (setjmp(png_jmpbuf(png)))
        return false;
    png_read_info(png, info);
    const int colorType = png_get_color_type(png, info);
    const int bitDepth = png_get_bit_depth(png, info);
    minimumBytes = pngMinimumEncodedBytes(png_get_image_width(png, info), png_get_image_height(png, info),
                                          colorType, bitDepth);
    if (colorType == PNG_COLOR_TYPE_PALETTE)
        png_set_palette_to_rgb(png);
    if (colorType == PNG_COLOR_TYPE_GRAY && bitDepth < 8)
        png_set_expand_gray_1_2_4_to_8(png);
    if (png_get_valid(png, info, PNG_INFO_tRNS))
        png_set_tRNS_to_alpha(png);
    if (colorType == PNG_COLOR_TYPE_GRAY || colorType == PNG_COLOR_TYPE_GRAY_ALPHA)
        png_set_gray_to_rgb(png);
    if (eightBit && bitDepth == 16)
        png_set_strip_16(png);
    const bool hasAlpha = (colorType & PNG_COLOR_MASK_ALPHA) != 0 || png_get_valid(png, info, PNG_INFO_tRNS);
    if (!hasAlpha)
        png_set_add_alpha(png, 0xffff, PNG_FILLER_AFTER);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    return true;
}

bool pngReadRows(png_structp png, png_infop info, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png)))
        return false;
    png_read_image(png, rows);
    png_read_end(png, info); // to IEND: a file cut after the pixel data is still truncated
    return true;
}

struct PngReadStruct {
    png_structp png = nullptr;
    png_infop info = nullptr;
    PngReadStruct() = default;
    PngReadStruct(const PngReadStruct&) = delete;
    PngReadStruct& operator=(const PngReadStruct&) = delete;
    ~PngReadStruct() { png_destroy_read_struct(&png, &info, nullptr); }
};

struct PngPixels {
    int width = 0;
    int height = 0;
    bool sixteenBit = false;
    Bytes samples; ///< RGBA rows, 8 bit, or 16 bit big-endian
};

PngPixels decodePng(const fs::path& path, std::span<const unsigned char> bytes, bool eightBit,
                    const ImageReadLimits& limits) {
    PngSource source{.bytes = bytes, .pos = 0, .error = {}};
    PngReadStruct reader;
    reader.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &source, pngFail, pngWarn);
    reader.info = reader.png ? png_create_info_struct(reader.png) : nullptr;
    png_structp png = reader.png;
    png_infop info = reader.info;
    if (!png || !info)
        throw IoError(path, "cannot decode PNG: out of memory");
    png_set_read_fn(png, &source, pngReadBytes);
#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
    // Fuzzed inputs rarely carry right CRCs; without this the fuzzer never gets past the first chunk.
    png_set_crc_action(png, PNG_CRC_QUIET_USE, PNG_CRC_QUIET_USE);
#endif
    const auto fail = [&](const char* what) {
        throw IoError(path, std::string(what) + (source.error[0] ? source.error.data() : "corrupt file"));
    };
    std::uint64_t minimumBytes = 0;
    if (!pngReadInfo(png, info, eightBit, minimumBytes))
        fail("cannot decode PNG: ");

    PngPixels pixels;
    pixels.width = int(png_get_image_width(png, info));
    pixels.height = int(png_get_image_height(png, info));
    pixels.sixteenBit = png_get_bit_depth(png, info) == 16;
    checkSize(path, png_get_image_width(png, info), png_get_image_height(png, info), limits);
    const std::size_t rowBytes = png_get_rowbytes(png, info);
    if (rowBytes != std::size_t(pixels.width) * 4 * (pixels.sixteenBit ? 2 : 1))
        throw IoError(path, "cannot decode PNG: unexpected row layout");
    checkBytesHold(path, pixels.width, pixels.height, minimumBytes, bytes.size() - source.pos, "PNG");

    pixels.samples.resize(rowBytes * std::size_t(pixels.height));
    std::vector<png_bytep> rows(std::size_t(pixels.height));
    for (std::size_t y = 0; y < rows.size(); ++y)
        rows[y] = pixels.samples.data() + y * rowBytes;
    if (!pngReadRows(png, info, rows.data()))
        fail("cannot decode PNG: ");
    return pixels;
}

ImageF readPngLinear(const fs::path& path, std::span<const unsigned char> bytes,
                     const ImageReadLimits& limits) {
    const PngPixels pixels = decodePng(path, bytes, false, limits);
    ImageF image(pixels.width, pixels.height);
    if (pixels.sixteenBit) {
        for (std::size_t i = 0; i < image.rgba.size(); ++i) {
            const float v = float(pixels.samples[2 * i] << 8 | pixels.samples[2 * i + 1]) / 65535.0f;
            image.rgba[i] = i % 4 == 3 ? v : srgbDecode(v);
        }
    } else {
        std::array<float, 256> decode{};
        for (std::size_t v = 0; v < decode.size(); ++v)
            decode[v] = srgbDecode(float(v) / 255.0f);
        for (std::size_t i = 0; i < image.rgba.size(); ++i) {
            const unsigned char v = pixels.samples[i];
            image.rgba[i] = i % 4 == 3 ? float(v) / 255.0f : decode[v];
        }
    }
    return image;
}

/// Encodes `image` into `out` (its first `size` bytes), `rgb` holding the alpha-less copy of an opaque image;
/// both are kept, so a sequence encoded through the same buffers allocates once. `out` is sized for the worst
/// case and never cleared: only the pages the stream is written to are touched.
void putBigEndian(unsigned char* at, std::uint32_t v) {
    at[0] = static_cast<unsigned char>(v >> 24);
    at[1] = static_cast<unsigned char>(v >> 16);
    at[2] = static_cast<unsigned char>(v >> 8);
    at[3] = static_cast<unsigned char>(v);
}

/// One chunk (length, type, data, CRC over type and data) at `at`, whose data the caller placed at `at + 8`
/// already; returns the chunk's size.
std::size_t finishChunk(unsigned char* at, const char (&type)[5], std::size_t length) {
    putBigEndian(at, std::uint32_t(length));
    std::memcpy(at + 4, type, 4);
    putBigEndian(at + 8 + length, std::uint32_t(libdeflate_crc32(0, at + 4, length + 4)));
    return length + 12;
}

/// Encodes as a PNG (RGB when opaque, else RGBA; 8 bits; no interlace; an sRGB chunk, perceptual intent;
/// filter type None on every row) into `out`; returns the size. The stream is one zlib stream from libdeflate
/// at level 1: a 1080p frame deflates in about 40 ms against 110 ms for zlib at level 3 (libpng's fast
/// setting), and comes out ~5% larger; sequences of hundreds of frames are what it is for.
std::size_t encodePng(const fs::path& path, const Image8& image, Bytes& rows, PngWriter::EncodeBuffer& out,
                      libdeflate_compressor* deflater) {
    bool opaque = true;
    for (std::size_t i = 3; i < image.rgba.size() && opaque; i += 4)
        opaque = image.rgba[i] == 255;
    const std::size_t width = std::size_t(image.width), height = std::size_t(image.height);
    const std::size_t channels = opaque ? 3 : 4;
    const std::size_t stride = width * channels + 1; // each row starts with its filter type, 0: None
    rows.resize(height * stride);
    for (std::size_t y = 0; y < height; ++y) {
        unsigned char* row = rows.data() + y * stride;
        const unsigned char* rgba = image.rgba.data() + y * width * 4;
        row[0] = 0;
        if (opaque) {
            for (std::size_t x = 0; x < width; ++x)
                std::memcpy(row + 1 + x * 3, rgba + x * 4, 3);
        } else {
            std::memcpy(row + 1, rgba, width * 4);
        }
    }

    // Signature, IHDR, sRGB, then the zlib stream in IDAT chunks of at most 1 MiB, then IEND.
    constexpr std::size_t kIdatMax = std::size_t(1) << 20;
    const std::size_t bound = libdeflate_zlib_compress_bound(deflater, rows.size());
    const std::size_t size = 8 + 25 + 13 + 12 * (bound / kIdatMax + 1) + bound + 12;
    if (out.capacity < size) {
        out.bytes.reset(new unsigned char[size]); // default-initialised: not cleared
        out.capacity = size;
    }
    unsigned char* p = out.bytes.get();
    static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    std::memcpy(p, kSignature, 8);
    std::size_t at = 8;
    putBigEndian(p + at + 8, std::uint32_t(width));
    putBigEndian(p + at + 12, std::uint32_t(height));
    const unsigned char header[5] = {8, static_cast<unsigned char>(opaque ? 2 : 6), 0, 0, 0};
    std::memcpy(p + at + 16, header, 5);
    at += finishChunk(p + at, "IHDR", 13);
    p[at + 8] = 0; // rendering intent: perceptual
    at += finishChunk(p + at, "sRGB", 1);
    // Deflated behind the room for the IDAT headers, then moved forward chunk by chunk.
    const std::size_t chunks = bound / kIdatMax + 1;
    unsigned char* stream = p + at + 12 * chunks;
    const std::size_t deflated = libdeflate_zlib_compress(deflater, rows.data(), rows.size(), stream, bound);
    if (deflated == 0)
        throw IoError(path, "cannot encode PNG: the deflated stream exceeded its bound");
    for (std::size_t done = 0; done < deflated;) {
        const std::size_t n = std::min(kIdatMax, deflated - done);
        std::memmove(p + at + 8, stream + done, n);
        at += finishChunk(p + at, "IDAT", n);
        done += n;
    }
    at += finishChunk(p + at, "IEND", 0);
    return at;
}

} // namespace

struct PngWriter::Deflater {
    libdeflate_compressor* compressor = libdeflate_alloc_compressor(1);
    Deflater() {
        if (!compressor)
            throw std::bad_alloc();
    }
    ~Deflater() { libdeflate_free_compressor(compressor); }
    Deflater(const Deflater&) = delete;
    Deflater& operator=(const Deflater&) = delete;
};

namespace {

// ---------------------------------------------------------------------------------------------------------------
// Atomic writes

std::atomic<unsigned> gTemporaryCounter{0};

/// The folder a file goes into; throws unless `path` names a file in an existing folder.
fs::path outputFolder(const fs::path& path) {
    if (!path.has_filename() || path.filename() == "." || path.filename() == "..")
        throw IoError(path, "names a folder, not a file");
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        throw IoError(path, fs::exists(folder, ec) ? quoted(folder) + " is not a folder"
                                                   : "folder " + quoted(folder) + " does not exist");
    return folder;
}

void writeAtomically(const fs::path& path, std::span<const unsigned char> bytes) {
    AtomicFileWriter file(path);
    file.write({reinterpret_cast<const char*>(bytes.data()), bytes.size()});
    file.commit();
}

} // namespace

// ---------------------------------------------------------------------------------------------------------------
// Shared with ExrFrame.cpp (io/ExrDetail.h)

void detail::readCheckedExrBytes(const fs::path& path, std::vector<unsigned char>& bytes,
                                 const ImageReadLimits& limits) {
    requireRegularFile(path);
    readBytes(path, bytes);
    checkExrBytes(path, bytes, limits);
}

void detail::checkExrBytes(const fs::path& path, std::span<const unsigned char> bytes,
                           const ImageReadLimits& limits) {
    if (bytes.empty())
        throw IoError(path, "file is empty");
    if (!startsWith(bytes, kExrMagic))
        throw IoError(path, "is not an OpenEXR file (no OpenEXR magic number)");
    try {
        checkExrHeader(path, bytes, limits);
    } catch (const IoError&) {
        throw;
    } catch (const std::exception& e) {
        // OpenEXR's own parse of the header (an attribute of the wrong type, a truncated value).
        throw IoError(path, std::string("cannot read OpenEXR: ") + e.what());
    }
}

namespace {

/// The data window's size, checked against the limits, once the file holds every chunk it lists.
std::pair<int, int> exrColorSize(const fs::path& path, const Imf::InputFile& file,
                                 const ImageReadLimits& limits) {
    const Imath::Box2i dataWindow = file.header().dataWindow();
    const std::int64_t width64 = std::int64_t(dataWindow.max.x) - dataWindow.min.x + 1;
    const std::int64_t height64 = std::int64_t(dataWindow.max.y) - dataWindow.min.y + 1;
    checkSize(path, width64, height64, limits);
    if (!file.isComplete())
        throw IoError(path, "OpenEXR file is truncated or incomplete (pixel blocks are missing)");
    return {int(width64), int(height64)};
}

bool hasChannel(const Imf::Header& header, const std::string& name) {
    return !name.empty() && header.channels().findChannel(name) != nullptr;
}

bool hasRgbChannel(const Imf::Header& header, const detail::ExrColorChannels& names) {
    return !names.luminance &&
           (hasChannel(header, names.r) || hasChannel(header, names.g) || hasChannel(header, names.b));
}

/// Throws IoError naming `path` and the file's channels when it has no R, G, B or Y channel.
void requireColorChannels(const fs::path& path, const Imf::Header& header,
                          const detail::ExrColorChannels& names) {
    if (hasRgbChannel(header, names) || hasChannel(header, names.y))
        return;
    std::string channels;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
        channels += std::string(channels.empty() ? "" : ", ") + it.name();
    throw IoError(path, "OpenEXR file has no R, G, B or Y channel (channels: " + channels + ")");
}

/// Reads R, G, B (or Y, copied to all three) and A (1 where absent) as `type` values, four a pixel, into
/// `rgba` (width * height * 4 values, each written), plus whatever `extra` adds, in one pass.
template <class Value>
void readRgbaSlices(const fs::path& path, std::span<const unsigned char> bytes, Imf::InputFile& file,
                    Imf::PixelType type, Value* rgba, int width, int height,
                    const detail::ExrExtraSlices& extra, const detail::ExrColorChannels& names) {
    const Imf::Header& header = file.header();
    const Imath::Box2i dataWindow = header.dataWindow();
    const bool hasRgb = hasRgbChannel(header, names);
    Imf::FrameBuffer frameBuffer;
    const std::size_t xStride = 4 * sizeof(Value);
    const std::size_t yStride = xStride * std::size_t(width);
    // Absent channels take the fill value.
    const auto addSlice = [&](const std::string& name, std::size_t component, double fill) {
        frameBuffer.insert(
            name, Imf::Slice::Make(type, rgba + component, dataWindow, xStride, yStride, 1, 1, fill));
    };
    if (hasRgb) {
        addSlice(names.r, 0, 0.0);
        addSlice(names.g, 1, 0.0);
        addSlice(names.b, 2, 0.0);
    } else {
        addSlice(names.y, 0, 0.0);
    }
    if (!names.a.empty())
        addSlice(names.a, 3, 1.0);
    if (extra)
        extra(frameBuffer, dataWindow, width, height);
    if (!detail::readZipScanlines(bytes, header, frameBuffer)) {
        detail::checkExrChunks(path, bytes);
        file.setFrameBuffer(frameBuffer);
        file.readPixels(dataWindow.min.y, dataWindow.max.y);
    }
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    if (!hasRgb) {
        for (std::size_t i = 0; i < pixels; ++i)
            rgba[i * 4 + 1] = rgba[i * 4 + 2] = rgba[i * 4];
    }
    if (names.a.empty()) { // no alpha channel named: opaque, as an absent A reads
        constexpr Value kOne = std::is_same_v<Value, float> ? Value(1) : Value(0x3C00); // 1.0 as half bits
        for (std::size_t i = 0; i < pixels; ++i)
            rgba[i * 4 + 3] = kOne;
    }
}

} // namespace

detail::ExrColorChannels detail::ExrColorChannels::of(const std::vector<std::string>& names) {
    ExrColorChannels c;
    if (names.size() <= 2) {
        c.luminance = true;
        c.y = names.empty() ? "Y" : names[0];
        c.a = names.size() == 2 ? names[1] : "";
    } else {
        c.r = names[0];
        c.g = names[1];
        c.b = names[2];
        c.a = names.size() == 4 ? names[3] : "";
    }
    return c;
}

void detail::readExrColor(const fs::path& path, std::span<const unsigned char> bytes, Imf::InputFile& file,
                          ImageF& image, const ExrExtraSlices& extra, const ImageReadLimits& limits,
                          const ExrColorChannels& names) {
    const auto [width, height] = exrColorSize(path, file, limits);
    const Imf::Header& header = file.header();
    const Imath::Box2i dataWindow = header.dataWindow();
    const bool hasRgb = hasRgbChannel(header, names);
    const bool lumaChroma = names.y == "Y" && (names.standard() || names.luminance) &&
                            hasChannel(header, "Y") && (hasChannel(header, "RY") || hasChannel(header, "BY"));
    if (!hasRgb && lumaChroma) {
        checkExrChunks(path, bytes);
        image = readExrLuminanceChroma(path, bytes, width, height);
        detail::convertExrToRec709(path, header, image);
        if (extra) { // RgbaInputFile reads colour only: the extra layers take a second pass
            Imf::FrameBuffer frameBuffer;
            extra(frameBuffer, dataWindow, width, height);
            // A file with no extra layer has nothing more to read (OpenEXR refuses an empty frame buffer).
            if (frameBuffer.begin() != frameBuffer.end()) {
                file.setFrameBuffer(frameBuffer);
                file.readPixels(dataWindow.min.y, dataWindow.max.y);
            }
        }
        return;
    }
    requireColorChannels(path, header, names);
    // Every value is written (absent channels take their fill), so storage kept from an earlier frame needs
    // no clearing.
    image.width = width;
    image.height = height;
    image.rgba.resize(image.pixelCount() * 4);
    readRgbaSlices(path, bytes, file, Imf::FLOAT, image.rgba.data(), width, height, extra, names);
    detail::convertExrToRec709(path, header, image);
}

bool detail::exrColorIsHalves(const Imf::Header& header, const ExrColorChannels& names) {
    const bool hasRgb = hasRgbChannel(header, names);
    if (!hasRgb && !hasChannel(header, names.y))
        return false;
    if (!hasRgb && names.y == "Y" && (hasChannel(header, "RY") || hasChannel(header, "BY")))
        return false; // luminance/chroma: rebuilt as RGB in float
    for (const std::string* name : {&names.r, &names.g, &names.b, &names.a, &names.y}) {
        if (name->empty())
            continue;
        const Imf::Channel* channel = header.channels().findChannel(*name);
        if (channel != nullptr && channel->type != Imf::HALF)
            return false;
    }
    return !detail::exrToRec709(header).has_value();
}

void detail::readExrColorHalves(const fs::path& path, std::span<const unsigned char> bytes,
                                Imf::InputFile& file, ImageH& image, const ExrExtraSlices& extra,
                                const ImageReadLimits& limits, const ExrColorChannels& names) {
    if (!exrColorIsHalves(file.header(), names))
        throw std::invalid_argument("readExrColorHalves: the colour of \"" + path.string() +
                                    "\" is not halves as stored");
    const auto [width, height] = exrColorSize(path, file, limits);
    image.width = width;
    image.height = height;
    image.rgba.resize(image.pixelCount() * 4);
    readRgbaSlices(path, bytes, file, Imf::HALF, image.rgba.data(), width, height, extra, names);
}

void detail::writeAtomically(const fs::path& path, std::span<const unsigned char> bytes) {
    photopic::writeAtomically(path, bytes);
}

AtomicFileWriter::AtomicFileWriter(fs::path path)
    : mPath(std::move(path)) {
    if (isStreamOutput(mPath)) {
        // A stream takes the bytes as they come: there is no folder to put a temporary in, and a rename would
        // replace the device or pipe rather than write to it. /dev/stdout redirected to a file is standard
        // output too: written through the process's stdout, from where it stands, not reopened and truncated.
        mFile = namesStandardOutput(mPath) ? stdout : std::fopen(mPath.c_str(), "wb");
        if (!mFile)
            throw IoError(mPath, "cannot open: " + errnoMessage(errno));
        return;
    }
    const fs::path folder = outputFolder(mPath);
    std::error_code ec;
    if (fs::is_directory(mPath, ec))
        throw IoError(mPath, "is a folder, not a file");
    // ".NAME.tmp-PID-N", built by appends: GCC 12 warns of a false overlap in `"." + std::string`.
    std::string name(1, '.');
    name.append(mPath.filename().string())
        .append(".tmp-")
        .append(std::to_string(::getpid()))
        .append("-")
        .append(std::to_string(gTemporaryCounter++));
    mTemporary = folder / name;
    mFile = std::fopen(mTemporary.c_str(), "wbx");
    if (!mFile)
        throw IoError(mPath,
                      "cannot create temporary file " + quoted(mTemporary) + ": " + errnoMessage(errno));
}

bool AtomicFileWriter::close() {
    const bool closed = mFile == stdout ? std::fflush(mFile) == 0 : std::fclose(mFile) == 0;
    mFile = nullptr;
    if (!mTemporary.empty()) {
        std::error_code ignored;
        fs::remove(mTemporary, ignored);
    }
    return closed;
}

AtomicFileWriter::~AtomicFileWriter() {
    if (mFile)
        close();
}

void AtomicFileWriter::fail(const std::string& problem) {
    close();
    throw IoError(mPath, problem);
}

void AtomicFileWriter::write(std::string_view text) {
    if (!mFile)
        throw IoError(mPath, "written after commit or after a failure");
    if (std::fwrite(text.data(), 1, text.size(), mFile) != text.size())
        fail("cannot write: " + errnoMessage(errno));
}

std::uint64_t pngMinimumEncodedBytes(std::uint32_t width, std::uint32_t height, int colorType, int bitDepth) {
    int channels = 1; // grey, palette
    if (colorType == PNG_COLOR_TYPE_RGB)
        channels = 3;
    else if (colorType == PNG_COLOR_TYPE_GRAY_ALPHA)
        channels = 2;
    else if (colorType == PNG_COLOR_TYPE_RGB_ALPHA)
        channels = 4;
    const std::uint64_t bits =
        std::uint64_t(width) * height * std::uint64_t(channels) * std::uint64_t(bitDepth);
    return (height + bits / 8) / 1032;
}

namespace {

std::mutex gBeforeReplaceMutex;
BeforeReplace gBeforeReplace;

void beforeReplace(const fs::path& path) {
    BeforeReplace hook;
    {
        const std::lock_guard lock(gBeforeReplaceMutex);
        hook = gBeforeReplace;
    }
    std::error_code ec;
    if (hook && fs::is_regular_file(fs::symlink_status(path, ec)))
        hook(path);
}

} // namespace

void setBeforeReplace(BeforeReplace hook) {
    const std::lock_guard lock(gBeforeReplaceMutex);
    gBeforeReplace = std::move(hook);
}

void AtomicFileWriter::commit() {
    if (!mFile)
        throw IoError(mPath, "committed twice or after a failure");
    if (mTemporary.empty()) { // a stream: flushed, and closed unless it is standard output
        if (!close())
            throw IoError(mPath, "cannot write: " + errnoMessage(errno));
        return;
    }
    // fsync before the rename: after a crash the path holds either the old file or the whole new one.
    if (std::fflush(mFile) != 0 || ::fsync(::fileno(mFile)) != 0)
        fail("cannot write: " + errnoMessage(errno));
    const int closed = std::fclose(mFile);
    mFile = nullptr;
    std::error_code ec;
    if (closed != 0) {
        fs::remove(mTemporary, ec);
        throw IoError(mPath, "cannot write: " + errnoMessage(errno));
    }
    try {
        beforeReplace(mPath);
    } catch (const IoError&) {
        std::error_code ignored;
        fs::remove(mTemporary, ignored);
        throw;
    }
    fs::rename(mTemporary, mPath, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(mTemporary, ignored);
        throw IoError(mPath, "cannot move the finished file into place: " + ec.message());
    }
}

bool namesStandardOutput(const fs::path& path) {
    struct stat target {};
    struct stat out {};
    return path == kStdoutPath || (::stat(path.c_str(), &target) == 0 && ::fstat(STDOUT_FILENO, &out) == 0 &&
                                   target.st_dev == out.st_dev && target.st_ino == out.st_ino);
}

bool isStreamOutput(const fs::path& path) {
    if (namesStandardOutput(path))
        return true;
    std::error_code ec;
    const fs::file_status target = fs::status(path, ec); // through links: /dev/stdout is one
    return !ec && fs::exists(target) && !fs::is_regular_file(target) && !fs::is_directory(target);
}

void requireWritableFile(const fs::path& path) {
    if (isStreamOutput(path))
        return;
    const fs::path folder = outputFolder(path);
    std::error_code ec;
    if (fs::is_directory(path, ec))
        throw IoError(path, "is a folder, not a file");
    // The atomic write renames a new file over the path: over a link that replaces the link, not what it
    // points to, and a device or pipe (/dev/stdout) would be replaced by a regular file.
    const fs::file_status link = fs::symlink_status(path, ec);
    if (!ec && fs::is_symlink(link))
        throw IoError(
            path, "is a symbolic link; writing would replace the link itself: name the file it points to");
    if (!ec && fs::exists(link) && !fs::is_regular_file(link))
        throw IoError(path, "is not a regular file (a device, pipe or socket): write to a file");
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        throw IoError(path, "folder " + quoted(folder) + " is not writable: " + errnoMessage(errno));
}

void writeTextFile(const fs::path& path, std::string_view text) {
    writeAtomically(path, {reinterpret_cast<const unsigned char*>(text.data()), text.size()});
}

ImageF decodeImage(std::span<const unsigned char> bytes, const fs::path& name,
                   const ImageReadLimits& limits) {
    if (bytes.empty())
        throw IoError(name, "file is empty");
    switch (sniff(bytes)) {
    case FileFormat::Exr:
        return readExr(name, bytes, limits);
    case FileFormat::Rgbe:
        return RgbeReader(name, bytes, limits).read();
    case FileFormat::Png:
        return readPngLinear(name, bytes, limits);
    case FileFormat::Unknown:
        break;
    }
    throw IoError(name, unknownFormatMessage(name, bytes.first(std::min<std::size_t>(bytes.size(), 16))));
}

void setExrThreads(int threads) {
    Imf::setGlobalThreadCount(std::max(threads, 0));
}

ImageF readImage(const fs::path& path, const ImageReadLimits& limits) {
    requireRegularFile(path);
    const Bytes bytes = readBytes(path);
    return decodeImage(bytes, path, limits);
}

Image8 decodePng8(std::span<const unsigned char> bytes, const fs::path& name, const ImageReadLimits& limits) {
    if (bytes.empty())
        throw IoError(name, "file is empty");
    if (sniff(bytes) != FileFormat::Png)
        throw IoError(name, "not a PNG file");
    PngPixels pixels = decodePng(name, bytes, true, limits);
    Image8 image;
    image.width = pixels.width;
    image.height = pixels.height;
    image.rgba = std::move(pixels.samples);
    return image;
}

Image8 readPng8(const fs::path& path, const ImageReadLimits& limits) {
    requireRegularFile(path);
    return decodePng8(readBytes(path), path, limits);
}

void writePng(const fs::path& path, const Image8& image) {
    PngWriter().write(path, image);
}

PngWriter::PngWriter()
    : mDeflater(std::make_unique<Deflater>()) {}

PngWriter::~PngWriter() = default;

void PngWriter::write(const fs::path& path, const Image8& image) {
    detail::requirePixels(path, image);
    const std::size_t size = encodePng(path, image, mRows, mEncoded, mDeflater->compressor);
    writeAtomically(path, {mEncoded.bytes.get(), size});
}

void writeExr(const fs::path& path, const ImageF& image) {
    detail::requirePixels(path, image);
    const std::string bytes = encodeExr(path, image);
    writeAtomically(path, std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()));
}

} // namespace photopic
