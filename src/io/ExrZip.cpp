// OpenEXR's core library over a file in memory (ExrMemory.h): scanline ZIP / ZIPS pixel data decoded through
// it (chunk table, chunk reads and their checks; ExrChunks.cpp checks every chunk's size first) with the
// inflate step done by libdeflate instead of zlib, on OpenEXR's global thread pool. The unpacking into the
// frame buffer is done here too: OpenEXR 3.1's own routine for four half channels into interleaved floats at
// descending addresses (A, B, G, R into RGBA) writes them in file order, R's value where A belongs
// (ExrZipTest.RgbaMatchesOpenExrBitForBit fails with it). Half channels may also go to half slices, as stored
// (a colour kept in half the memory). zlib's inflate was the largest single cost of reading a ZIP-compressed
// sequence; libdeflate inflates the same stream several times faster.
//
// The ZIP codec (OpenEXR file layout, "ZIP compression"): a chunk's bytes are deflated in a zlib stream after
// two reversible steps, which are undone here after inflating: the bytes were split into the even-indexed
// ones followed by the odd-indexed ones, and then each byte replaced by its difference to the previous one
// plus 128 (modulo 256; the first byte kept). A chunk whose deflated size would not be smaller is stored raw.
#include "io/ExrDetail.h"

#include "core/HalfFloat.h"
#include "io/ExrMemory.h"

#include <IlmThreadPool.h>
#include <ImfChannelList.h>
#include <libdeflate.h>
#include <openexr.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <new>
#include <optional>
#include <span>
#include <vector>

namespace photopic::detail {

namespace {

// ------------------------------------------------------------------------------------------------ ZIP codec

/// Undoes the predictor in place: b[i] = b[i - 1] + b[i] - 128 (mod 256) for i >= 1, a running sum.
void undoPredictor(std::uint8_t* bytes, std::size_t size) {
    if (size == 0)
        return;
    std::size_t i = 1;
    std::uint8_t previous = bytes[0];
#if defined(__SSE2__)
    // Sixteen bytes at a time: subtract 128 from each, a prefix sum in four shifted adds, plus the last sum.
    const __m128i bias = _mm_set1_epi8(char(-128));
    for (; i + 16 <= size; i += 16) {
        __m128i d = _mm_add_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(bytes + i)), bias);
        d = _mm_add_epi8(d, _mm_slli_si128(d, 1));
        d = _mm_add_epi8(d, _mm_slli_si128(d, 2));
        d = _mm_add_epi8(d, _mm_slli_si128(d, 4));
        d = _mm_add_epi8(d, _mm_slli_si128(d, 8));
        d = _mm_add_epi8(d, _mm_set1_epi8(char(previous)));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(bytes + i), d);
        previous = std::uint8_t(_mm_extract_epi16(d, 7) >> 8);
    }
#endif
    for (; i < size; ++i) {
        previous = std::uint8_t(previous + bytes[i] - 128);
        bytes[i] = previous;
    }
}

/// out[2i] = in[i] and out[2i + 1] = in[(size + 1) / 2 + i]: the two halves woven back together.
void interleave(std::uint8_t* out, const std::uint8_t* in, std::size_t size) {
    const std::uint8_t* even = in;
    const std::uint8_t* odd = in + (size + 1) / 2;
    std::size_t o = 0;
#if defined(__SSE2__)
    for (; o + 32 <= size; o += 32) {
        const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(even));
        const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(odd));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out + o), _mm_unpacklo_epi8(a, b));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out + o + 16), _mm_unpackhi_epi8(a, b));
        even += 16;
        odd += 16;
    }
#endif
    for (; o < size; ++o)
        out[o] = (o % 2 == 0) ? *even++ : *odd++;
}

/// One decoding thread's state: its inflater and the inflated bytes before the two steps are undone.
struct ZipState {
    ZipState()
        : inflater(libdeflate_alloc_decompressor()) {}
    ZipState(const ZipState&) = delete;
    ZipState& operator=(const ZipState&) = delete;
    ~ZipState() { libdeflate_free_decompressor(inflater); }

