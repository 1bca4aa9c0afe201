// OpenEXR's core library over a file in memory: the check that every chunk holds the bytes its lines need
// (checkExrChunks), and scanline ZIP / ZIPS pixel data decoded through it (chunk table, chunk reads and their
// checks) with the inflate step done by libdeflate instead of zlib, on OpenEXR's global thread pool. The
// unpacking into the frame buffer is done here too: OpenEXR 3.1's own routine for four half channels into
// interleaved floats at descending addresses (A, B, G, R into RGBA) writes them in file order, R's value
// where A belongs (ExrZipTest.RgbaMatchesOpenExrBitForBit fails with it). Half channels may also go to half
// slices, as stored (a colour kept in half the memory). zlib's inflate was the largest
// single cost of reading a ZIP-compressed sequence; libdeflate inflates the same stream several times faster.
//
// The ZIP codec (OpenEXR file layout, "ZIP compression"): a chunk's bytes are deflated in a zlib stream after
// two reversible steps, which are undone here after inflating: the bytes were split into the even-indexed
// ones followed by the odd-indexed ones, and then each byte replaced by its difference to the previous one
// plus 128 (modulo 256; the first byte kept). A chunk whose deflated size would not be smaller is stored raw.
#include "io/ExrDetail.h"

#include "core/HalfFloat.h"

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
#include <string>
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

/// The pipeline's unpack step: each line of the chunk holds every channel's run of values in the part's
/// channel order (no subsampling here), little-endian; a channel with a float destination is converted to
/// float exactly as Imf::InputFile converts it (halfToFloat gives Imath's values to the bit), a half channel
/// with a half destination is copied as it is, the others are stepped over. Four channels that make up RGBA
/// pixels are widened a run at a time and written a pixel at a time, rather than a value at a time at 16-
/// or 8-byte steps.
exr_result_t unpackChannels(exr_decode_pipeline_t* decode) {
    static_assert(std::endian::native == std::endian::little, "EXR values are little-endian");
    const auto* source = static_cast<const std::uint8_t*>(decode->unpacked_buffer);
    auto* state = static_cast<ZipState*>(decode->decoding_user_data);
    const int lines = decode->chunk.height;
    std::uint64_t lineBytes = 0;
    for (int c = 0; c < decode->channel_count; ++c) {
        const exr_coding_channel_info_t& channel = decode->channels[c];
        if (channel.height != lines || channel.width != decode->chunk.width ||
            (channel.bytes_per_element != 2 && channel.bytes_per_element != 4) ||
            (channel.decode_to_ptr != nullptr && channel.user_bytes_per_element == 2 &&
             channel.bytes_per_element != 2))
            return EXR_ERR_INVALID_ARGUMENT;
        lineBytes += std::uint64_t(channel.width) * std::uint64_t(channel.bytes_per_element);
    }
    if (source == nullptr || state == nullptr || lines < 0 ||
        lineBytes * std::uint64_t(lines) != decode->chunk.unpacked_size)
        return EXR_ERR_CORRUPT_CHUNK;
    const std::size_t width = std::size_t(std::max(decode->chunk.width, 0));
    try {
        state->floats.resize(width * 4);
    } catch (const std::bad_alloc&) {
        return EXR_ERR_OUT_OF_MEMORY;
    }
    const FourLanes four = fourLanes(*decode);
    for (int y = 0; y < lines; ++y) {
        if (four.base != nullptr && four.halves) {
            const std::uint8_t* runs[4];
            for (int c = 0; c < 4; ++c) {
                runs[c] = source;
                source += width * std::size_t(decode->channels[c].bytes_per_element);
            }
            interleaveFourHalves(runs, four.lane,
                                 four.base + std::ptrdiff_t(y) * decode->channels[0].user_line_stride, width);
            continue;
        }
        if (four.base != nullptr) {
            const float* runs[4];
            for (int c = 0; c < 4; ++c) {
                const exr_coding_channel_info_t& channel = decode->channels[c];
                runs[c] = lineFloats(channel, source, state->floats.data() + std::size_t(c) * width);
                source += width * std::size_t(channel.bytes_per_element);
            }
            interleaveFour(runs, four.lane,
                           four.base + std::ptrdiff_t(y) * decode->channels[0].user_line_stride, width);
            continue;
        }
        for (int c = 0; c < decode->channel_count; ++c) {
            const exr_coding_channel_info_t& channel = decode->channels[c];
            if (channel.decode_to_ptr != nullptr && channel.user_bytes_per_element == 2) {
                std::uint8_t* out = channel.decode_to_ptr + std::ptrdiff_t(y) * channel.user_line_stride;
                const std::ptrdiff_t step = channel.user_pixel_stride;
                if (step == 2) {
                    std::memcpy(out, source, width * 2);
                } else {
                    for (std::size_t x = 0; x < width; ++x)
                        std::memcpy(out + std::ptrdiff_t(x) * step, source + 2 * x, 2);
                }
            } else if (channel.decode_to_ptr != nullptr) {
                const float* values = lineFloats(channel, source, state->floats.data());
                std::uint8_t* out = channel.decode_to_ptr + std::ptrdiff_t(y) * channel.user_line_stride;
                const std::ptrdiff_t step = channel.user_pixel_stride;
                if (step == sizeof(float)) {
                    std::memcpy(out, values, width * sizeof(float));
                } else {
                    for (std::size_t x = 0; x < width; ++x)
                        std::memcpy(out + std::ptrdiff_t(x) * step, values + x, sizeof(float));
                }
            }
            source += width * std::size_t(channel.bytes_per_element);
        }
    }
#if defined(__SSE2__)
    _mm_sfence(); // the streamed stores are seen before the task reports done
#endif
    return EXR_ERR_SUCCESS;
}

