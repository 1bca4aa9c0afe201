#include "io/DisplayImageIO.h"

#include "io/ExrDetail.h"
#include "io/ImageIO.h"

#include <png.h>
#include <tiffio.h>

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

#include <algorithm>
#include <cctype>
#include <csetjmp>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace photopic {

namespace fs = std::filesystem;

namespace {

using Bytes = std::vector<unsigned char>;

template <typename Image>
bool opaque(const Image& image) {
    using Sample = typename decltype(image.rgba)::value_type;
    constexpr Sample kOne = Sample(~Sample(0));
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) {
        if (image.rgba[i] != kOne) {
            return false;
        }
    }
    return true;
}

/// Row `y` of `image` with `channels` (3: alpha dropped, 4: as stored) samples per pixel.
template <typename Sample>
void packRow(const std::vector<Sample>& rgba, int width, int y, int channels, std::vector<Sample>& row) {
    row.resize(std::size_t(width) * std::size_t(channels));
    const Sample* src = rgba.data() + std::size_t(y) * std::size_t(width) * 4;
    for (std::size_t x = 0; x < std::size_t(width); ++x) {
        std::copy_n(src + x * 4, channels, row.data() + x * std::size_t(channels));
    }
}

void writeBytes(const fs::path& path, const Bytes& bytes) {
    detail::writeAtomically(path, bytes);
}

// ---------------------------------------------------------------------------------------------------------------
// PNG, 16 bits (libpng's simplified API writes 16-bit samples only as linear light, so the full API is used)

struct PngWriteState {
    Bytes* out;
    std::string error;
};

void pngWrite(png_structp png, png_bytep data, png_size_t size) {
    auto* state = static_cast<PngWriteState*>(png_get_io_ptr(png));
    state->out->insert(state->out->end(), data, data + size);
}

void pngFlush(png_structp) {}

void pngError(png_structp png, png_const_charp message) {
    static_cast<PngWriteState*>(png_get_error_ptr(png))->error = message;
    png_longjmp(png, 1);
}

void pngWarning(png_structp, png_const_charp) {}

/// Encodes with every libpng call inside one setjmp frame and no C++ object with a destructor in it (a
/// longjmp would skip the destructor).
bool encodePng16(png_structp png, png_infop info, const Image16& image, int channels,
                 std::vector<std::uint16_t>& row) {
    if (setjmp(png_jmpbuf(png))) {
        return false;
    }
    png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 16,
                 channels == 4 ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    png_set_swap(png); // PNG stores samples big-endian; ours are in host (little-endian) order
    for (int y = 0; y < image.height; ++y) {
        packRow(image.rgba, image.width, y, channels, row);
        png_write_row(png, reinterpret_cast<png_const_bytep>(row.data()));
    }
    png_write_end(png, info);
    return true;
}

// ---------------------------------------------------------------------------------------------------------------
// TIFF, through libtiff's client I/O into memory (so the file goes through the atomic writer)

struct TiffMemory {
    Bytes bytes;
    toff_t position = 0;
};

tsize_t tiffRead(thandle_t handle, tdata_t data, tsize_t size) {
    auto* m = static_cast<TiffMemory*>(handle);
    const toff_t available = m->position < m->bytes.size() ? m->bytes.size() - m->position : 0;
    const auto n = std::min<toff_t>(toff_t(size), available);
    std::memcpy(data, m->bytes.data() + m->position, n);
    m->position += n;
    return tsize_t(n);
}

tsize_t tiffWrite(thandle_t handle, tdata_t data, tsize_t size) {
    auto* m = static_cast<TiffMemory*>(handle);
    const auto n = std::size_t(size);
    if (m->position + n > m->bytes.size()) {
        m->bytes.resize(m->position + n);
    }
    std::memcpy(m->bytes.data() + m->position, data, n);
    m->position += n;
    return size;
}

toff_t tiffSeek(thandle_t handle, toff_t offset, int whence) {
    auto* m = static_cast<TiffMemory*>(handle);
    const toff_t base = whence == SEEK_CUR ? m->position : whence == SEEK_END ? m->bytes.size() : 0;
    m->position = base + offset;
    return m->position;
}

int tiffClose(thandle_t) {
    return 0;
}

toff_t tiffSize(thandle_t handle) {
    return static_cast<TiffMemory*>(handle)->bytes.size();
}

int tiffMap(thandle_t, tdata_t*, toff_t*) {
    return 0;
}

void tiffUnmap(thandle_t, tdata_t, toff_t) {}

struct TiffCloser {
    void operator()(TIFF* tiff) const { TIFFClose(tiff); }
};

