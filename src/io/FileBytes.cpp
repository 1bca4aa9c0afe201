// Reading an image file's bytes, telling its format from them, and the checks of a declared size that every
// decoder makes before it allocates (io/ImageIoDetail.h).
#include "io/ImageIoDetail.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <memory>
#include <system_error>

namespace photopic::detail {

namespace fs = std::filesystem;

std::string quoted(const fs::path& path) {
    // Built by appends: GCC 12 warns of a false overlap in `"\"" + std::string`.
    std::string text(1, '"');
    text.append(path.string()).push_back('"');
    return text;
}
std::string errnoMessage(int err) {
    return std::generic_category().message(err);
}

namespace {
struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;
} // namespace

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

void readBytes(const fs::path& path, Bytes& bytes, std::size_t limit) {
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

void checkSize(const fs::path& path, std::int64_t width, std::int64_t height, const ImageReadLimits& limits) {
    if (width <= 0 || height <= 0)
        throw IoError(path, "image has no pixels (" + extentText(width, height) + ")");
    if (width > std::max<std::int64_t>(limits.maxPixels, 1) / height)
        throw IoError(path, "image is " + extentText(width, height) + ", more than the limit of " +
                                std::to_string(limits.maxPixels) + " pixels (--max-pixels)");
}

void checkBytesHold(const fs::path& path, std::int64_t width, std::int64_t height, std::uint64_t needed,
                    std::size_t available, const char* format) {
    if (needed > available)
        throw IoError(path, std::string(format) + " file is truncated: " + std::to_string(available) +
                                " bytes cannot hold the " + extentText(width, height) +
                                " image its header declares (at least " + std::to_string(needed) +
                                " needed)");
}

} // namespace photopic::detail