// ---------------------------------------------------------------------------------------- the file in memory

/// An OpenEXR file in memory, as the core library's read callbacks see it, and the library's last error
/// message about it (kept by keepMessage; `quiet` keeps none).
struct MemorySource {
    std::span<const unsigned char> bytes;
    std::string error;
};

int64_t readMemory(exr_const_context_t, void* user, void* buffer, uint64_t size, uint64_t offset,
                   exr_stream_error_func_ptr_t) {
    const std::span<const unsigned char> bytes = static_cast<const MemorySource*>(user)->bytes;
    if (offset >= bytes.size())
        return 0;
    const std::uint64_t n = std::min<std::uint64_t>(size, bytes.size() - offset);
    std::memcpy(buffer, bytes.data() + offset, n);
    return int64_t(n);
}

int64_t memorySize(exr_const_context_t, void* user) {
    return int64_t(static_cast<const MemorySource*>(user)->bytes.size());
}

/// Any failure here falls back to Imf::InputFile, which reports it in its own words: nothing to print.
void quiet(exr_const_context_t, exr_result_t, const char*) {}

/// Collects the core library's last error message (its error handler's user data).
void keepMessage(exr_const_context_t context, exr_result_t, const char* message) {
    void* user = nullptr;
    if (exr_get_user_data(context, &user) == EXR_ERR_SUCCESS && user != nullptr && message != nullptr)
        static_cast<MemorySource*>(user)->error = message;
}

struct Context {
    exr_context_t handle = nullptr;
    Context() = default;
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;
    ~Context() {
        if (handle != nullptr)
            exr_finish(&handle);
    }
};

/// Opens `source` for reading with the core library, its errors going to `onError`; false when the header
/// cannot be read.
bool startMemoryRead(Context& context, MemorySource& source, exr_error_handler_cb_t onError) {
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.user_data = &source;
    init.read_fn = &readMemory;
    init.size_fn = &memorySize;
    init.error_handler_fn = onError;
    return exr_start_read(&context.handle, "memory", &init) == EXR_ERR_SUCCESS;
}

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

// ------------------------------------------------------------------------------------- the chunks' sizes

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

} // namespace

