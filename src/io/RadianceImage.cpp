// Radiance RGBE (.hdr, .pic), decoded here rather than by stb_image: stbi_loadf loops forever on a truncated RLE
// scanline (past the end its reader yields zero bytes, and a zero-length literal run makes no progress), and it
// cannot report truncation. Format: Greg Ward, "Real Pixels", Graphics Gems II (1991), and Radiance's color.c.
#include "io/ImageIoDetail.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>
#include <system_error>

namespace photopic::detail {

namespace fs = std::filesystem;

namespace {

class RgbeReader {
public:
    RgbeReader(const fs::path& path, std::span<const unsigned char> bytes, const ImageReadLimits& limits)
        : mPath(path)
        , mBytes(bytes)
        , mLimits(limits) {}

    ImageF read() {
        readHeader();
        checkBytesHold(mPath, mWidth, mHeight, std::uint64_t(mHeight) * minimumScanlineBytes(), left(),
                       "Radiance");
        ImageF image(mWidth, mHeight, 1.0f);
        std::vector<unsigned char> scanline(std::size_t(mWidth) * 4);
        for (int y = 0; y < mHeight; ++y) {
            readScanline(scanline, y);
            float* out = image.at(0, y);
            for (int x = 0; x < mWidth; ++x, out += 4) {
                const unsigned char* rgbe = scanline.data() + std::size_t(x) * 4;
                if (rgbe[3] == 0) {
                    out[0] = out[1] = out[2] = 0.0f;
                    continue;
                }
                // As Radiance's colr_color: a mantissa is its bin's lower edge, so decode at the centre.
                const float scale = std::ldexp(1.0f, int(rgbe[3]) - (128 + 8));
                for (int c = 0; c < 3; ++c)
                    out[c] = (float(rgbe[c]) + 0.5f) * scale;
            }
        }
        return image;
    }

private:
    std::string_view nextLine() {
        const auto begin = mBytes.begin() + std::ptrdiff_t(mPos);
        const auto end = std::find(begin, mBytes.end(), '\n');
        if (end == mBytes.end())
            throw IoError(mPath, "Radiance header is truncated");
        mPos = std::size_t(end - mBytes.begin()) + 1;
        return {reinterpret_cast<const char*>(&*begin), std::size_t(end - begin)};
    }

    void readHeader() {
        nextLine(); // "#?RADIANCE": checked by sniff()
        for (std::string_view line = nextLine(); !line.empty(); line = nextLine()) {
            constexpr std::string_view kFormat = "FORMAT=";
            if (line.starts_with(kFormat) && line.substr(kFormat.size()) != "32-bit_rle_rgbe")
                throw IoError(mPath, "unsupported Radiance pixel format \"" +
                                         std::string(line.substr(kFormat.size())) +
                                         "\" (only 32-bit_rle_rgbe)");
        }
        // Resolution string; only the standard orientation (rows top to bottom, columns left to right).
        const std::string_view line = nextLine();
        int height = 0;
        int width = 0;
        const char* p = line.data();
        const char* end = line.data() + line.size();
        bool ok = line.starts_with("-Y ");
        if (ok) {
            const auto [afterHeight, heightError] = std::from_chars(p + 3, end, height);
            ok = heightError == std::errc() &&
                 std::string_view(afterHeight, std::size_t(end - afterHeight)).starts_with(" +X ");
            if (ok) {
                const auto [afterWidth, widthError] = std::from_chars(afterHeight + 4, end, width);
                ok = widthError == std::errc() && afterWidth == end;
            }
        }
        if (!ok)
            throw IoError(mPath, "unsupported Radiance resolution line \"" + std::string(line) +
                                     "\" (expected \"-Y <height> +X <width>\")");
        checkSize(mPath, width, height, mLimits);
        mWidth = width;
        mHeight = height;
    }

    [[noreturn]] void truncated(int y) const {
        throw IoError(mPath, "Radiance file is truncated in scanline " + std::to_string(y) + " of " +
                                 std::to_string(mHeight));
    }

    [[noreturn]] void corrupt(int y) const {
        throw IoError(mPath,
                      "Radiance file is corrupt: bad run-length data in scanline " + std::to_string(y));
    }

    std::size_t left() const { return mBytes.size() - mPos; }

    /// The fewest bytes one scanline can take: flat, 4 a pixel; run-length coded, a 4-byte marker and for
    /// each of the 4 components one 2-byte run per 127 pixels.
    std::uint64_t minimumScanlineBytes() const {
        const std::uint64_t flat = std::uint64_t(mWidth) * 4;
        if (mWidth < 8 || mWidth >= 32768)
            return flat;
        return std::min(flat, 4 + 4 * 2 * ((std::uint64_t(mWidth) + 126) / 127));
    }

    /// One scanline as interleaved RGBE bytes. A new-style RLE scanline opens with 2, 2 and a 15-bit width
    /// and then holds each component's runs in turn; anything else is flat RGBE pixels.
    void readScanline(std::vector<unsigned char>& scanline, int y) {
        const unsigned char* p = mBytes.data() + mPos;
        const bool rle =
            mWidth >= 8 && mWidth < 32768 && left() >= 4 && p[0] == 2 && p[1] == 2 && (p[2] & 0x80) == 0;
        if (!rle) {
            if (left() < scanline.size())
                truncated(y);
            std::copy_n(p, scanline.size(), scanline.begin());
            mPos += scanline.size();
            return;
        }
        if ((int(p[2]) << 8 | int(p[3])) != mWidth)
            corrupt(y);
        mPos += 4;
        for (std::size_t c = 0; c < 4; ++c) {
            for (int x = 0; x < mWidth;) {
                if (left() < 2)
                    truncated(y);
                int count = mBytes[mPos++];
                if (count > 128) { // a run of one value
                    count -= 128;
                    if (count > mWidth - x)
                        corrupt(y);
                    const unsigned char value = mBytes[mPos++];
                    for (int i = 0; i < count; ++i, ++x)
                        scanline[std::size_t(x) * 4 + c] = value;
                } else { // `count` literal values
                    if (count == 0 || count > mWidth - x)
                        corrupt(y);
                    if (left() < std::size_t(count))
                        truncated(y);
                    for (int i = 0; i < count; ++i, ++x)
                        scanline[std::size_t(x) * 4 + c] = mBytes[mPos++];
                }
            }
        }
    }

    const fs::path& mPath;
    std::span<const unsigned char> mBytes;
    ImageReadLimits mLimits;
    std::size_t mPos = 0;
    int mWidth = 0;
    int mHeight = 0;
};

} // namespace

ImageF readRadiance(const fs::path& path, std::span<const unsigned char> bytes, const ImageReadLimits& limits) {
    return RgbeReader(path, bytes, limits).read();
}

} // namespace photopic::detail