    libdeflate_decompressor* inflater;
    std::vector<std::uint8_t> inflated;
    std::vector<float> floats; ///< a line's runs widened to float, four channels' worth
};

/// The pipeline's decompress step for ZIP and ZIPS chunks (decoding_user_data: the thread's ZipState).
exr_result_t inflateZipChunk(exr_decode_pipeline_t* decode) {
    const std::uint64_t packed = decode->chunk.packed_size;
    const std::uint64_t unpacked = decode->chunk.unpacked_size;
    if (packed == 0 || packed == unpacked)
        return EXR_ERR_SUCCESS; // stored raw: the pipeline already points the unpacked buffer at it
    auto* state = static_cast<ZipState*>(decode->decoding_user_data);
    if (state == nullptr || state->inflater == nullptr || decode->unpacked_buffer == nullptr ||
        decode->unpacked_alloc_size < unpacked)
        return EXR_ERR_OUT_OF_MEMORY;
    // Called from OpenEXR's C code on a pool thread: nothing may throw through it.
    try {
        state->inflated.resize(unpacked);
    } catch (const std::bad_alloc&) {
        return EXR_ERR_OUT_OF_MEMORY;
    }
    // With no length out-parameter libdeflate demands exactly `unpacked` bytes, as OpenEXR's own reader does.
    if (libdeflate_zlib_decompress(state->inflater, decode->packed_buffer, packed, state->inflated.data(),
                                   unpacked, nullptr) != LIBDEFLATE_SUCCESS)
        return EXR_ERR_CORRUPT_CHUNK;
    undoPredictor(state->inflated.data(), unpacked);
    interleave(static_cast<std::uint8_t*>(decode->unpacked_buffer), state->inflated.data(), unpacked);
    return EXR_ERR_SUCCESS;
}

/// A line's run of one channel as floats, in the thread's scratch: half runs widened, float runs copied (a
/// run may start at any byte offset).
const float* lineFloats(const exr_coding_channel_info_t& channel, const std::uint8_t* source,
                        float* scratch) noexcept {
    const std::size_t width = std::size_t(channel.width);
    if (channel.bytes_per_element == 4) {
        std::memcpy(scratch, source, width * sizeof(float));
        return scratch;
    }
    if (reinterpret_cast<std::uintptr_t>(source) % alignof(std::uint16_t) == 0) {
        halfToFloat(reinterpret_cast<const std::uint16_t*>(source), scratch, width);
        return scratch;
    }
    std::uint16_t halves[256];
    for (std::size_t x = 0; x < width; x += 256) {
        const std::size_t n = std::min<std::size_t>(256, width - x);
        std::memcpy(halves, source + 2 * x, n * 2);
        halfToFloat(halves, scratch + x, n);
    }
    return scratch;
}

/// The value each of four channels fills in a pixel of four values, when the four fill one pixel between them
/// (a renderer's A, B, G, R into RGBA), all four as floats (16-byte pixels) or all four as halves (8-byte
/// pixels): lane[c] for channel c, and the pixel at `base`. Else base is null.
struct FourLanes {
    std::uint8_t* base = nullptr;
    int lane[4] = {};
    bool halves = false;
};

FourLanes fourLanes(const exr_decode_pipeline_t& decode) noexcept {
    FourLanes four;
    if (decode.channel_count != 4)
        return four;
    const int element = decode.channels[0].user_bytes_per_element;
    if (element != 2 && element != 4)
        return four;
    std::uint8_t* base = nullptr;
    for (int c = 0; c < 4; ++c) {
        const exr_coding_channel_info_t& channel = decode.channels[c];
        if (channel.decode_to_ptr == nullptr || channel.user_bytes_per_element != element ||
            channel.user_pixel_stride != 4 * element ||
            channel.user_line_stride != decode.channels[0].user_line_stride)
            return four;
        if (base == nullptr || channel.decode_to_ptr < base)
            base = channel.decode_to_ptr;
    }
    unsigned lanesSeen = 0;
    for (int c = 0; c < 4; ++c) {
        const std::ptrdiff_t offset = decode.channels[c].decode_to_ptr - base;
        if (offset % element != 0 || offset > 3 * element || (lanesSeen & (1u << (offset / element))) != 0)
            return four;
        lanesSeen |= 1u << (offset / element);
        four.lane[c] = int(offset / element);
    }
    four.base = base;
    four.halves = element == 2;
    return four;
}