void checkExrChunks(const std::filesystem::path& path, std::span<const unsigned char> bytes, int part) {
    MemorySource source{bytes, {}};
    Context context;
    const auto corrupt = [&](const std::string& where) {
        throw IoError(path, "OpenEXR pixel data is corrupt: " + where +
                                (source.error.empty() ? std::string() : ": " + source.error));
    };
    if (!startMemoryRead(context, source, &keepMessage))
        corrupt("the chunk table cannot be read");
    exr_storage_t storage{};
    exr_compression_t compression{};
    exr_attr_box2i_t window{};
    if (exr_get_storage(context.handle, part, &storage) != EXR_ERR_SUCCESS ||
        exr_get_compression(context.handle, part, &compression) != EXR_ERR_SUCCESS ||
        exr_get_data_window(context.handle, part, &window) != EXR_ERR_SUCCESS)
        corrupt(part == 0 ? std::string("the first part's layout cannot be read")
                          : "the layout of part " + std::to_string(part) + " cannot be read");
    if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED)
        return; // deep data: Imf::InputFile refuses it itself

    std::unique_ptr<libdeflate_decompressor, void (*)(libdeflate_decompressor*)> inflater(
        libdeflate_alloc_decompressor(), &libdeflate_free_decompressor);
    std::vector<std::uint8_t> scratch;
    const auto check = [&](exr_result_t read, const exr_chunk_info_t& chunk, const std::string& where) {
        if (read != EXR_ERR_SUCCESS)
            corrupt(where);
        const std::string problem = chunkProblem(compression, chunk, bytes, inflater.get(), scratch);
        if (!problem.empty()) {
            source.error.clear();
            corrupt(where + " " + problem);
        }
    };
    if (storage == EXR_STORAGE_SCANLINE) {
        int32_t linesPerChunk = 0;
        if (exr_get_scanlines_per_chunk(context.handle, part, &linesPerChunk) != EXR_ERR_SUCCESS ||
            linesPerChunk < 1)
            corrupt("the lines per chunk cannot be read");
        for (std::int64_t y = window.min.y; y <= window.max.y; y += linesPerChunk) {
            exr_chunk_info_t chunk{};
            check(exr_read_scanline_chunk_info(context.handle, part, int(y), &chunk), chunk,
                  "the chunk of line " + std::to_string(y));
        }
        return;
    }
    // Tiled: the full-resolution level, the one Imf::InputFile reads.
    int32_t tileWidth = 0;
    int32_t tileHeight = 0;
    int32_t levelWidth = 0;
    int32_t levelHeight = 0;
    if (exr_get_tile_sizes(context.handle, part, 0, 0, &tileWidth, &tileHeight) != EXR_ERR_SUCCESS ||
        exr_get_level_sizes(context.handle, part, 0, 0, &levelWidth, &levelHeight) != EXR_ERR_SUCCESS ||
        tileWidth < 1 || tileHeight < 1 || levelWidth < 1 || levelHeight < 1)
        corrupt("the tile layout cannot be read");
    const int tilesX = int((std::int64_t(levelWidth) + tileWidth - 1) / tileWidth);
    const int tilesY = int((std::int64_t(levelHeight) + tileHeight - 1) / tileHeight);
    for (int ty = 0; ty < tilesY; ++ty) {
        for (int tx = 0; tx < tilesX; ++tx) {
            exr_chunk_info_t chunk{};
            check(exr_read_tile_chunk_info(context.handle, part, tx, ty, 0, 0, &chunk), chunk,
                  "tile (" + std::to_string(tx) + ", " + std::to_string(ty) + ")");
        }
    }
}

