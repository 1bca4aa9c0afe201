// Entry points for the image readers: OpenEXR (colour alone, and frames with their layers and camera),
// Radiance .hdr and PNG, from bytes in memory. A PNG that photopic refuses is also given to libpng itself:
// a file libpng reads must be read.

#include "FuzzTargets.h"

#include "core/HalfFloat.h"
#include "io/ExrFrame.h"
#include "io/ImageIO.h"

#include <glm/gtc/matrix_transform.hpp>
#include <png.h>
#include <zlib.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace photopic::fuzz {

namespace {

// Small enough that a fuzzed header cannot make one input take seconds, large enough for every real path
// (tiling, RLE scanlines, interlacing) to be reached.
constexpr ImageReadLimits kLimits{.maxPixels = 1 << 20};

[[noreturn]] void broken(const std::string& promise) {
    std::fprintf(stderr, "fuzz target: promise broken: %s\n", promise.c_str());
    std::abort();
}

template <typename Image>
void checkShape(const Image& image, const ImageReadLimits& limits = kLimits) {
    if (image.empty() || image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4 ||
        std::int64_t(image.width) * image.height > limits.maxPixels) {
        broken("decoded image has the wrong shape");
    }
}

/// decodeImage: nothing when it read the image, else its IoError's message.
std::optional<std::string> decode(const std::uint8_t* data, std::size_t size, const char* name) {
    try {
        checkShape(decodeImage({data, size}, name, kLimits));
    } catch (const IoError& e) {
        return e.what();
    }
    return std::nullopt;
}

// ---------------------------------------------------------------------------------------------------------------
// PNG against libpng

/// The bytes as libpng is to judge them. A fuzzing build of photopic's reader takes chunks whatever their
/// CRC (a fuzzer seldom makes a right one), so there libpng gets a copy with every CRC recomputed and judges
/// the same content; elsewhere both check the CRCs as stored.
std::vector<unsigned char> bytesForLibpng(std::span<const unsigned char> bytes) {
    std::vector<unsigned char> copy(bytes.begin(), bytes.end());
#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
    // After the 8-byte signature, each chunk: length (4, big-endian), type (4), data, CRC of type and data.
    std::size_t pos = 8;
    while (copy.size() >= pos + 12) {
        const std::size_t length = std::size_t(copy[pos]) << 24 | std::size_t(copy[pos + 1]) << 16 |
                                   std::size_t(copy[pos + 2]) << 8 | std::size_t(copy[pos + 3]);
        if (length > copy.size() - pos - 12)
            break;
        const uLong crc = crc32(0, copy.data() + pos + 4, uInt(length + 4));
        unsigned char* out = copy.data() + pos + 8 + length;
        for (int i = 0; i < 4; ++i)
            out[i] = static_cast<unsigned char>(crc >> (24 - 8 * i));
        pos += length + 12;
    }
#endif
    return copy;
}

/// libpng's simplified API decodes the file to RGBA; nullopt where the image is over kLimits' pixels (which
/// photopic refuses by design), so not compared.
std::optional<bool> libpngDecodes(std::span<const unsigned char> bytes) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size())) {
        png_image_free(&image);
        return false;
    }
    // The pixel limit bounds the buffer too: 4 bytes a pixel, 4 MiB at most.
    if (std::int64_t(image.width) * std::int64_t(image.height) > kLimits.maxPixels) {
        png_image_free(&image);
        return std::nullopt;
    }
    image.format = PNG_FORMAT_RGBA;
    std::vector<png_byte> pixels(std::size_t(image.width) * image.height * 4);
    const bool decoded = png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr) != 0;
    png_image_free(&image);
    return decoded;
}

struct LibpngSource {
    std::span<const unsigned char> bytes;
    std::size_t pos = 0;
};

void libpngRead(png_structp png, png_bytep out, png_size_t count) {
    auto* source = static_cast<LibpngSource*>(png_get_io_ptr(png));
    if (count > source->bytes.size() - source->pos)
        png_error(png, "read past the end");
    std::memcpy(out, source->bytes.data() + source->pos, count);
    source->pos += count;
}

[[noreturn]] void libpngError(png_structp png, png_const_charp) {
    png_longjmp(png, 1);
}