/// Interleaves four runs of `width` floats into RGBA pixels, run c into float lane[c] of each pixel.
void interleaveFour(const float* const runs[4], const int lane[4], std::uint8_t* out,
                    std::size_t width) noexcept {
    const float* byLane[4];
    for (int c = 0; c < 4; ++c)
        byLane[lane[c]] = runs[c];
    std::size_t x = 0;
#if defined(__SSE2__)
    const bool streaming = reinterpret_cast<std::uintptr_t>(out) % 16 == 0;
    for (; x + 4 <= width; x += 4) {
        __m128 r = _mm_loadu_ps(byLane[0] + x);
        __m128 g = _mm_loadu_ps(byLane[1] + x);
        __m128 b = _mm_loadu_ps(byLane[2] + x);
        __m128 a = _mm_loadu_ps(byLane[3] + x);
        _MM_TRANSPOSE4_PS(r, g, b, a);
        auto* pixel = reinterpret_cast<float*>(out + 16 * x);
        if (streaming) {
            _mm_stream_ps(pixel, r);
            _mm_stream_ps(pixel + 4, g);
            _mm_stream_ps(pixel + 8, b);
            _mm_stream_ps(pixel + 12, a);
        } else {
            _mm_storeu_ps(pixel, r);
            _mm_storeu_ps(pixel + 4, g);
            _mm_storeu_ps(pixel + 8, b);
            _mm_storeu_ps(pixel + 12, a);
        }
    }
#endif
    for (; x < width; ++x) {
        const float pixel[4] = {byLane[0][x], byLane[1][x], byLane[2][x], byLane[3][x]};
        std::memcpy(out + 16 * x, pixel, sizeof(pixel));
    }
}

/// Interleaves four runs of `width` halves (each at any byte offset) into 8-byte RGBA pixels, run c into
/// lane[c] of each pixel, the bits as they are.
void interleaveFourHalves(const std::uint8_t* const runs[4], const int lane[4], std::uint8_t* out,
                          std::size_t width) noexcept {
    const std::uint8_t* byLane[4];
    for (int c = 0; c < 4; ++c)
        byLane[lane[c]] = runs[c];
    std::size_t x = 0;
#if defined(__SSE2__)
    // Eight pixels at a time: (r, g) and (b, a) woven into pairs, then the pairs into pixels.
    for (; x + 8 <= width; x += 8) {
        const __m128i r = _mm_loadu_si128(reinterpret_cast<const __m128i*>(byLane[0] + 2 * x));
        const __m128i g = _mm_loadu_si128(reinterpret_cast<const __m128i*>(byLane[1] + 2 * x));
        const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(byLane[2] + 2 * x));
        const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(byLane[3] + 2 * x));
        const __m128i rgLow = _mm_unpacklo_epi16(r, g);
        const __m128i rgHigh = _mm_unpackhi_epi16(r, g);
        const __m128i baLow = _mm_unpacklo_epi16(b, a);
        const __m128i baHigh = _mm_unpackhi_epi16(b, a);
        auto* pixel = reinterpret_cast<__m128i*>(out + 8 * x);
        _mm_storeu_si128(pixel, _mm_unpacklo_epi32(rgLow, baLow));
        _mm_storeu_si128(pixel + 1, _mm_unpackhi_epi32(rgLow, baLow));
        _mm_storeu_si128(pixel + 2, _mm_unpacklo_epi32(rgHigh, baHigh));
        _mm_storeu_si128(pixel + 3, _mm_unpackhi_epi32(rgHigh, baHigh));
    }
#endif
    for (; x < width; ++x) {
        for (int l = 0; l < 4; ++l)
            std::memcpy(out + 8 * x + 2 * std::size_t(l), byLane[l] + 2 * x, 2);
    }
}

