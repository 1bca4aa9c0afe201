#pragma once
// `photopic image` over a sequence streams its frames: while the GL thread processes frame N, frame N+1 is
// decoded and frames N-1, N-2, ... are encoded and written on other threads. Everything else stays on the
// calling thread in frame order (GL, telemetry, the lines printed, RunOutputs), so the outputs, the telemetry
// and the console are the same as a serial run's. What is in flight is bounded (one frame decoded ahead, a
// fixed number being written), so memory stays flat over a sequence of any length, and the images read back
// are recycled, so a steady-state frame allocates none.

#include "ImageInputs.h"
#include "Outputs.h"

#include "core/Image.h"

#include "io/DisplayImageIO.h"
#include "io/ImageIO.h"

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <filesystem>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace photopic::cli {

/// One thread that runs the tasks given to it one after another, in order; each task's result or exception
/// comes back through the future run() returns. A thread that lives as long as the sequence (rather than
/// one per task) keeps its buffers in one malloc arena, where the next frame finds them again.
class Worker {
public:
    Worker();
    /// Runs the tasks still queued, then joins.
    ~Worker();
    Worker(const Worker&) = delete;
    Worker& operator=(const Worker&) = delete;

    template <class F>
    [[nodiscard]] auto run(F task) -> std::future<decltype(task())> {
        using Result = decltype(task());
        auto packaged = std::make_shared<std::packaged_task<Result()>>(std::move(task));
        std::future<Result> result = packaged->get_future();
        post([packaged] { (*packaged)(); });
        return result;
    }

private:
    void post(std::function<void()> task);
    void loop();
    std::mutex mMutex;
    std::condition_variable mWake;
    std::deque<std::function<void()>> mTasks;
    bool mStop = false;
    std::thread mThread;
};

/// Decodes a sequence's frames in order on a worker thread, `ahead` frames at most beyond the one the caller
/// holds (0: each on the caller's thread, in next()). At 1 the next frame is decoded as soon as the caller
/// has released this one, i.e. uploaded it, so its decode runs while this frame is on the GPU, and a sequence
/// holds one decoded frame whatever its length. At 2 it is decoded while this one is uploaded too, for two
/// frames' memory. Frames are decoded one after another, never two at once (the decoder carries the previous
/// frame's camera), and into the storage of frames released. A decode error (InputError) comes out of next()
/// for the frame it belongs to. Only the first frame's decode starts at construction: the others wait for
/// decodeAhead() or the first release(), so that what the decoder is told before (the layers to leave out)
/// holds for them.
class FrameReader {
public:
    FrameReader(InputDecoder& decoder, const std::vector<std::filesystem::path>& inputs, int ahead);
    /// Starts the decodes ahead that wait (from 2 ahead: the second frame's, while the first is held).
    void decodeAhead();
    /// Waits for the decodes in flight (their errors, if any, go with them: the run failed already).
    ~FrameReader();
    FrameReader(const FrameReader&) = delete;
    FrameReader& operator=(const FrameReader&) = delete;

    /// The current frame, in input order (waits for its decode); the same frame until release(). Without
    /// the layers the decoder was told to leave out since (InputDecoder::readLayers).
    [[nodiscard]] const DecodedFrame& next();
    /// The caller is done with the frame next() returned: its storage goes back to the decoder for a frame
    /// still to decode, whose decode is queued (at once when `ahead` > 0, else at the next next()).
    void release();
    /// How long the current frame's decode took on the thread that decoded it, ms.
    [[nodiscard]] double decodeMs() const { return mCurrent.ms; }

private:
    struct Decoded {
        DecodedFrame frame;
        double ms = 0.0;
    };
    /// Queues the decode of the next input, into `storage`'s memory.
    void start(DecodedFrame storage);
    [[nodiscard]] Decoded decode(const std::filesystem::path& path, DecodedFrame storage);
    InputDecoder& mDecoder;
    const std::vector<std::filesystem::path>& mInputs;
    int mAhead;
    std::size_t mNext = 0; ///< the index of the frame decoded next
    bool mHave = false;    ///< mCurrent holds the frame next() returned, not yet released
    Decoded mCurrent;
    std::deque<std::future<Decoded>> mPending; ///< oldest first
    std::unique_ptr<Worker> mWorker;           ///< last: joined before the members its tasks use go
};

/// Frames a sequence decodes ahead of the one being processed, of `framesInFlight` (--frames-in-flight): 0
/// for 1 (serial); 1 for 2 and 3 (the default with up to four cores, where the cores are busy already: a
/// software renderer uses them, and a second decoded frame would only add its memory); 2 from 4 on (the
/// default on more than four cores), where the next frame's decode then overlaps this one's upload too.
[[nodiscard]] int framesDecodedAhead(int framesInFlight);

/// A frame read back from the GPU: the display image (PNG, TIFF, JPEG outputs; 8 or 16 bits) or the
/// scene-referred one (EXR outputs).
struct FrameImage {
    Image8 display;
    Image16 display16; ///< the display image at output.bitDepth 16
    ImageF scene;
};

/// How FrameWriter encodes the display image.
struct DisplayEncoding {
    int bitDepth = 8;                      ///< 8: FrameImage::display is written, 16: display16
    int jpegQuality = kDefaultJpegQuality; ///< [1, 100], default 95
};

/// Writes `image.scene` to an .exr `path`, else the display image (`display`, or `display16` at 16 bits) as
/// the extension says, PNG when it names no display format (a stream); `png` keeps the 8-bit PNG encoder's
/// buffers from frame to frame. Gives the image back for its storage to be reused. Throws IoError.
FrameImage writeFrameImage(const std::filesystem::path& path, FrameImage image, PngWriter& png,
                           DisplayEncoding encoding);

/// How FrameWriter tells RunOutputs of a frame written.
enum class FrameRecord {
    Listed,   ///< RunOutputs::wrote(path)
    Sequence, ///< RunOutputs::wroteSequenceItem(): the frames are its numbered sequence, given in order (once
              ///< one fails to be written, the ones after it are listed)
};

/// Encodes and writes frames on worker threads, at most `maxPending` at a time (0: on the caller's thread,
/// before write() returns), and reports each written frame in the order the frames were given: the path
/// goes to RunOutputs and `report` runs, both on the caller's thread.
class FrameWriter {
public:
    FrameWriter(RunOutputs& outputs, std::size_t maxPending, DisplayEncoding encoding,
                FrameRecord record = FrameRecord::Listed);
    /// Waits for every write still running; the files that were written go to RunOutputs (which removes
    /// them when the run failed).
    ~FrameWriter();
    FrameWriter(const FrameWriter&) = delete;
    FrameWriter& operator=(const FrameWriter&) = delete;

    /// Storage for the next frame's read-back, recycled from a frame already written when there is one.
    [[nodiscard]] FrameImage storage();
    /// Writes `image.scene` to an .exr `path`, else the display image as the extension says (PNG when it
    /// names no display format: a stream). When `maxPending` writes are running, first waits for the oldest
    /// (and throws its error).
    void write(const std::filesystem::path& path, FrameImage image, std::function<void()> report);
    /// Waits for every write, in order; throws the first error.
    void finish();

private:
    struct Pending {
        std::filesystem::path path;
        std::future<FrameImage> done;
        std::function<void()> report;
    };
    void retireOldest();
    void record(const std::filesystem::path& path);
    RunOutputs& mOutputs;
    FrameRecord mRecord;
    bool mGap = false; ///< a write failed: the frames after it are no longer the sequence's first ones
    std::size_t mMaxPending;
    DisplayEncoding mEncoding;
    std::deque<Pending> mPending;
    std::vector<FrameImage> mFree;
    std::size_t mWritten = 0;         ///< frames given to write(); frame i goes to worker i % workers
    std::vector<PngWriter> mEncoders; ///< one per worker, used only on its thread
    std::vector<std::unique_ptr<Worker>> mWorkers; ///< last: joined before the encoders go
};

} // namespace photopic::cli