void libpngWarning(png_structp, png_const_charp) {}

/// Under setjmp, so no object with a destructor lives here: `row` is the caller's.
bool libpngReadRowsAndEnd(png_structp png, png_infop info, LibpngSource& source, std::vector<png_byte>& row) {
    if (setjmp(png_jmpbuf(png)))
        return false;
    png_set_read_fn(png, &source, libpngRead);
    png_read_info(png, info);
    const int passes = png_set_interlace_handling(png);
    png_read_update_info(png, info);
    row.resize(png_get_rowbytes(png, info));
    for (int pass = 0; pass < passes; ++pass) {
        for (png_uint_32 y = 0; y < png_get_image_height(png, info); ++y)
            png_read_row(png, row.data(), nullptr);
    }
    png_read_end(png, nullptr);
    return true;
}

/// libpng's sequential reader takes the file through IEND, as photopic's reader does (a file cut after the
/// pixel data is truncated); the simplified API stops after the last row and cannot tell. Only called once
/// the simplified API decoded the file within the pixel limit, so the rows are bounded.
bool libpngReadsToEnd(std::span<const unsigned char> bytes) {
    LibpngSource source{.bytes = bytes, .pos = 0};
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, libpngError, libpngWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    std::vector<png_byte> row;
    const bool read = png && info && libpngReadRowsAndEnd(png, info, source, row);
    png_destroy_read_struct(&png, &info, nullptr);
    return read;
}

/// Whether libpng accepts the PNG as photopic's reader promises to: decoded, and read through IEND.
bool libpngAccepts(std::span<const unsigned char> original) {
    const std::vector<unsigned char> bytes = bytesForLibpng(original);
    return libpngDecodes(bytes).value_or(false) && libpngReadsToEnd(bytes);
}

// ---------------------------------------------------------------------------------------------------------------
// EXR frames

constexpr const char* kFrameName = "fuzz.exr";
// A frame with its layers is read five times an input (alone, and into the storage each of two frames
// before it left, by a reader of floats and by one that keeps half colour as halves): a smaller bound than
// kLimits keeps that fast, still above the largest chunk (256 lines) and the tiles the header check lets
// through.
constexpr ImageReadLimits kFrameLimits{.maxPixels = 1 << 16};

/// Bit for bit, NaNs included: the reader must give the same values whatever its storage held before.
template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}
template <typename T>
bool sameBits(const std::optional<T>& a, const std::optional<T>& b) {
    return a.has_value() == b.has_value() && (!a || std::memcmp(&*a, &*b, sizeof(T)) == 0);
}

bool sameCamera(const ExrCameraAttributes& a, const ExrCameraAttributes& b) {
    return sameBits(a.worldToCamera, b.worldToCamera) && sameBits(a.worldToNDC, b.worldToNDC) &&
           sameBits(a.focus, b.focus) && sameBits(a.aperture, b.aperture) && sameBits(a.expTime, b.expTime) &&
           sameBits(a.isoSpeed, b.isoSpeed) && sameBits(a.pinholeFocalLength, b.pinholeFocalLength) &&
           sameBits(a.sensorOverallDimensions, b.sensorOverallDimensions) &&
           sameBits(a.shutterAngle, b.shutterAngle) && sameBits(a.jitter, b.jitter) &&
           sameBits(a.nearClip, b.nearClip) && sameBits(a.farClip, b.farClip) &&
           sameBits(a.sunDirection, b.sunDirection);
}

bool sameFrame(const ExrFrame& a, const ExrFrame& b) {
    return a.color.width == b.color.width && a.color.height == b.color.height &&
           sameBits(a.color.rgba, b.color.rgba) && a.colorHalves.width == b.colorHalves.width &&
           a.colorHalves.height == b.colorHalves.height && sameBits(a.colorHalves.rgba, b.colorHalves.rgba) &&
           sameBits(a.depth, b.depth) && sameBits(a.normals, b.normals) && sameBits(a.motion, b.motion) &&
           sameCamera(a.camera, b.camera) && a.channels == b.channels && a.attributes == b.attributes &&
           a.displaySize == b.displaySize && a.dataOrigin == b.dataOrigin && a.halfColor == b.halfColor;
}