/// Whether every channel of the chunk is one this unpacker takes (2- or 4-byte values, all the chunk's lines
/// and width, a half destination only for half values) and the lines hold exactly the unpacked bytes.
exr_result_t checkChunkLayout(const exr_decode_pipeline_t& decode) {
    const int lines = decode.chunk.height;
    std::uint64_t lineBytes = 0;
    for (int c = 0; c < decode.channel_count; ++c) {
        const exr_coding_channel_info_t& channel = decode.channels[c];
        if (channel.height != lines || channel.width != decode.chunk.width ||
            (channel.bytes_per_element != 2 && channel.bytes_per_element != 4) ||
            (channel.decode_to_ptr != nullptr && channel.user_bytes_per_element == 2 &&
             channel.bytes_per_element != 2))
            return EXR_ERR_INVALID_ARGUMENT;
        lineBytes += std::uint64_t(channel.width) * std::uint64_t(channel.bytes_per_element);
    }
    if (decode.unpacked_buffer == nullptr || decode.decoding_user_data == nullptr || lines < 0 ||
        lineBytes * std::uint64_t(lines) != decode.chunk.unpacked_size)
        return EXR_ERR_CORRUPT_CHUNK;
    return EXR_ERR_SUCCESS;
}

/// Line y of four channels that make up RGBA pixels, from `source`; returns the end of the line's runs.
const std::uint8_t* unpackFourLine(const exr_decode_pipeline_t& decode, const FourLanes& four,
                                   ZipState& state, const std::uint8_t* source, int y, std::size_t width) {
    std::uint8_t* out = four.base + std::ptrdiff_t(y) * decode.channels[0].user_line_stride;
    if (four.halves) {
        const std::uint8_t* runs[4];
        for (int c = 0; c < 4; ++c) {
            runs[c] = source;
            source += width * std::size_t(decode.channels[c].bytes_per_element);
        }
        interleaveFourHalves(runs, four.lane, out, width);
        return source;
    }
    const float* runs[4];
    for (int c = 0; c < 4; ++c) {
        const exr_coding_channel_info_t& channel = decode.channels[c];
        runs[c] = lineFloats(channel, source, state.floats.data() + std::size_t(c) * width);
        source += width * std::size_t(channel.bytes_per_element);
    }
    interleaveFour(runs, four.lane, out, width);
    return source;
}

/// Line y of one channel's run into its destination, if it has one: halves as they are, else as floats.
void unpackRun(const exr_coding_channel_info_t& channel, ZipState& state, const std::uint8_t* source, int y,
               std::size_t width) {
    if (channel.decode_to_ptr == nullptr)
        return;
    std::uint8_t* out = channel.decode_to_ptr + std::ptrdiff_t(y) * channel.user_line_stride;
    const std::ptrdiff_t step = channel.user_pixel_stride;
    if (channel.user_bytes_per_element == 2) {
        if (step == 2) {
            std::memcpy(out, source, width * 2);
        } else {
            for (std::size_t x = 0; x < width; ++x)
                std::memcpy(out + std::ptrdiff_t(x) * step, source + 2 * x, 2);
        }
        return;
    }
    const float* values = lineFloats(channel, source, state.floats.data());
    if (step == sizeof(float)) {
        std::memcpy(out, values, width * sizeof(float));
    } else {
        for (std::size_t x = 0; x < width; ++x)
            std::memcpy(out + std::ptrdiff_t(x) * step, values + x, sizeof(float));
    }
}

