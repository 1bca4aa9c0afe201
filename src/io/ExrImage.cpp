// OpenEXR: the checks of a file's header before OpenEXR parses it (attribute sizes, parts, tiles, the data
// window against the bytes), reading its colour (with other layers in the same pass, io/ExrDetail.h) and
// writing a half-float RGBA file.
#include "io/ImageIoDetail.h"

#include "io/ExrDetail.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfPartType.h>
#include <ImfRgbaFile.h>
#include <ImfStdIO.h>
#include <ImfVersion.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <set>
#include <string_view>
#include <type_traits>
#include <utility>

namespace photopic {

namespace fs = std::filesystem;
using namespace detail;

namespace {

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

/// Deep data (any number of samples a pixel, version flag 0x800 or a part of type deepscanline or deeptile)
/// has no flat colour to read; refused before OpenEXR's deep reader sees the file.
[[noreturn]] void refuseDeep(const fs::path& path, const std::string& what) {
    throw IoError(path,
                  "OpenEXR deep data is not read (" + what +
                      "): flatten it first, e.g. with your renderer's or compositor's deep-to-image step");
}

/// The header attributes read in turn from byte 8: name, type, 32-bit size, value.
class AttributeWalk {
public:
    AttributeWalk(const fs::path& path, std::span<const unsigned char> bytes)
        : mPath(path)
        , mBytes(bytes) {}

    /// The null-terminated string at the read position, which moves past it.
    std::string cString() {
        const auto end =
            std::find(mBytes.begin() + std::ptrdiff_t(std::min(mPos, mBytes.size())), mBytes.end(), 0);
        if (end == mBytes.end())
            throw IoError(mPath, "OpenEXR header is truncated");
        const std::string text(mBytes.begin() + std::ptrdiff_t(mPos), end);
        mPos = std::size_t(end - mBytes.begin()) + 1;
        return text;
    }

    /// The value of attribute `name` of `type` after its size field, checked against the bytes left and
    /// against its type; the read position moves past it.
    void skipValue(const std::string& name, const std::string& type) {
        if (mBytes.size() - mPos < 4)
            throw IoError(mPath, "OpenEXR header is truncated");
        const std::uint32_t size = std::uint32_t(mBytes[mPos]) | std::uint32_t(mBytes[mPos + 1]) << 8 |
                                   std::uint32_t(mBytes[mPos + 2]) << 16 |
                                   std::uint32_t(mBytes[mPos + 3]) << 24;
        mPos += 4;
        if (size > mBytes.size() - mPos)
            throw IoError(mPath, "OpenEXR header is corrupt: attribute \"" + name + "\" (" + type +
                                     ") declares " + std::to_string(size) + " bytes, the file has " +
                                     std::to_string(mBytes.size() - mPos) + " left");
        const std::optional<std::size_t> fixed = exrFixedValueSize(type);
        if (fixed && size != *fixed)
            throw IoError(mPath, "OpenEXR header is corrupt: attribute \"" + name + "\" (" + type +
                                     ") declares " + std::to_string(size) + " bytes, a " + type + " has " +
                                     std::to_string(*fixed));
        if (name == "type" && type == "string") {
            const std::string partType(mBytes.begin() + std::ptrdiff_t(mPos),
                                       mBytes.begin() + std::ptrdiff_t(mPos + size));
            if (partType.starts_with("deep"))
                refuseDeep(mPath, "a part of type " + partType.substr(0, 16));
        }
        if (type == "chlist" && !exrChannelListFits(mBytes.subspan(mPos, size)))
            throw IoError(mPath, "OpenEXR header is corrupt: channel list \"" + name +
                                     "\" does not end where its declared " + std::to_string(size) +
                                     " bytes do");
        mPos += size;
    }

private:
    const fs::path& mPath;
    std::span<const unsigned char> mBytes;
    std::size_t mPos = 8;
};

/// Walks the header attributes (name, type, 32-bit size, value) without OpenEXR and refuses a size beyond the
/// file's end: OpenEXR allocates a value's declared size (up to 2 GiB for an unknown type) before it reads
/// it. Refused too: an attribute named twice in one header, and a known type whose reader takes another
/// number of bytes than the declared size (a fixed-size value, a channel list), after which OpenEXR would
/// go on reading the next attribute from the wrong place, where a size it then trusted was never checked.
void checkExrAttributeSizes(const fs::path& path, std::span<const unsigned char> bytes) {
    const bool multiPart = detail::isMultiPartExr(bytes);
    if (bytes.size() >= 8 && (bytes[5] & 0x08) != 0)
        refuseDeep(path, "the file's version field says it holds deep data");
    AttributeWalk walk(path, bytes);
    std::set<std::string> names; // of this header's attributes so far
    for (bool firstInHeader = true;;) {
        const std::string name = walk.cString();
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
        const std::string type = walk.cString();
        walk.skipValue(name, type);
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

} // namespace

ImageF detail::readExr(const fs::path& path, std::span<const unsigned char> bytes,
                       const ImageReadLimits& limits) {
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

void writeExr(const fs::path& path, const ImageF& image) {
    detail::requirePixels(path, image);
    const std::string bytes = encodeExr(path, image);
    detail::writeAtomically(path,
                            std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()));
}

} // namespace photopic
