#pragma once
// Image files in and out: OpenEXR, Radiance RGBE (.hdr) and PNG. Readers dispatch on the file's first bytes,
// not on its name; writers are atomic (a reader never sees a half-written file). Display images as 16-bit
// PNG, TIFF and JPEG: io/DisplayImageIO.h.

#include "core/Image.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace photopic {

/// A file could not be read or written. what() always names the file: `"<path>": <what is wrong>`.
class IoError : public std::runtime_error {
public:
    IoError(const std::filesystem::path& path, std::string_view problem);
};

/// Default bound on a decoded image: 16384 x 16384 = 2^28 pixels, 4 GiB as ImageF.
inline constexpr std::int64_t kDefaultMaxPixels = std::int64_t(1) << 28;

/// Bounds a reader checks against the file's declared size before it allocates anything.
struct ImageReadLimits {
    std::int64_t maxPixels = kDefaultMaxPixels; ///< pixels, >= 1; a bigger declared image is an IoError
};

/// Reads a linear RGBA float image; the format comes from the file's magic bytes.
/// - OpenEXR, scanline or tiled, any compression (DWAA/DWAB included), half/float/uint channels: R, G, B and
/// A of
///   the first part. Missing colour channels read 0 and a missing A reads 1; a luminance-only file (Y) is
///   copied to R, G and B, and luminance/chroma (Y, RY, BY) is converted to RGB. Returns the pixels of the
///   *data window*, its top-left corner at (0, 0); the display window is ignored. Values are kept as stored
///   (negative, huge, NaN), except that RGB whose `chromaticities` attribute names primaries or a white
///   other than Rec.709 / D65 is converted to linear Rec.709 (a Bradford adaptation when the white differs;
///   logged once per set of primaries).
/// - Radiance RGBE, "-Y <h> +X <w>" orientation, flat or RLE scanlines; linear values, EXPOSURE lines
/// ignored.
/// - PNG, 8 or 16 bit, grey/RGB/palette, with or without alpha: colour decoded by the exact sRGB EOTF, alpha
/// kept
///   linear, alpha 1 when absent. gAMA/iCCP chunks are ignored: a PNG is taken to be sRGB.
/// Throws IoError naming the path for a missing or unreadable file, an unrecognised format, a truncated or
/// corrupt file, an image with no pixels, an image over `limits.maxPixels`, or a declared size that the
/// file's bytes cannot hold (checked before the pixels are allocated, so a 40-byte file cannot ask for
/// gigabytes).
[[nodiscard]] ImageF readImage(const std::filesystem::path& path, const ImageReadLimits& limits = {});

/// Threads OpenEXR decodes (and encodes) a file's chunks on: 0 decodes on the calling thread (OpenEXR's own
/// default). The pool is process-wide; the pixels are the same whatever the count.
void setExrThreads(int threads);

/// readImage on bytes already in memory; `name` only names the source in errors. Any byte string gives an
/// image or an IoError (the fuzzers hold it to that).
[[nodiscard]] ImageF decodeImage(std::span<const unsigned char> bytes, const std::filesystem::path& name,
                                 const ImageReadLimits& limits = {});

/// Reads a PNG's stored 8-bit RGBA values with no colour decoding (alpha 255 when absent; a 16-bit file keeps
/// the high byte of each sample). For comparing written PNGs byte for byte.
[[nodiscard]] Image8 readPng8(const std::filesystem::path& path, const ImageReadLimits& limits = {});
/// readPng8 on bytes in memory; `name` only names the source in errors.
[[nodiscard]] Image8 decodePng8(std::span<const unsigned char> bytes, const std::filesystem::path& name,
                                const ImageReadLimits& limits = {});

/// The path that names standard output, as command-line tools spell it.
inline const std::filesystem::path kStdoutPath{"-"};

/// Whether `path` is standard output: "-", or a name of the file standard output is (/dev/stdout).
[[nodiscard]] bool namesStandardOutput(const std::filesystem::path& path);

/// Whether `path` is written as a stream rather than atomically: "-" (standard output), or an existing
/// device, pipe or socket, links followed (/dev/null, a named pipe), or standard output whatever it is.
[[nodiscard]] bool isStreamOutput(const std::filesystem::path& path);

