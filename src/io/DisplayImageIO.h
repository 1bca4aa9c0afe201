#pragma once
// Display images out: 8- and 16-bit PNG, 8- and 16-bit TIFF, and JPEG, the format chosen by the output's
// extension. Three small codec libraries (libpng, libtiff, stb_image_write) rather than OpenImageIO, which
// would bring a large tree of dependencies for these three formats. Every writer is atomic like writePng
// (io/ImageIO.h): a reader never sees a half-written file, and a failure leaves the path as it was.

#include "core/Image.h"

#include <filesystem>
#include <optional>
#include <string_view>

namespace photopic {

/// The file formats a display image is written in.
enum class DisplayFileFormat {
    Png,  ///< .png: 8 or 16 bits per channel, deflate
    Tiff, ///< .tif, .tiff: 8 or 16 bits per channel, deflate with horizontal differencing
    Jpeg, ///< .jpg, .jpeg: 8 bits per channel, lossy, no alpha
};

/// The format an output path's extension names (any case), or nullopt for any other extension.
[[nodiscard]] std::optional<DisplayFileFormat> displayFileFormatFor(const std::filesystem::path& path);

/// Whether `format` can hold `bitDepth` (8 or 16) bits per channel: JPEG holds 8 only.
[[nodiscard]] bool holdsBitDepth(DisplayFileFormat format, int bitDepth);

/// The format's name for messages ("PNG", "TIFF", "JPEG").
[[nodiscard]] std::string_view displayFileFormatName(DisplayFileFormat format);

inline constexpr int kDefaultJpegQuality = 95; ///< stb_image_write's quality scale, [1, 100]

/// Writes a 16-bit sRGB PNG (samples as stored, 65535 = 1.0, an sRGB chunk), RGB when every alpha is 65535
/// and RGBA otherwise. Atomic; throws IoError naming the path.
void writePng16(const std::filesystem::path& path, const Image16& image);

/// Writes an 8- or 16-bit RGB(A) TIFF, deflate compressed with horizontal differencing (lossless), rows top
/// to bottom, alpha (unassociated) only when some pixel is not opaque. Atomic; throws IoError naming the
/// path.
void writeTiff(const std::filesystem::path& path, const Image8& image);
void writeTiff(const std::filesystem::path& path, const Image16& image);

/// Writes a baseline JPEG (RGB; alpha is dropped) at `quality`, [1, 100]. Atomic; throws IoError naming the
/// path, also for a quality out of range.
void writeJpeg(const std::filesystem::path& path, const Image8& image, int quality = kDefaultJpegQuality);

} // namespace photopic
