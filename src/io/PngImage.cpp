// PNG: decoded by libpng's full API (raw samples, no gamma handling), encoded here (one zlib stream from
// libdeflate).
//
// libpng reports errors by longjmp. The functions that call into it under setjmp hold no object with a
// destructor, so a longjmp out of them skips nothing; everything they fill is owned by their callers.
#include "io/ImageIoDetail.h"

#include "core/Color.h"
#include "io/ExrDetail.h"

#include <libdeflate.h>
#include <png.h>

#include <algorithm>
#include <array>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>

namespace photopic {

namespace fs = std::filesystem;
using namespace detail;

namespace {

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
/// at level 1: several times faster than zlib at libpng's fast setting for a stream ~5% larger
/// (docs/bench/LOG.md); sequences of hundreds of frames are what it is for.
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

ImageF detail::readPngLinear(const fs::path& path, std::span<const unsigned char> bytes,
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
    detail::writeAtomically(path, {mEncoded.bytes.get(), size});
}

} // namespace photopic
