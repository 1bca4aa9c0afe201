// The check that every chunk of an OpenEXR file in memory holds the bytes its lines need (checkExrChunks,
// declared in ExrDetail.h), through OpenEXR's core library: OpenEXR 3.1's reader would fill the lines of a
// short chunk only in part. Stored chunks must hold their lines' length, RLE chunks decode to exactly that
// length, ZIP/ZIPS chunks inflate (libdeflate) to exactly that length.
#include "io/ExrDetail.h"

#include "io/ExrMemory.h"

#include <libdeflate.h>
#include <openexr.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace photopic::detail {

namespace {

/// The bytes a run-length coded chunk decodes to (OpenEXR's RLE: a signed count byte; -n: n bytes follow as
/// they are; n >= 0: the next byte n + 1 times), or nullopt when a run is cut off by the chunk's end.
std::optional<std::uint64_t> rleDecodedSize(std::span<const unsigned char> packed) {
    std::uint64_t size = 0;
    std::size_t pos = 0;
    while (pos < packed.size()) {
        const int count = static_cast<signed char>(packed[pos++]);
        const std::size_t consumed = count < 0 ? std::size_t(-count) : 1;
        if (consumed > packed.size() - pos)
            return std::nullopt;
        pos += consumed;
        size += count < 0 ? std::uint64_t(-count) : std::uint64_t(count) + 1;
    }
    return size;
}

/// What is wrong with a chunk that OpenEXR's reader would fill its lines from only in part, or "".
std::string chunkProblem(exr_compression_t compression, const exr_chunk_info_t& chunk,
                         std::span<const unsigned char> file, libdeflate_decompressor* inflater,
                         std::vector<std::uint8_t>& scratch) {
    const std::uint64_t packed = chunk.packed_size;
    const std::uint64_t unpacked = chunk.unpacked_size;
    if (chunk.data_offset > file.size() || packed > file.size() - chunk.data_offset)
        return "runs past the end of the file";
    if (packed >= unpacked)
        return ""; // stored as it is, all of it there
    const std::span<const unsigned char> data = file.subspan(chunk.data_offset, packed);
    const auto shortBy = [&](const std::string& what) {
        return what + " " + std::to_string(unpacked) + " bytes its lines need";
    };
    switch (compression) {
    case EXR_COMPRESSION_NONE:
        return shortBy("holds " + std::to_string(packed) + " of the");
    case EXR_COMPRESSION_RLE: {
        const std::optional<std::uint64_t> size = rleDecodedSize(data);
        if (size != unpacked)
            return shortBy(size ? "decodes to " + std::to_string(*size) + " of the"
                                : "cuts off a run of the");
        return "";
    }
    case EXR_COMPRESSION_ZIPS:
    case EXR_COMPRESSION_ZIP:
        scratch.resize(unpacked);
        if (inflater == nullptr ||
            libdeflate_zlib_decompress(inflater, data.data(), data.size(), scratch.data(), unpacked,
                                       nullptr) != LIBDEFLATE_SUCCESS)
            return shortBy("does not inflate to the");
        return "";
    default:
        return ""; // the other codecs check their own output's size as they decode
    }
}

/// One part's chunks checked in turn; the first short or unreadable one throws IoError naming the file.
class ChunkChecker {
public:
    ChunkChecker(const std::filesystem::path& path, std::span<const unsigned char> bytes, int part)
        : mPath(path)
        , mBytes(bytes)
        , mPart(part)
        , mSource{bytes, {}}
        , mInflater(libdeflate_alloc_decompressor(), &libdeflate_free_decompressor) {}