/// Writes an 8-bit sRGB PNG, stored as RGB when every alpha is 255 (smaller) and as RGBA otherwise; readPng8
/// gives back the same RGBA bytes either way. Both writers are atomic when `path` is a regular file: the file
/// is written as `.<name>.tmp-<pid>-<n>` in the destination folder, flushed to disk, then renamed over
/// `path`. On any failure the temporary is removed, `path` is left as it was and IoError is thrown. The
/// destination folder must already exist; it is never created. A stream output (isStreamOutput) is written
/// straight through instead, and what reached it before a failure stays there.
void writePng(const std::filesystem::path& path, const Image8& image);

/// writePng for a sequence: the encoder's buffers (the filtered rows, the encoded stream) and its deflate
/// state are kept from one image to the next, so frames of one size allocate nothing after the first. The
/// same bytes as writePng. One thread at a time.
class PngWriter {
public:
    PngWriter();
    ~PngWriter();
    PngWriter(const PngWriter&) = delete;
    PngWriter& operator=(const PngWriter&) = delete;

    void write(const std::filesystem::path& path, const Image8& image);

    /// A buffer that is never cleared: only what the encoder writes is touched.
    struct EncodeBuffer {
        std::unique_ptr<unsigned char[]> bytes;
        std::size_t capacity = 0;
    };
    struct Deflater;

private:
    std::vector<unsigned char> mRows;
    EncodeBuffer mEncoded;
    std::unique_ptr<Deflater> mDeflater;
};

/// Writes a text file (CSV telemetry, JSON) atomically, like writePng.
void writeTextFile(const std::filesystem::path& path, std::string_view text);

/// Checks, without writing anything, that `path` can be an output file: a stream output (isStreamOutput), or
/// it names a file (not a folder, not an existing folder, not a symbolic link), its folder exists and is
/// writable. Throws IoError saying which of these fails. For
/// validating every output before a long run starts.
void requireWritableFile(const std::filesystem::path& path);

/// The fewest bytes a PNG's compressed rows can take: the rows as the file stores them (its IHDR's colour
/// type and bit depth, one filter byte a row; Adam7's passes have at least as many rows and bits), over
/// deflate's largest expansion, 1032:1. A file with fewer is truncated or lies about its size: a lower bound
/// to check before allocating the decoded image.
[[nodiscard]] std::uint64_t pngMinimumEncodedBytes(std::uint32_t width, std::uint32_t height, int colorType,
                                                   int bitDepth);

/// Called by AtomicFileWriter::commit (and so by every writer here) just before its finished file replaces
/// an existing file at `path`; never for a new file or a stream. For a program that must be able to put back
/// what a failed run replaced: the CLI moves the old file aside here and restores it if the run fails. May be
/// called from several threads at once; throwing IoError stops the commit (the temporary is removed and
/// `path` is left as it was). Process-wide; an empty function (the default) replaces files outright.
using BeforeReplace = std::function<void(const std::filesystem::path& path)>;
void setBeforeReplace(BeforeReplace hook);

/// A file written piece by piece and published atomically: the pieces go to a temporary beside `path` (named
/// like writePng's), commit() flushes it to disk and renames it over `path`; destroyed without commit(), it
/// removes the temporary and leaves `path` as it was. The constructor creates the temporary at once, so an
/// unwritable destination fails before any work. For outputs that grow with the run (telemetry CSV). A stream
/// output (isStreamOutput) is written straight through instead: commit() flushes it, and what was written
/// before a failure stays written.
class AtomicFileWriter {
public:
    explicit AtomicFileWriter(std::filesystem::path path);
    ~AtomicFileWriter();
    AtomicFileWriter(const AtomicFileWriter&) = delete;
    AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

    void write(std::string_view text); ///< throws IoError (the temporary is then removed)
    void commit();                     ///< throws IoError (the temporary is then removed)
    [[nodiscard]] const std::filesystem::path& path() const { return mPath; }
    /// Where the file is written until commit() (empty for a stream output): for a program that writes the
    /// file itself (ffmpeg), after which commit() flushes it to disk and renames it over path().
    [[nodiscard]] const std::filesystem::path& temporaryPath() const { return mTemporary; }

private:
    void fail(const std::string& problem);
    bool close(); ///< closes the file (flushes standard output), removes the temporary; false on an error
    std::filesystem::path mPath;
    std::filesystem::path mTemporary; ///< empty for a stream
    std::FILE* mFile = nullptr;
};

/// Writes a half-float RGBA OpenEXR, ZIP compressed (lossless for half data), data window = display window =
/// the image. Values are rounded to half; finite values beyond +-65504 are clamped to it rather than becoming
/// infinite. Atomic, like writePng.
void writeExr(const std::filesystem::path& path, const ImageF& image);

} // namespace photopic