bool readZipScanlines(std::span<const unsigned char> bytes, const Imf::Header& header,
                      const Imf::FrameBuffer& frameBuffer) {
    if (header.compression() != Imf::ZIP_COMPRESSION && header.compression() != Imf::ZIPS_COMPRESSION)
        return false;
    for (auto it = frameBuffer.begin(); it != frameBuffer.end(); ++it) {
        const Imf::Slice& s = it.slice();
        if ((s.type != Imf::FLOAT && s.type != Imf::HALF) || s.xSampling != 1 || s.ySampling != 1 ||
            s.xTileCoords || s.yTileCoords || s.xStride <= 0 || s.yStride <= 0 ||
            s.xStride > std::numeric_limits<int>::max() || s.yStride > std::numeric_limits<int>::max())
            return false;
    }

    MemorySource file{bytes, {}};
    Context context;
    if (!startMemoryRead(context, file, &quiet))
        return false;
    int parts = 0;
    exr_storage_t storage{};
    exr_compression_t compression{};
    exr_attr_box2i_t window{};
    int32_t scanlinesPerChunk = 0;
    int32_t chunks = 0;
    const exr_attr_chlist_t* channels = nullptr;
    if (exr_get_count(context.handle, &parts) != EXR_ERR_SUCCESS || parts != 1 ||
        exr_get_storage(context.handle, 0, &storage) != EXR_ERR_SUCCESS || storage != EXR_STORAGE_SCANLINE ||
        exr_get_compression(context.handle, 0, &compression) != EXR_ERR_SUCCESS ||
        (compression != EXR_COMPRESSION_ZIP && compression != EXR_COMPRESSION_ZIPS) ||
        exr_get_data_window(context.handle, 0, &window) != EXR_ERR_SUCCESS ||
        exr_get_scanlines_per_chunk(context.handle, 0, &scanlinesPerChunk) != EXR_ERR_SUCCESS ||
        scanlinesPerChunk < 1 || exr_get_chunk_count(context.handle, 0, &chunks) != EXR_ERR_SUCCESS ||
        chunks < 1 || exr_get_channels(context.handle, 0, &channels) != EXR_ERR_SUCCESS ||
        channels == nullptr)
        return false;
    const Imath::Box2i dataWindow = header.dataWindow();
    if (window.min.x != dataWindow.min.x || window.min.y != dataWindow.min.y ||
        window.max.x != dataWindow.max.x || window.max.y != dataWindow.max.y)
        return false;
    const std::int64_t height = std::int64_t(window.max.y) - window.min.y + 1;
    if (std::int64_t(chunks) != (height + scanlinesPerChunk - 1) / scanlinesPerChunk)
        return false;

    Job job;
    job.context = context.handle;
    job.minY = window.min.y;
    job.maxY = window.max.y;
    job.width = window.max.x - window.min.x + 1;
    job.scanlinesPerChunk = scanlinesPerChunk;
    for (int c = 0; c < channels->num_channels; ++c) {
        const exr_attr_chlist_entry_t& entry = channels->entries[c];
        const Imf::Slice* slice = frameBuffer.findSlice(entry.name.str);
        Target target;
        if (slice != nullptr) {
            // A half slice takes a half channel's bits; a float channel into it (a rounding) is Imf's.
            if ((entry.pixel_type != EXR_PIXEL_HALF && entry.pixel_type != EXR_PIXEL_FLOAT) ||
                entry.x_sampling != 1 || entry.y_sampling != 1 ||
                (slice->type == Imf::HALF && entry.pixel_type != EXR_PIXEL_HALF))
                return false;
            target.origin = slicePixel(*slice, window.min.x, window.min.y);
            target.pixelStride = int(slice->xStride);
            target.lineStride = int(slice->yStride);
            target.half = slice->type == Imf::HALF;
        }
        job.targets.push_back(target);
    }

    // Slices the file has no channel for take their fill value, as Imf::InputFile gives them.
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
            for (int x = 0; x < job.width; ++x)
                std::memcpy(row + std::ptrdiff_t(x) * s.xStride, value, size);
        }
    }

    const int threads = std::max(1, IlmThread::ThreadPool::globalThreadPool().numThreads());
    const int tasks = std::min(threads, int(chunks));
    {
        IlmThread::TaskGroup group; // waits for its tasks when it goes out of scope
        for (int t = 0; t < tasks; ++t)
            IlmThread::ThreadPool::addGlobalTask(new ChunkTask(&group, job, t, tasks, chunks));
    }
    return !job.failed.load();
}

} // namespace photopic::detail