/// The pipeline's unpack step: each line of the chunk holds every channel's run of values in the part's
/// channel order (no subsampling here), little-endian; a channel with a float destination is converted to
/// float exactly as Imf::InputFile converts it (halfToFloat gives Imath's values to the bit), a half channel
/// with a half destination is copied as it is, the others are stepped over. Four channels that make up RGBA
/// pixels are widened a run at a time and written a pixel at a time, rather than a value at a time at 16-
/// or 8-byte steps.
exr_result_t unpackChannels(exr_decode_pipeline_t* decode) {
    static_assert(std::endian::native == std::endian::little, "EXR values are little-endian");
    if (const exr_result_t layout = checkChunkLayout(*decode); layout != EXR_ERR_SUCCESS)
        return layout;
    const auto* source = static_cast<const std::uint8_t*>(decode->unpacked_buffer);
    auto& state = *static_cast<ZipState*>(decode->decoding_user_data);
    const std::size_t width = std::size_t(std::max(decode->chunk.width, 0));
    try {
        state.floats.resize(width * 4);
    } catch (const std::bad_alloc&) {
        return EXR_ERR_OUT_OF_MEMORY;
    }
    const FourLanes four = fourLanes(*decode);
    for (int y = 0; y < decode->chunk.height; ++y) {
        if (four.base != nullptr) {
            source = unpackFourLine(*decode, four, state, source, y, width);
            continue;
        }
        for (int c = 0; c < decode->channel_count; ++c) {
            const exr_coding_channel_info_t& channel = decode->channels[c];
            unpackRun(channel, state, source, y, width);
            source += width * std::size_t(channel.bytes_per_element);
        }
    }
#if defined(__SSE2__)
    _mm_sfence(); // the streamed stores are seen before the task reports done
#endif
    return EXR_ERR_SUCCESS;
}

// ---------------------------------------------------------------------------------------- the frame buffer

/// The address of pixel (x, y), in data-window coordinates, of an Imf slice: Imf's base addresses it at
/// base + x * xStride + y * yStride (the base itself may lie outside the buffer).
std::uint8_t* slicePixel(const Imf::Slice& slice, std::int64_t x, std::int64_t y) {
    return reinterpret_cast<std::uint8_t*>(reinterpret_cast<std::intptr_t>(slice.base) +
                                           std::intptr_t(x) * std::intptr_t(slice.xStride) +
                                           std::intptr_t(y) * std::intptr_t(slice.yStride));
}

/// Where a file channel goes: the frame buffer slice's pixel (x, y) of the data window is at
/// `origin + (y - minY) * lineStride + (x - minX) * pixelStride`.
struct Target {
    std::uint8_t* origin = nullptr;
    int pixelStride = 0;
    int lineStride = 0;
    bool half = false; ///< a half slice (of a half channel: its bits as stored), else a float one
};

struct Job {
    exr_const_context_t context = nullptr;
    int minY = 0;
    int maxY = 0;
    int width = 0;
    int scanlinesPerChunk = 1;
    std::vector<Target> targets; // one per file channel, in the part's channel order; origin null: skipped
    std::atomic<bool> failed{false};
};

bool decodeChunk(Job& job, ZipState& state, exr_decode_pipeline_t& decode, bool& initialised, int chunkY) {
    exr_chunk_info_t chunk{};
    if (exr_read_scanline_chunk_info(job.context, 0, chunkY, &chunk) != EXR_ERR_SUCCESS)
        return false;
    // The rows the chunk writes, checked against the frame buffer's before any pointer is made.
    if (chunk.width != job.width || chunk.height < 1 || chunk.start_y != chunkY ||
        std::int64_t(chunk.start_y) + chunk.height - 1 > job.maxY)
        return false;
    if (!initialised) {
        if (exr_decoding_initialize(job.context, 0, &chunk, &decode) != EXR_ERR_SUCCESS)
            return false;
        initialised = true;
        decode.decoding_user_data = &state; // initialize clears the whole pipeline
    } else if (exr_decoding_update(job.context, 0, &chunk, &decode) != EXR_ERR_SUCCESS) {
        return false;
    }
    if (std::size_t(decode.channel_count) != job.targets.size())
        return false;
    for (int c = 0; c < decode.channel_count; ++c) {
        exr_coding_channel_info_t& channel = decode.channels[c];
        const Target& target = job.targets[std::size_t(c)];
        if (target.origin == nullptr) {
            channel.decode_to_ptr = nullptr;
            continue;
        }
        channel.decode_to_ptr = target.origin + std::ptrdiff_t(chunk.start_y - job.minY) * target.lineStride;
        channel.user_pixel_stride = target.pixelStride;
        channel.user_line_stride = target.lineStride;
        channel.user_data_type = target.half ? EXR_PIXEL_HALF : EXR_PIXEL_FLOAT;
        channel.user_bytes_per_element = target.half ? 2 : 4;
    }
    if (exr_decoding_choose_default_routines(job.context, 0, &decode) != EXR_ERR_SUCCESS)
        return false;
    if (decode.decompress_fn != nullptr)
        decode.decompress_fn = &inflateZipChunk;
    decode.unpack_and_convert_fn = &unpackChannels;
    return exr_decoding_run(job.context, 0, &decode) == EXR_ERR_SUCCESS;
}

