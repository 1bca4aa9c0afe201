// Reading any image file this library knows (OpenEXR, Radiance, PNG: told by their first bytes) and the
// errors that name the file. Each format lives in its own file: ExrImage.cpp, RadianceImage.cpp,
// PngImage.cpp; the bytes and the size checks in FileBytes.cpp; atomic writes in AtomicFile.cpp.
#include "io/ImageIO.h"

#include "io/ImageIoDetail.h"

#include <ImfThreading.h>

#include <algorithm>

namespace photopic {

namespace fs = std::filesystem;
using namespace detail;

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

ImageF decodeImage(std::span<const unsigned char> bytes, const fs::path& name,
                   const ImageReadLimits& limits) {
    if (bytes.empty())
        throw IoError(name, "file is empty");
    switch (sniff(bytes)) {
    case FileFormat::Exr:
        return readExr(name, bytes, limits);
    case FileFormat::Rgbe:
        return readRadiance(name, bytes, limits);
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

} // namespace photopic
