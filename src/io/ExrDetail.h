#pragma once
// Internal to the io library: the pieces of ExrImage.cpp and AtomicFile.cpp that ExrFrame.cpp,
// ExrFrameWrite.cpp and DisplayImageIO.cpp share (the checked reading of an OpenEXR file from memory, colour
// reading with extra layers in the same pass, the check of an image about to be written, and the atomic
// writer). Not part of the public API.

#include "core/Image.h"
#include "io/ImageIO.h"

#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <glm/mat3x3.hpp>

#include <cstring>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace photopic::detail {

/// The whole file, checked before OpenEXR parses it: the magic number, every header attribute's declared size
/// against the bytes left, and the data window against `limits` and against the bytes that could hold it
/// (OpenEXR allocates by what the header declares). Throws IoError naming `path`. Into `bytes`, whose
/// capacity is kept: a sequence's reader reuses one buffer.
void readCheckedExrBytes(const std::filesystem::path& path, std::vector<unsigned char>& bytes,
                         const ImageReadLimits& limits = {});
/// readCheckedExrBytes's checks on bytes already in memory (`path` only names them in errors).
void checkExrBytes(const std::filesystem::path& path, std::span<const unsigned char> bytes,
                   const ImageReadLimits& limits = {});

/// Whether the file's version field says it has several parts (flag 0x1000).
[[nodiscard]] inline bool isMultiPartExr(std::span<const unsigned char> bytes) {
    return bytes.size() >= 8 && (bytes[5] & 0x10) != 0;
}

/// OpenEXR's input stream over bytes in memory; reads past the end throw like a short file does.
class MemoryIStream : public Imf::IStream {
public:
    MemoryIStream(const std::filesystem::path& path, std::span<const unsigned char> bytes)
        : Imf::IStream(path.c_str())
        , mBytes(bytes) {}

    bool read(char c[], int n) override {
        if (n < 0 || std::size_t(n) > mBytes.size() - mPos)
            throw std::runtime_error("unexpected end of file");
        std::memcpy(c, mBytes.data() + mPos, std::size_t(n));
        mPos += std::size_t(n);
        return mPos < mBytes.size();
    }
    uint64_t tellg() override { return mPos; }
    void seekg(uint64_t pos) override {
        if (pos > mBytes.size())
            throw std::runtime_error("seek past the end of file");
        mPos = std::size_t(pos);
    }
    void clear() override {}

private:
    std::span<const unsigned char> mBytes;
    std::size_t mPos = 0;
};

/// The channels colour is read from: R, G, B and A, or Y and A (luminance), under any names; an empty alpha
/// name means none (alpha 1). The standard names by default, where a file of Y, RY and BY is read as
/// luminance/chroma.
struct ExrColorChannels {
    std::string r = "R";
    std::string g = "G";
    std::string b = "B";
    std::string a = "A";
    std::string y = "Y";
    bool luminance = false; ///< Y (and A) only: r, g and b are not read
    /// The standard names, the file's own choice of RGB, Y or luminance/chroma.
    [[nodiscard]] bool standard() const { return r == "R" && g == "G" && b == "B" && a == "A" && !luminance; }
    /// From a mapping's colour names: 1 or 2 (Y[, A]) or 3 or 4 (R, G, B[, A]).
    [[nodiscard]] static ExrColorChannels of(const std::vector<std::string>& names);
};

/// Called once the data window is known (width x height pixels, checked) to add the caller's slices to the
/// frame buffer the colour is read through.
using ExrExtraSlices =
    std::function<void(Imf::FrameBuffer& frameBuffer, const Imath::Box2i& dataWindow, int width, int height)>;

/// The matrix taking RGB in the primaries and white of the header's `chromaticities` attribute to linear
/// Rec.709 with a D65 white (out = M * rgb; a Bradford adaptation when the whites differ), or nullopt when
/// the attribute is absent or names Rec.709/D65 already (each xy within 1e-3). ExrColorSpace.cpp.
[[nodiscard]] std::optional<glm::mat3> exrToRec709(const Imf::Header& header);

/// Converts `image`'s RGB (alpha untouched) from the header's chromaticities to linear Rec.709 / D65 in
/// place, and logs once per set of primaries (info, naming `path`); does nothing for Rec.709 / D65.
void convertExrToRec709(const std::filesystem::path& path, const Imf::Header& header, ImageF& image);