/// Decodes the chunks first, first + step, ... of the part (scanline chunks, in file order of y).
class ChunkTask : public IlmThread::Task {
public:
    ChunkTask(IlmThread::TaskGroup* group, Job& job, int first, int step, int chunks)
        : IlmThread::Task(group)
        , mJob(job)
        , mFirst(first)
        , mStep(step)
        , mChunks(chunks) {}

    void execute() override {
        ZipState state;
        exr_decode_pipeline_t decode = EXR_DECODE_PIPELINE_INITIALIZER;
        bool initialised = false;
        for (int i = mFirst; i < mChunks && !mJob.failed.load(std::memory_order_relaxed); i += mStep) {
            if (!decodeChunk(mJob, state, decode, initialised, mJob.minY + i * mJob.scanlinesPerChunk)) {
                mJob.failed.store(true, std::memory_order_relaxed);
                break;
            }
        }
        if (initialised)
            exr_decoding_destroy(mJob.context, &decode);
    }

private:
    Job& mJob;
    int mFirst;
    int mStep;
    int mChunks;
};

/// Whether every slice is one the decoder fills: float or half, unsampled, strides positive and within int.
bool slicesFit(const Imf::FrameBuffer& frameBuffer) {
    for (auto it = frameBuffer.begin(); it != frameBuffer.end(); ++it) {
        const Imf::Slice& s = it.slice();
        if ((s.type != Imf::FLOAT && s.type != Imf::HALF) || s.xSampling != 1 || s.ySampling != 1 ||
            s.xTileCoords || s.yTileCoords || s.xStride <= 0 || s.yStride <= 0 ||
            s.xStride > std::numeric_limits<int>::max() || s.yStride > std::numeric_limits<int>::max())
            return false;
    }
    return true;
}

/// The single part's layout, as the core library reads it.
struct PartLayout {
    exr_attr_box2i_t window{};
    int32_t scanlinesPerChunk = 0;
    int32_t chunks = 0;
    const exr_attr_chlist_t* channels = nullptr;
};

/// The layout of a single-part ZIP or ZIPS scanline file whose data window is the header's and whose chunk
/// count matches it; else nullopt.
std::optional<PartLayout> zipPartLayout(exr_const_context_t context, const Imf::Header& header) {
    int parts = 0;
    exr_storage_t storage{};
    exr_compression_t compression{};
    PartLayout part;
    if (exr_get_count(context, &parts) != EXR_ERR_SUCCESS || parts != 1 ||
        exr_get_storage(context, 0, &storage) != EXR_ERR_SUCCESS || storage != EXR_STORAGE_SCANLINE ||
        exr_get_compression(context, 0, &compression) != EXR_ERR_SUCCESS ||
        (compression != EXR_COMPRESSION_ZIP && compression != EXR_COMPRESSION_ZIPS) ||
        exr_get_data_window(context, 0, &part.window) != EXR_ERR_SUCCESS ||
        exr_get_scanlines_per_chunk(context, 0, &part.scanlinesPerChunk) != EXR_ERR_SUCCESS ||
        part.scanlinesPerChunk < 1 || exr_get_chunk_count(context, 0, &part.chunks) != EXR_ERR_SUCCESS ||
        part.chunks < 1 || exr_get_channels(context, 0, &part.channels) != EXR_ERR_SUCCESS ||
        part.channels == nullptr)
        return std::nullopt;
    const exr_attr_box2i_t& window = part.window;
    const Imath::Box2i dataWindow = header.dataWindow();
    if (window.min.x != dataWindow.min.x || window.min.y != dataWindow.min.y ||
        window.max.x != dataWindow.max.x || window.max.y != dataWindow.max.y)
        return std::nullopt;
    const std::int64_t height = std::int64_t(window.max.y) - window.min.y + 1;
    if (std::int64_t(part.chunks) != (height + part.scanlinesPerChunk - 1) / part.scanlinesPerChunk)
        return std::nullopt;
    return part;
}