template <typename Sample>
void writeTiffImage(const fs::path& path, const std::vector<Sample>& rgba, int width, int height,
                    bool hasAlpha) {
    constexpr int kBits = int(sizeof(Sample) * 8);
    const int channels = hasAlpha ? 4 : 3;
    TiffMemory memory;
    std::unique_ptr<TIFF, TiffCloser> tiff(TIFFClientOpen(path.c_str(), "w", &memory, tiffRead, tiffWrite,
                                                          tiffSeek, tiffClose, tiffSize, tiffMap, tiffUnmap));
    if (!tiff) {
        throw IoError(path, "cannot start a TIFF encoder");
    }
    TIFF* t = tiff.get();
    TIFFSetField(t, TIFFTAG_IMAGEWIDTH, std::uint32_t(width));
    TIFFSetField(t, TIFFTAG_IMAGELENGTH, std::uint32_t(height));
    TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, kBits);
    TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, channels);
    TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_RGB);
    TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(t, TIFFTAG_ORIENTATION, ORIENTATION_TOPLEFT);
    TIFFSetField(t, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
    // Horizontal differencing: neighbouring pixels of a display image differ little, and their differences
    // deflate smaller than the values themselves (TIFF 6.0, section 14).
    TIFFSetField(t, TIFFTAG_PREDICTOR, PREDICTOR_HORIZONTAL);
    if (hasAlpha) {
        const std::uint16_t extra[] = {EXTRASAMPLE_UNASSALPHA};
        TIFFSetField(t, TIFFTAG_EXTRASAMPLES, 1, extra);
    }
    TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, TIFFDefaultStripSize(t, 0));
    std::vector<Sample> row;
    for (int y = 0; y < height; ++y) {
        packRow(rgba, width, y, channels, row);
        if (TIFFWriteScanline(t, row.data(), std::uint32_t(y), 0) != 1) {
            throw IoError(path, "cannot encode TIFF row " + std::to_string(y));
        }
    }
    if (!TIFFFlush(t)) {
        throw IoError(path, "cannot encode TIFF");
    }
    tiff.reset();
    writeBytes(path, memory.bytes);
}

void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<Bytes*>(context);
    const auto* bytes = static_cast<const unsigned char*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

} // namespace

std::optional<DisplayFileFormat> displayFileFormatFor(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".png") {
        return DisplayFileFormat::Png;
    }
    if (ext == ".tif" || ext == ".tiff") {
        return DisplayFileFormat::Tiff;
    }
    if (ext == ".jpg" || ext == ".jpeg") {
        return DisplayFileFormat::Jpeg;
    }
    return std::nullopt;
}

bool holdsBitDepth(DisplayFileFormat format, int bitDepth) {
    return bitDepth == 8 || (bitDepth == 16 && format != DisplayFileFormat::Jpeg);
}

std::string_view displayFileFormatName(DisplayFileFormat format) {
    switch (format) {
    case DisplayFileFormat::Png:
        return "PNG";
    case DisplayFileFormat::Tiff:
        return "TIFF";
    case DisplayFileFormat::Jpeg:
        return "JPEG";
    }
    return "?";
}

void writePng16(const fs::path& path, const Image16& image) {
    detail::requirePixels(path, image);
    Bytes bytes;
    PngWriteState state{.out = &bytes, .error = {}};
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, pngError, pngWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        throw IoError(path, "cannot start a PNG encoder (out of memory)");
    }
    png_set_write_fn(png, &state, pngWrite, pngFlush);
    std::vector<std::uint16_t> row;
    const bool ok = encodePng16(png, info, image, opaque(image) ? 3 : 4, row);
    png_destroy_write_struct(&png, &info);
    if (!ok) {
        throw IoError(path, "cannot encode PNG: " + state.error);
    }
    writeBytes(path, bytes);
}

void writeTiff(const fs::path& path, const Image8& image) {
    detail::requirePixels(path, image);
    writeTiffImage(path, image.rgba, image.width, image.height, !opaque(image));
}

void writeTiff(const fs::path& path, const Image16& image) {
    detail::requirePixels(path, image);
    writeTiffImage(path, image.rgba, image.width, image.height, !opaque(image));
}

void writeJpeg(const fs::path& path, const Image8& image, int quality) {
    detail::requirePixels(path, image);
    if (quality < 1 || quality > 100) {
        throw IoError(path, "JPEG quality " + std::to_string(quality) + " is outside [1, 100]");
    }
    Bytes bytes;
    if (!stbi_write_jpg_to_func(appendBytes, &bytes, image.width, image.height, 4, image.rgba.data(),
                                quality)) {
        throw IoError(path, "cannot encode JPEG");
    }
    writeBytes(path, bytes);
}

} // namespace photopic