    /// Opens the file; false for deep data, which Imf::InputFile refuses itself.
    bool start() {
        if (!startMemoryRead(mContext, mSource, &keepMessage))
            corrupt("the chunk table cannot be read");
        exr_attr_box2i_t window{};
        if (exr_get_storage(mContext.handle, mPart, &mStorage) != EXR_ERR_SUCCESS ||
            exr_get_compression(mContext.handle, mPart, &mCompression) != EXR_ERR_SUCCESS ||
            exr_get_data_window(mContext.handle, mPart, &window) != EXR_ERR_SUCCESS)
            corrupt(mPart == 0 ? std::string("the first part's layout cannot be read")
                               : "the layout of part " + std::to_string(mPart) + " cannot be read");
        mMinY = window.min.y;
        mMaxY = window.max.y;
        return mStorage == EXR_STORAGE_SCANLINE || mStorage == EXR_STORAGE_TILED;
    }

    void checkAll() {
        if (mStorage == EXR_STORAGE_SCANLINE)
            checkScanlines();
        else
            checkTiles();
    }

private:
    [[noreturn]] void corrupt(const std::string& where) const {
        throw IoError(mPath, "OpenEXR pixel data is corrupt: " + where +
                                 (mSource.error.empty() ? std::string() : ": " + mSource.error));
    }

    void check(exr_result_t read, const exr_chunk_info_t& chunk, const std::string& where) {
        if (read != EXR_ERR_SUCCESS)
            corrupt(where);
        const std::string problem = chunkProblem(mCompression, chunk, mBytes, mInflater.get(), mScratch);
        if (!problem.empty()) {
            mSource.error.clear();
            corrupt(where + " " + problem);
        }
    }

    void checkScanlines() {
        int32_t linesPerChunk = 0;
        if (exr_get_scanlines_per_chunk(mContext.handle, mPart, &linesPerChunk) != EXR_ERR_SUCCESS ||
            linesPerChunk < 1)
            corrupt("the lines per chunk cannot be read");
        for (std::int64_t y = mMinY; y <= mMaxY; y += linesPerChunk) {
            exr_chunk_info_t chunk{};
            check(exr_read_scanline_chunk_info(mContext.handle, mPart, int(y), &chunk), chunk,
                  "the chunk of line " + std::to_string(y));
        }
    }

    /// The full-resolution level, the one Imf::InputFile reads.
    void checkTiles() {
        int32_t tileWidth = 0;
        int32_t tileHeight = 0;
        int32_t levelWidth = 0;
        int32_t levelHeight = 0;
        if (exr_get_tile_sizes(mContext.handle, mPart, 0, 0, &tileWidth, &tileHeight) != EXR_ERR_SUCCESS ||
            exr_get_level_sizes(mContext.handle, mPart, 0, 0, &levelWidth, &levelHeight) != EXR_ERR_SUCCESS ||
            tileWidth < 1 || tileHeight < 1 || levelWidth < 1 || levelHeight < 1)
            corrupt("the tile layout cannot be read");
        const int tilesX = int((std::int64_t(levelWidth) + tileWidth - 1) / tileWidth);
        const int tilesY = int((std::int64_t(levelHeight) + tileHeight - 1) / tileHeight);
        for (int ty = 0; ty < tilesY; ++ty) {
            for (int tx = 0; tx < tilesX; ++tx) {
                exr_chunk_info_t chunk{};
                check(exr_read_tile_chunk_info(mContext.handle, mPart, tx, ty, 0, 0, &chunk), chunk,
                      "tile (" + std::to_string(tx) + ", " + std::to_string(ty) + ")");
            }
        }
    }

    const std::filesystem::path& mPath;
    std::span<const unsigned char> mBytes;
    int mPart;
    MemorySource mSource;
    ExrReadContext mContext;
    exr_storage_t mStorage{};
    exr_compression_t mCompression{};
    std::int64_t mMinY = 0;
    std::int64_t mMaxY = 0;
    std::unique_ptr<libdeflate_decompressor, void (*)(libdeflate_decompressor*)> mInflater;
    std::vector<std::uint8_t> mScratch;
};

} // namespace

void checkExrChunks(const std::filesystem::path& path, std::span<const unsigned char> bytes, int part) {
    ChunkChecker checker(path, bytes, part);
    if (checker.start())
        checker.checkAll();
}

} // namespace photopic::detail
