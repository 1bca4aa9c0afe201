// Entry points for the image readers: OpenEXR, Radiance .hdr and PNG, from bytes in memory.

#include "FuzzTargets.h"

#include "io/ImageIO.h"

#include <cstdio>
#include <cstdlib>

namespace photopic::fuzz {

namespace {

// Small enough that a fuzzed header cannot make one input take seconds, large enough for every real path
// (tiling, RLE scanlines, interlacing) to be reached.
constexpr ImageReadLimits kLimits{.maxPixels = 1 << 20};

template <typename Image>
void checkShape(const Image& image) {
    if (image.empty() || image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4 ||
        std::int64_t(image.width) * image.height > kLimits.maxPixels) {
        std::fprintf(stderr, "fuzz target: promise broken: decoded image has the wrong shape\n");
        std::abort();
    }
}

void decode(const std::uint8_t* data, std::size_t size, const char* name) {
    try {
        checkShape(decodeImage({data, size}, name, kLimits));
    } catch (const IoError&) {
    }
}

} // namespace

void exrImage(const std::uint8_t* data, std::size_t size) {
    decode(data, size, "fuzz.exr");
}

void hdrImage(const std::uint8_t* data, std::size_t size) {
    decode(data, size, "fuzz.hdr");
}

void pngImage(const std::uint8_t* data, std::size_t size) {
    decode(data, size, "fuzz.png");
    try {
        checkShape(decodePng8({data, size}, "fuzz.png", kLimits));
    } catch (const IoError&) {
    }
}

} // namespace photopic::fuzz
