#include "io/ImageIO.h"

#include "core/Color.h"
#include "io/ExrDetail.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfRgbaFile.h>
#include <ImfStdIO.h>
#include <png.h>
#include <stb_image.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <span>
#include <string>
#include <system_error>
#include <vector>

namespace photopic {

namespace fs = std::filesystem;

IoError::IoError(const fs::path& path, std::string_view problem)
    : std::runtime_error("\"" + path.string() + "\": " + std::string(problem)) {}

namespace {

using Bytes = std::vector<unsigned char>;

/// Largest image accepted: 2^28 pixels (4 GiB as ImageF). A bigger header is most likely corrupt.
constexpr std::int64_t kMaxPixels = std::int64_t(1) << 28;

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

struct StbiFree {
    void operator()(void* pixels) const { stbi_image_free(pixels); }
};

// ---------------------------------------------------------------------------------------------------------------
// Reading files

} // namespace

void detail::requireRegularFile(const fs::path& path) {
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

namespace {

/// The first `limit` bytes of the file (all of it by default).
Bytes readBytes(const fs::path& path, std::size_t limit = SIZE_MAX) {
    const FilePtr file(std::fopen(path.c_str(), "rb"));
    if (!file)
        throw IoError(path, "cannot open: " + errnoMessage(errno));
    constexpr std::size_t kChunk = std::size_t(1) << 20;
    Bytes bytes;
    while (bytes.size() < limit) {
        const std::size_t old = bytes.size();
        const std::size_t want = std::min(kChunk, limit - old);
        bytes.resize(old + want);
        const std::size_t got = std::fread(bytes.data() + old, 1, want, file.get());
        bytes.resize(old + got);
        if (got < want) {
            if (std::ferror(file.get()))
                throw IoError(path, "read error: " + errnoMessage(errno));
            break;
        }
    }
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

void checkSize(const fs::path& path, std::int64_t width, std::int64_t height) {
    if (width <= 0 || height <= 0)
        throw IoError(path,
                      "image has no pixels (" + std::to_string(width) + "x" + std::to_string(height) + ")");
    if (width > kMaxPixels / height)
        throw IoError(path, "image is implausibly large (" + std::to_string(width) + "x" +
                                std::to_string(height) + "), file corrupt?");
}

// ---------------------------------------------------------------------------------------------------------------
// OpenEXR

/// Luminance/chroma files (Y, RY, BY; chroma subsampled) are always half: RgbaInputFile converts them.
ImageF readExrLuminanceChroma(const fs::path& path, int width, int height) {
    Imf::RgbaInputFile file(path.c_str());
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

} // namespace

ImageF detail::readExrColor(const fs::path& path, Imf::InputFile& file, const ExrExtraSlices& extra) {
    const Imf::Header& header = file.header();
    const Imath::Box2i dataWindow = header.dataWindow();
    const std::int64_t width64 = std::int64_t(dataWindow.max.x) - dataWindow.min.x + 1;
    const std::int64_t height64 = std::int64_t(dataWindow.max.y) - dataWindow.min.y + 1;
    checkSize(path, width64, height64);
    const int width = int(width64);
    const int height = int(height64);
    if (!file.isComplete())
        throw IoError(path, "OpenEXR file is truncated or incomplete (pixel blocks are missing)");

    const Imf::ChannelList& channels = header.channels();
    const auto has = [&](const char* name) { return channels.findChannel(name) != nullptr; };
    const bool hasRgb = has("R") || has("G") || has("B");
    if (!hasRgb && has("Y") && (has("RY") || has("BY"))) {
        ImageF image = readExrLuminanceChroma(path, width, height);
        if (extra) { // RgbaInputFile reads colour only: the extra layers take a second pass
            Imf::FrameBuffer frameBuffer;
            extra(frameBuffer, dataWindow, width, height);
            file.setFrameBuffer(frameBuffer);
            file.readPixels(dataWindow.min.y, dataWindow.max.y);
        }
        return image;
    }
    if (!hasRgb && !has("Y")) {
        std::string names;
        for (auto it = channels.begin(); it != channels.end(); ++it)
            names += std::string(names.empty() ? "" : ", ") + it.name();
        throw IoError(path, "OpenEXR file has no R, G, B or Y channel (channels: " + names + ")");
    }

    ImageF image(width, height);
    Imf::FrameBuffer frameBuffer;
    const std::size_t xStride = 4 * sizeof(float);
    const std::size_t yStride = xStride * std::size_t(width);
    // Every channel is read as FLOAT whatever it is stored as; absent channels take the fill value.
    const auto addSlice = [&](const char* name, std::size_t component, double fill) {
        frameBuffer.insert(name, Imf::Slice::Make(Imf::FLOAT, image.rgba.data() + component, dataWindow,
                                                  xStride, yStride, 1, 1, fill));
    };
    if (hasRgb) {
        addSlice("R", 0, 0.0);
        addSlice("G", 1, 0.0);
        addSlice("B", 2, 0.0);
    } else {
        addSlice("Y", 0, 0.0);
    }
    addSlice("A", 3, 1.0);
    if (extra)
        extra(frameBuffer, dataWindow, width, height);
    file.setFrameBuffer(frameBuffer);
    file.readPixels(dataWindow.min.y, dataWindow.max.y);

    if (!hasRgb) {
        for (std::size_t i = 0; i < image.pixelCount(); ++i)
            image.rgba[i * 4 + 1] = image.rgba[i * 4 + 2] = image.rgba[i * 4];
    }
    return image;
}

namespace {

ImageF readExr(const fs::path& path) {
    try {
        Imf::InputFile file(path.c_str());
        return detail::readExrColor(path, file);
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
    RgbeReader(const fs::path& path, std::span<const unsigned char> bytes)
        : mPath(path)
        , mBytes(bytes) {}

    ImageF read() {
        readHeader();
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
        checkSize(mPath, width, height);
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
    std::size_t mPos = 0;
    int mWidth = 0;
    int mHeight = 0;
};

// ---------------------------------------------------------------------------------------------------------------
// PNG: decoded by stb_image (raw samples, no gamma handling), encoded by libpng's simplified API.

/// stb_image decodes a PNG whose end is cut off as long as the pixel data is whole; insist on the IEND chunk.
void requireCompletePng(const fs::path& path, std::span<const unsigned char> bytes) {
    constexpr std::array<unsigned char, 12> kIend{0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    if (std::search(bytes.begin(), bytes.end(), kIend.begin(), kIend.end()) == bytes.end())
        throw IoError(path, "PNG file is truncated (no IEND chunk)");
    if (bytes.size() > std::size_t(INT32_MAX))
        throw IoError(path, "PNG file is too large (over 2 GiB)");
}

/// Decodes to RGBA with samples of type T (stbi_uc or stbi_us), setting width and height.
template <typename T>
std::unique_ptr<T, StbiFree> decodePng(const fs::path& path, std::span<const unsigned char> bytes, int& width,
                                       int& height) {
    requireCompletePng(path, bytes);
    stbi_set_flip_vertically_on_load_thread(0);
    int channels = 0;
    T* pixels = nullptr;
    if constexpr (sizeof(T) == 2)
        pixels = stbi_load_16_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels, 4);
    else
        pixels = stbi_load_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channels, 4);
    if (!pixels)
        throw IoError(path, std::string("cannot decode PNG: ") + stbi_failure_reason());
    std::unique_ptr<T, StbiFree> owned(pixels);
    checkSize(path, width, height);
    return owned;
}

ImageF readPngLinear(const fs::path& path, std::span<const unsigned char> bytes) {
    int width = 0;
    int height = 0;
    ImageF image;
    if (stbi_is_16_bit_from_memory(bytes.data(), int(std::min<std::size_t>(bytes.size(), INT32_MAX)))) {
        const auto pixels = decodePng<stbi_us>(path, bytes, width, height);
        image = ImageF(width, height);
        for (std::size_t i = 0; i < image.rgba.size(); ++i) {
            const float v = float(pixels.get()[i]) / 65535.0f;
            image.rgba[i] = i % 4 == 3 ? v : srgbDecode(v);
        }
    } else {
        const auto pixels = decodePng<stbi_uc>(path, bytes, width, height);
        std::array<float, 256> decode{};
        for (std::size_t v = 0; v < decode.size(); ++v)
            decode[v] = srgbDecode(float(v) / 255.0f);
        image = ImageF(width, height);
        for (std::size_t i = 0; i < image.rgba.size(); ++i) {
            const unsigned char v = pixels.get()[i];
            image.rgba[i] = i % 4 == 3 ? float(v) / 255.0f : decode[v];
        }
    }
    return image;
}

Bytes encodePng(const fs::path& path, const Image8& image) {
    bool opaque = true;
    for (std::size_t i = 3; i < image.rgba.size() && opaque; i += 4)
        opaque = image.rgba[i] == 255;
    const std::size_t pixelCount = std::size_t(image.width) * std::size_t(image.height);
    const std::size_t channels = opaque ? 3 : 4;
    Bytes rgb;
    if (opaque) {
        rgb.resize(pixelCount * 3);
        for (std::size_t i = 0; i < pixelCount; ++i)
            std::copy_n(image.rgba.data() + i * 4, 3, rgb.data() + i * 3);
    }
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = png_uint_32(image.width);
    png.height = png_uint_32(image.height);
    png.format = opaque ? PNG_FORMAT_RGB : PNG_FORMAT_RGBA;
    // Fast deflate: a 1080p frame encodes ~10x faster than at the default level for ~10-20% more bytes, which
    // is what sequences of hundreds of frames need.
    png.flags = PNG_IMAGE_FLAG_FAST;
    const void* pixels =
        opaque ? static_cast<const void*>(rgb.data()) : static_cast<const void*>(image.rgba.data());
    const auto stride = png_int_32(std::size_t(image.width) * channels);

    // Upper bound on the stream (libpng's PNG_IMAGE_PNG_SIZE_MAX, restated without its C casts): deflate's
    // bound on the filtered rows, 12 bytes per 8 KiB IDAT chunk, and the fixed chunks.
    const std::size_t raw = std::size_t(image.height) * (std::size_t(stride) + 1);
    const std::size_t deflated = raw + (raw + 7) / 8 + (raw + 63) / 64 + 11;
    png_alloc_size_t size = 8 + 25 + 16 + 44 + 12 + 12 + 12 * (deflated / 8192 + 1) + deflated;
    Bytes out(size);
    if (!png_image_write_to_memory(&png, out.data(), &size, 0, pixels, stride, nullptr)) {
        const std::string message = png.message;
        png_image_free(&png);
        throw IoError(path, "cannot encode PNG: " + message);
    }
    out.resize(size);
    return out;
}

// ---------------------------------------------------------------------------------------------------------------
// Atomic writes

std::atomic<unsigned> gTemporaryCounter{0};

} // namespace

void detail::writeAtomically(const fs::path& path, std::span<const unsigned char> bytes) {
    if (!path.has_filename())
        throw IoError(path, "names a folder, not a file");
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        throw IoError(path, fs::exists(folder, ec) ? quoted(folder) + " is not a folder"
                                                   : "folder " + quoted(folder) + " does not exist");

    const fs::path temporary =
        folder / ("." + path.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                  std::to_string(gTemporaryCounter++));
    FilePtr file(std::fopen(temporary.c_str(), "wbx"));
    if (!file)
        throw IoError(path, "cannot create temporary file " + quoted(temporary) + ": " + errnoMessage(errno));
    const auto fail = [&](const std::string& problem) {
        file.reset();
        std::error_code ignored;
        fs::remove(temporary, ignored);
        throw IoError(path, problem);
    };
    // fsync before the rename: after a crash the path holds either the old file or the whole new one.
    if (std::fwrite(bytes.data(), 1, bytes.size(), file.get()) != bytes.size() ||
        std::fflush(file.get()) != 0 || ::fsync(::fileno(file.get())) != 0)
        fail("cannot write: " + errnoMessage(errno));
    if (std::fclose(file.release()) != 0)
        fail("cannot write: " + errnoMessage(errno));
    fs::rename(temporary, path, ec);
    if (ec)
        fail("cannot move the finished file into place: " + ec.message());
}

namespace {

template <typename Image>
void requirePixels(const fs::path& path, const Image& image) {
    if (image.empty())
        throw IoError(path, "cannot write an empty image (" + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + ")");
    const std::size_t expected = std::size_t(image.width) * std::size_t(image.height) * 4;
    if (image.rgba.size() != expected)
        throw IoError(path, "image holds " + std::to_string(image.rgba.size()) + " values, expected " +
                                std::to_string(expected) + " for " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + " RGBA");
    if (std::int64_t(image.width) * image.height > kMaxPixels)
        throw IoError(path, "image is too large to write");
}

} // namespace

void writeTextFile(const fs::path& path, std::string_view text) {
    detail::writeAtomically(path, {reinterpret_cast<const unsigned char*>(text.data()), text.size()});
}

void detail::requireExrFile(const fs::path& path) {
    const Bytes head = readBytes(path, 16);
    if (sniff(head) != FileFormat::Exr)
        throw IoError(path, head.empty() ? std::string("file is empty") : unknownFormatMessage(path, head));
}

ImageF readImage(const fs::path& path) {
    detail::requireRegularFile(path);
    const Bytes head = readBytes(path, 16);
    if (head.empty())
        throw IoError(path, "file is empty");
    switch (sniff(head)) {
    case FileFormat::Exr:
        return readExr(path);
    case FileFormat::Rgbe: {
        const Bytes bytes = readBytes(path);
        return RgbeReader(path, bytes).read();
    }
    case FileFormat::Png:
        return readPngLinear(path, readBytes(path));
    case FileFormat::Unknown:
        break;
    }
    throw IoError(path, unknownFormatMessage(path, head));
}

Image8 readPng8(const fs::path& path) {
    detail::requireRegularFile(path);
    const Bytes bytes = readBytes(path);
    if (bytes.empty())
        throw IoError(path, "file is empty");
    if (sniff(bytes) != FileFormat::Png)
        throw IoError(path, "not a PNG file");
    int width = 0;
    int height = 0;
    const auto pixels = decodePng<stbi_uc>(path, bytes, width, height);
    Image8 image(width, height);
    std::copy_n(pixels.get(), image.rgba.size(), image.rgba.begin());
    return image;
}

void writePng(const fs::path& path, const Image8& image) {
    requirePixels(path, image);
    detail::writeAtomically(path, encodePng(path, image));
}

void writeExr(const fs::path& path, const ImageF& image) {
    requirePixels(path, image);
    const std::string bytes = encodeExr(path, image);
    detail::writeAtomically(path,
                            std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()));
}

} // namespace photopic