/// Reads the pixels of a single-part scanline file with ZIP or ZIPS compression into `frameBuffer`, as
/// Imf::InputFile::readPixels does for the whole data window (the same values to the bit: absent channels
/// take the slice's fill value), with the inflate done by libdeflate on OpenEXR's global thread pool
/// (ExrZip.cpp). Returns false when the file or the frame buffer is outside what it decodes (another
/// compression, tiled or multi-part, subsampled or UINT channels, slices that are neither FLOAT nor HALF, a
/// HALF slice of a FLOAT channel) or when the data does not decode; the caller then checks the chunks
/// (checkExrChunks) and reads through Imf::InputFile. A HALF slice of a HALF channel takes its bits as
/// stored.
[[nodiscard]] bool readZipScanlines(std::span<const unsigned char> bytes, const Imf::Header& header,
                                    const Imf::FrameBuffer& frameBuffer);

/// Throws IoError naming `path` unless every chunk Imf::InputFile would read from part `part` (every
/// scanline chunk, or every tile of the full-resolution level) has a readable leader within the file and
/// holds all the bytes its lines need: stored chunks their full size, RLE chunks a run sequence of that
/// length, ZIP/ZIPS chunks a stream inflating to exactly that length (ExrChunks.cpp). OpenEXR 3.1's reader
/// fills the rest of a short chunk's lines from its buffers' earlier contents, so a corrupt file would give
/// pixels of whatever the process held there before. PIZ, PXR24, B44 and DWA decoders check their output's
/// size themselves. Deep parts are left to Imf::InputFile, which refuses them.
void checkExrChunks(const std::filesystem::path& path, std::span<const unsigned char> bytes, int part = 0);

/// The colour of an OpenEXR file open over `bytes`, as readImage returns it (in linear Rec.709: other
/// chromaticities are converted), into `image` (its storage kept
/// when large enough), plus whatever `extra` adds, read in the same pass. Throws IoError naming `path`;
/// OpenEXR's exceptions pass through (callers wrap them).
void readExrColor(const std::filesystem::path& path, std::span<const unsigned char> bytes,
                  Imf::InputFile& file, ImageF& image, const ExrExtraSlices& extra = {},
                  const ImageReadLimits& limits = {}, const ExrColorChannels& names = {});

/// Whether the header's colour is halves as stored, to the bit, with nothing to convert: R, G, B (or Y
/// alone, not luminance/chroma) and A, those present all HALF, in Rec.709 primaries (readExrColor converts
/// others in float).
[[nodiscard]] bool exrColorIsHalves(const Imf::Header& header, const ExrColorChannels& names = {});

/// readExrColor for a file whose colour is halves (exrColorIsHalves): the halves as stored, into `image`
/// (its storage kept when large enough; A is 1.0 where absent, Y copied to R, G and B as readExrColor does).
/// The same values as readExrColor's, in half the memory. Throws std::invalid_argument for any other file,
/// IoError and OpenEXR's exceptions as readExrColor does.
void readExrColorHalves(const std::filesystem::path& path, std::span<const unsigned char> bytes,
                        Imf::InputFile& file, ImageH& image, const ExrExtraSlices& extra = {},
                        const ImageReadLimits& limits = {}, const ExrColorChannels& names = {});

/// Throws IoError naming `path` unless `image` (ImageF, Image8 or Image16) can be written: not empty, its
/// samples matching its size, within kDefaultMaxPixels.
template <typename Image>
void requirePixels(const std::filesystem::path& path, const Image& image) {
    if (image.empty())
        throw IoError(path, "cannot write an empty image (" + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + ")");
    const std::size_t expected = std::size_t(image.width) * std::size_t(image.height) * 4;
    if (image.rgba.size() != expected)
        throw IoError(path, "image holds " + std::to_string(image.rgba.size()) + " values, expected " +
                                std::to_string(expected) + " for " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + " RGBA");
    if (std::int64_t(image.width) * image.height > kDefaultMaxPixels)
        throw IoError(path, "image is too large to write");
}

/// Writes `bytes` to a temporary in the destination folder, fsyncs it and renames it over `path`.
void writeAtomically(const std::filesystem::path& path, std::span<const unsigned char> bytes);

} // namespace photopic::detail
