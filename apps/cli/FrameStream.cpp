#include "FrameStream.h"

#include "io/ImageIO.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <string>
#include <thread>
#include <utility>

namespace photopic::cli {

namespace fs = std::filesystem;

namespace {
/// Encoder threads at most: PNG encoding is one thread's work per frame, so a machine with many cores encodes
/// as many frames at once as `--frames-in-flight` allows, leaving one core to decode and one to drive GL;
/// with up to four cores (llvmpipe renders on them) two.
std::size_t maxWorkers() {
    const std::size_t cores = std::thread::hardware_concurrency();
    return std::max<std::size_t>(2, cores > 2 ? cores - 2 : 0);
}
} // namespace

// ---------------------------------------------------------------------------------------------------------------
// Worker

Worker::Worker()
    : mThread([this] { loop(); }) {}

Worker::~Worker() {
    {
        const std::lock_guard lock(mMutex);
        mStop = true;
    }
    mWake.notify_one();
    mThread.join();
}

void Worker::post(std::function<void()> task) {
    {
        const std::lock_guard lock(mMutex);
        mTasks.push_back(std::move(task));
    }
    mWake.notify_one();
}

void Worker::loop() {
    for (;;) {
        std::function<void()> task;
        {
            std::unique_lock lock(mMutex);
            mWake.wait(lock, [this] { return mStop || !mTasks.empty(); });
            if (mTasks.empty()) {
                return; // stopped, and nothing left to run
            }
            task = std::move(mTasks.front());
            mTasks.pop_front();
        }
        task(); // a packaged task: its exception goes to its future
    }
}

// ---------------------------------------------------------------------------------------------------------------
// Reading

FrameReader::FrameReader(InputDecoder& decoder, const std::vector<fs::path>& inputs, int ahead)
    : mDecoder(decoder)
    , mInputs(inputs)
    , mAhead(std::max(ahead, 0)) {
    if (mAhead > 0) {
        mWorker = std::make_unique<Worker>();
        start({});
    }
}

void FrameReader::decodeAhead() {
    // At most `ahead` frames decoded or decoding, the one the caller holds counted.
    while (mAhead > 0 && int(mPending.size()) + (mHave ? 1 : 0) < mAhead && mNext < mInputs.size()) {
        start({});
    }
}

FrameReader::~FrameReader() {
    for (auto& pending : mPending) {
        pending.wait();
    }
}

FrameReader::Decoded FrameReader::decode(const fs::path& path, DecodedFrame storage) {
    const auto begin = std::chrono::steady_clock::now();
    mDecoder.recycle(std::move(storage)); // on the decoding thread: no other decode is running
    Decoded decoded{.frame = mDecoder.decode(path)};
    decoded.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
    return decoded;
}

void FrameReader::start(DecodedFrame storage) {
    if (mNext >= mInputs.size()) {
        return;
    }
    // The worker runs its tasks in order: each decode starts after the one before it has finished.
    const fs::path& path = mInputs[mNext++];
    mPending.push_back(mWorker->run(
        [this, &path, storage = std::move(storage)]() mutable { return decode(path, std::move(storage)); }));
}

const DecodedFrame& FrameReader::next() {
    if (!mHave) {
        if (mAhead > 0) {
            std::future<Decoded> pending = std::move(mPending.front());
            mPending.pop_front();
            mCurrent = pending.get();
        } else {
            mCurrent = decode(mInputs[mNext++], std::move(mCurrent.frame));
        }
        mHave = true;
    }
    mDecoder.leaveOutUnread(mCurrent.frame); // decoded before the decoder was told what to leave out
    return mCurrent.frame;
}

void FrameReader::release() {
    mHave = false;
    if (mAhead > 0) {
        start(std::move(mCurrent.frame));
        mCurrent.frame = {};
        decodeAhead();
    }
}

int framesDecodedAhead(int framesInFlight) {
    if (framesInFlight <= 1) {
        return 0;
    }
    return framesInFlight >= 4 ? 2 : 1;
}

// ---------------------------------------------------------------------------------------------------------------
// Writing

namespace {

bool isExrPath(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".exr";
}

} // namespace

FrameImage writeFrameImage(const fs::path& path, FrameImage image, PngWriter& png, DisplayEncoding encoding) {
    if (isExrPath(path)) {
        writeExr(path, image.scene);
        return image;
    }
    const bool deep = encoding.bitDepth == 16;
    switch (displayFileFormatFor(path).value_or(DisplayFileFormat::Png)) {
    case DisplayFileFormat::Png:
        if (deep) {
            writePng16(path, image.display16);
        } else {
            png.write(path, image.display);
        }
        break;
    case DisplayFileFormat::Tiff:
        if (deep) {
            writeTiff(path, image.display16);
        } else {
            writeTiff(path, image.display);
        }
        break;
    case DisplayFileFormat::Jpeg: // photopic image refuses 16 bits for a JPEG before any work
        writeJpeg(path, image.display, encoding.jpegQuality);
        break;
    }
    return image;
}

FrameWriter::FrameWriter(RunOutputs& outputs, std::size_t maxPending, DisplayEncoding encoding,
                         FrameRecord record)
    : mOutputs(outputs)
    , mRecord(record)
    , mMaxPending(maxPending)
    , mEncoding(encoding)
    , mEncoders(std::max<std::size_t>(std::min<std::size_t>(maxPending, maxWorkers()), 1)) {
    for (std::size_t i = 0; maxPending > 0 && i < mEncoders.size(); ++i) {
        mWorkers.push_back(std::make_unique<Worker>());
    }
}

FrameWriter::~FrameWriter() {
    for (Pending& p : mPending) {
        try {
            p.done.get();
            record(p.path);
        } catch (...) { // the run is failing already; the writer removed its own temporary
            mGap = true;
        }
    }
}

FrameImage FrameWriter::storage() {
    if (mFree.empty()) {
        return {};
    }
    FrameImage image = std::move(mFree.back());
    mFree.pop_back();
    return image;
}

void FrameWriter::write(const fs::path& path, FrameImage image, std::function<void()> report) {
    if (mWorkers.empty()) {
        mFree.push_back(writeFrameImage(path, std::move(image), mEncoders.front(), mEncoding));
        record(path);
        report();
        return;
    }
    while (mPending.size() >= mMaxPending) {
        retireOldest();
    }
    const std::size_t w = mWritten++ % mWorkers.size();
    PngWriter& png = mEncoders[w];
    mPending.push_back(
        {.path = path,
         .done = mWorkers[w]->run([path, image = std::move(image), &png, encoding = mEncoding]() mutable {
             return writeFrameImage(path, std::move(image), png, encoding);
         }),
         .report = std::move(report)});
}

void FrameWriter::retireOldest() {
    Pending p = std::move(mPending.front());
    mPending.pop_front();
    try {
        mFree.push_back(p.done.get());
    } catch (...) {
        mGap = true; // the frames after it that other workers write are listed (the destructor's record())
        throw;
    }
    record(p.path);
    p.report();
}

void FrameWriter::record(const fs::path& path) {
    // Counted while the frames written are the sequence's first ones; past a frame that failed, listed.
    if (mRecord == FrameRecord::Sequence && !mGap) {
        mOutputs.wroteSequenceItem();
    } else {
        mOutputs.wrote(path);
    }
}

void FrameWriter::finish() {
    while (!mPending.empty()) {
        retireOldest();
    }
}

} // namespace photopic::cli