/// The frames a sequence reader's storage holds before the fuzzed one: a larger one with every layer and
/// camera attribute, and a smaller one with colour alone, each as bytes and as read on its own.
struct Prime {
    std::string bytes;
    ExrFrame frame;
};

ExrFrame primeFrame(int width, int height, bool layers) {
    ExrFrame frame;
    frame.color = ImageF(width, height);
    const std::size_t pixels = frame.color.pixelCount();
    for (std::size_t i = 0; i < frame.color.rgba.size(); ++i)
        frame.color.rgba[i] = 0.5f + float(i % 97);
    if (!layers)
        return frame;
    frame.depth.assign(pixels, 7.25f);
    frame.normals.assign(pixels * 3, 0.5f);
    frame.motion.assign(pixels * 2, -3.5f);
    Camera camera;
    camera.view = glm::lookAt(glm::vec3(1.0f, 2.0f, 3.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    camera.projection = perspectiveProjection(camera.verticalFov, float(width) / float(height), 0.25f, 80.0f);
    camera.nearPlane = 0.25f;
    camera.farPlane = 80.0f;
    frame.camera = exrFromCamera(camera, width, height);
    frame.camera.jitter = glm::vec2(0.25f, -0.125f);
    frame.camera.sunDirection = glm::vec3(0.0f, 1.0f, 0.0f);
    return frame;
}

const std::array<Prime, 2>& primes() {
    static const std::array<Prime, 2> primes = [] {
        std::array<Prime, 2> made;
        const ExrFrame written[] = {primeFrame(37, 23, true), primeFrame(3, 2, false)};
        for (std::size_t i = 0; i < made.size(); ++i) {
            made[i].bytes = encodeExrFrame(written[i], "prime.exr");
            made[i].frame = decodeExrFrame(
                {reinterpret_cast<const unsigned char*>(made[i].bytes.data()), made[i].bytes.size()},
                "prime.exr");
        }
        return made;
    }();
    return primes;
}

/// `frame` with a colour kept as halves widened to floats (exactly), as a reader of floats gives it.
ExrFrame widened(ExrFrame frame) {
    if (!frame.colorHalves.empty()) {
        frame.color = ImageF(frame.colorHalves.width, frame.colorHalves.height);
        halfToFloat(frame.colorHalves.rgba.data(), frame.color.rgba.data(), frame.color.rgba.size());
        frame.colorHalves = ImageH{};
    }
    return frame;
}

void readPrime(ExrFrameReader& reader, const Prime& prime, ExrFrame& storage) {
    reader.decode({reinterpret_cast<const unsigned char*>(prime.bytes.data()), prime.bytes.size()},
                  "prime.exr", storage, kFrameLimits);
    // A reader keeping halves keeps the primes' half colour so; widened, it is the floats read.
    if (!sameFrame(storage.colorHalves.empty() ? storage : widened(storage), prime.frame))
        broken("a frame read into storage an earlier read left differs from the same frame read on its own");
}

/// A camera from cameraFromExr or frameCamera (`make`): nothing, std::invalid_argument, or a camera that
/// invalidCameraReason accepts.
template <typename Make>
void checkCamera(const Make& make) {
    std::optional<Camera> camera;
    try {
        camera = make();
    } catch (const std::invalid_argument&) {
        return;
    }
    if (camera) {
        if (const char* reason = invalidCameraReason(*camera))
            broken(std::string("an invalid camera from the file's attributes: ") + reason);
    }
}

/// What the reader promises of a frame it returns, and what cameraFromExr promises of its attributes.
void checkFrame(const ExrFrame& frame) {
    checkShape(frame.color, kFrameLimits);
    const std::size_t pixels = frame.color.pixelCount();
    const auto layer = [&](const std::vector<float>& values, std::size_t components, const char* name) {
        if (!values.empty() && values.size() != pixels * components)
            broken(std::string(name) + " layer does not match the colour's size");
    };
    layer(frame.depth, 1, "depth");
    layer(frame.normals, 3, "normals");
    layer(frame.motion, 2, "motion");
    if (frame.displaySize.x < 1 || frame.displaySize.y < 1)
        broken("an empty display window");
    if (frame.camera.jitter &&
        !(std::isfinite(frame.camera.jitter->x) && std::isfinite(frame.camera.jitter->y)))
        broken("a non-finite jitter");
    // The camera for the frame's pixels (cropped to its data window), alone and with a prime's as the
    // previous frame's, and a prime's after this one.
    const Prime& prime = primes()[0];
    checkCamera([&] { return frameCamera(frame); });
    checkCamera([&] { return frameCamera(frame, &prime.frame.camera); });
    checkCamera([&] { return frameCamera(prime.frame, &frame.camera); });
}

/// The sequence reader on the fuzzed bytes into `storage` (left by an earlier read): the same outcome as a
/// read of floats on its own, and on an error an empty frame. A reader that keeps half colour as halves
/// (`keepsHalves`) keeps them only for a colour that is halves, and their floats are the read's.
void readInto(ExrFrameReader& reader, std::span<const unsigned char> bytes, ExrFrame& storage,
              const std::optional<ExrFrame>& alone, const std::string& aloneError, bool keepsHalves) {
    try {
        reader.decode(bytes, kFrameName, storage, kFrameLimits);
    } catch (const IoError& e) {
        if (alone)
            broken(std::string("a read into kept storage failed where a read on its own did not: ") +
                   e.what());
        if (aloneError != e.what())
            broken(std::string("a read into kept storage failed differently: ") + e.what());
        if (!sameFrame(storage, ExrFrame{}))
            broken("a failed read left the frame half filled");
        return;
    }
    if (!alone)
        broken("a read into kept storage succeeded where a read on its own failed: " + aloneError);
    if (!storage.colorHalves.empty() && (!keepsHalves || !storage.color.empty() || !storage.halfColor))
        broken("colour kept as halves by a reader of floats, beside floats, or for a colour not half");
    if (!sameFrame(keepsHalves ? widened(storage) : storage, *alone))
        broken("a read into kept storage differs from a read of floats on its own");
}

} // namespace

void exrImage(const std::uint8_t* data, std::size_t size) {
    decode(data, size, "fuzz.exr");
}

void hdrImage(const std::uint8_t* data, std::size_t size) {
    decode(data, size, "fuzz.hdr");
}

void pngImage(const std::uint8_t* data, std::size_t size) {
    std::optional<std::string> refused = decode(data, size, "fuzz.png");
    if (refused)
        refused = "decodeImage: " + *refused;
    try {
        checkShape(decodePng8({data, size}, "fuzz.png", kLimits));
    } catch (const IoError& e) {
        refused = std::string("decodePng8: ") + e.what();
    }
    // libpng is asked only about a file photopic refused: it may be stricter, never more accepting.
    if (refused && libpngAccepts({data, size}))
        broken("libpng reads this PNG (within the pixel limit, through IEND) but photopic refuses it: " +
               *refused);
}

void exrFrame(const std::uint8_t* data, std::size_t size) {
    const std::span<const unsigned char> bytes(data, size);
    std::optional<ExrFrame> alone;
    std::string aloneError;
    try {
        alone = decodeExrFrame(bytes, kFrameName, kFrameLimits);
    } catch (const IoError& e) {
        aloneError = e.what();
    }
    if (alone)
        checkFrame(*alone);
    // A sequence: each prime, then the fuzzed frame into the storage it left; then a prime again into what
    // the fuzzed frame (or its error) left.
    ExrFrameReader reader;
    ExrFrame storage;
    for (const Prime& prime : primes()) {
        readPrime(reader, prime, storage);
        readInto(reader, bytes, storage, alone, aloneError, false);
    }
    readPrime(reader, primes()[0], storage);
    // The same with a reader keeping half colour as halves (the primes' colour is half).
    ExrFrameReader halves(ExrFrameReader::Color::HalvesWhenStored);
    ExrFrame kept;
    for (const Prime& prime : primes()) {
        readPrime(halves, prime, kept);
        if (kept.colorHalves.empty())
            broken("a reader keeping halves gave a half-colour prime as floats");
        readInto(halves, bytes, kept, alone, aloneError, true);
    }
}

} // namespace photopic::fuzz
