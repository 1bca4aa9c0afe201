#pragma once
// Internal to the io library: what the image files' readers and writers share (ImageIO.cpp, FileBytes.cpp,
// ExrImage.cpp, RadianceImage.cpp, PngImage.cpp, AtomicFile.cpp): reading a file's bytes, telling its format
// from them, the checks of a declared size, and each format's decoder for decodeImage. Not part of the
// public API.

#include "core/Image.h"
#include "io/ImageIO.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace photopic::detail {

using Bytes = std::vector<unsigned char>;

/// `"PATH"`, for messages.
[[nodiscard]] std::string quoted(const std::filesystem::path& path);
/// The text of an errno value.
[[nodiscard]] std::string errnoMessage(int err);

/// Throws IoError unless `path` is an existing regular file.
void requireRegularFile(const std::filesystem::path& path);
/// The first `limit` bytes of the file (all of it by default), into `bytes` (its capacity kept).
void readBytes(const std::filesystem::path& path, Bytes& bytes, std::size_t limit = SIZE_MAX);
[[nodiscard]] Bytes readBytes(const std::filesystem::path& path);

enum class FileFormat { Exr, Rgbe, Png, Unknown };

inline constexpr std::array<unsigned char, 4> kExrMagic{0x76, 0x2f, 0x31, 0x01};
inline constexpr std::array<unsigned char, 8> kPngMagic{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

template <std::size_t N>
[[nodiscard]] bool startsWith(std::span<const unsigned char> bytes, const std::array<unsigned char, N>& magic) {
    return bytes.size() >= N && std::equal(magic.begin(), magic.end(), bytes.begin());
}

/// The format the first bytes of a file say it is in.
[[nodiscard]] FileFormat sniff(std::span<const unsigned char> head);
/// Why `head` is not an image this library reads, naming its extension and first bytes.
[[nodiscard]] std::string unknownFormatMessage(const std::filesystem::path& path,
                                               std::span<const unsigned char> head);

[[nodiscard]] std::string extentText(std::int64_t width, std::int64_t height);
/// The declared size, before anything is allocated for it: some pixels, at most limits.maxPixels.
void checkSize(const std::filesystem::path& path, std::int64_t width, std::int64_t height,
               const ImageReadLimits& limits);
/// The declared size against the bytes that could hold it: `needed` is a lower bound on the file's size for
/// that image; a file shorter than that is truncated or lies about its size, and is rejected unallocated.
void checkBytesHold(const std::filesystem::path& path, std::int64_t width, std::int64_t height,
                    std::uint64_t needed, std::size_t available, const char* format);

/// Each format's decoder of a whole file in memory (`path` names it in errors).
[[nodiscard]] ImageF readExr(const std::filesystem::path& path, std::span<const unsigned char> bytes,
                             const ImageReadLimits& limits);
[[nodiscard]] ImageF readRadiance(const std::filesystem::path& path, std::span<const unsigned char> bytes,
                                  const ImageReadLimits& limits);
[[nodiscard]] ImageF readPngLinear(const std::filesystem::path& path, std::span<const unsigned char> bytes,
                                   const ImageReadLimits& limits);

} // namespace photopic::detail