/// The job's target for each of the part's channels, in its order; false when a channel cannot go into its
/// slice here.
bool addTargets(Job& job, const PartLayout& part, const Imf::FrameBuffer& frameBuffer) {
    for (int c = 0; c < part.channels->num_channels; ++c) {
        const exr_attr_chlist_entry_t& entry = part.channels->entries[c];
        const Imf::Slice* slice = frameBuffer.findSlice(entry.name.str);
        Target target;
        if (slice != nullptr) {
            // A half slice takes a half channel's bits; a float channel into it (a rounding) is Imf's.
            if ((entry.pixel_type != EXR_PIXEL_HALF && entry.pixel_type != EXR_PIXEL_FLOAT) ||
                entry.x_sampling != 1 || entry.y_sampling != 1 ||
                (slice->type == Imf::HALF && entry.pixel_type != EXR_PIXEL_HALF))
                return false;
            target.origin = slicePixel(*slice, part.window.min.x, part.window.min.y);
            target.pixelStride = int(slice->xStride);
            target.lineStride = int(slice->yStride);
            target.half = slice->type == Imf::HALF;
        }
        job.targets.push_back(target);
    }
    return true;
}

/// Slices the file has no channel for take their fill value, as Imf::InputFile gives them.
void fillMissingSlices(const Imf::Header& header, const Imf::FrameBuffer& frameBuffer,
                       const exr_attr_box2i_t& window, int width) {
    for (auto it = frameBuffer.begin(); it != frameBuffer.end(); ++it) {
        if (header.channels().findChannel(it.name()) != nullptr)
            continue;
        const Imf::Slice& s = it.slice();
        const float fill = float(s.fillValue);
        const std::uint16_t halfFill = floatToHalf(fill); // Imf's half(float) for the values it is given
        const void* value = s.type == Imf::HALF ? static_cast<const void*>(&halfFill) : &fill;
        const std::size_t size = s.type == Imf::HALF ? sizeof(halfFill) : sizeof(fill);
        for (std::int64_t y = window.min.y; y <= window.max.y; ++y) {
            std::uint8_t* row = slicePixel(s, window.min.x, y);
            for (int x = 0; x < width; ++x)
                std::memcpy(row + std::ptrdiff_t(x) * s.xStride, value, size);
        }
    }
}

/// Decodes the job's chunks on OpenEXR's global thread pool; false when one failed.
bool runChunkTasks(Job& job, int chunks) {
    const int threads = std::max(1, IlmThread::ThreadPool::globalThreadPool().numThreads());
    const int tasks = std::min(threads, chunks);
    {
        IlmThread::TaskGroup group; // waits for its tasks when it goes out of scope
        for (int t = 0; t < tasks; ++t)
            IlmThread::ThreadPool::addGlobalTask(new ChunkTask(&group, job, t, tasks, chunks));
    }
    return !job.failed.load();
}

} // namespace

bool readZipScanlines(std::span<const unsigned char> bytes, const Imf::Header& header,
                      const Imf::FrameBuffer& frameBuffer) {
    if (header.compression() != Imf::ZIP_COMPRESSION && header.compression() != Imf::ZIPS_COMPRESSION)
        return false;
    if (!slicesFit(frameBuffer))
        return false;
    MemorySource file{bytes, {}};
    ExrReadContext context;
    if (!startMemoryRead(context, file, &quiet))
        return false;
    const std::optional<PartLayout> part = zipPartLayout(context.handle, header);
    if (!part)
        return false;
    Job job;
    job.context = context.handle;
    job.minY = part->window.min.y;
    job.maxY = part->window.max.y;
    job.width = part->window.max.x - part->window.min.x + 1;
    job.scanlinesPerChunk = part->scanlinesPerChunk;
    if (!addTargets(job, *part, frameBuffer))
        return false;
    fillMissingSlices(header, frameBuffer, part->window, job.width);
    return runChunkTasks(job, part->chunks);
}

} // namespace photopic::detail
