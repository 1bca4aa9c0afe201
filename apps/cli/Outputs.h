#pragma once
// What a CLI run writes, checked before any work starts and taken back if the run fails or is interrupted:
// a run either finishes with all its outputs, or leaves the outputs as they were before it (no new frames,
// no half-written file, no folder it made, and every file it replaced put back).

#include "Interrupt.h"

#include <cstddef>
#include <filesystem>
#include <functional>
#include <mutex>
#include <string>
#include <unordered_set>
#include <vector>

namespace photopic::cli {

class RunOutputs {
public:
    /// From here until destruction, a file that any atomic writer replaces is first moved aside (beside it,
    /// as ".NAME.previous-PID"), to be put back if the run fails or removed once it succeeds.
    RunOutputs();
    /// Unless commit() was called: removes every file recorded by wrote() and wroteSequenceItem(), then each
    /// folder makeFolder() created, if it is empty, and puts back every file the run replaced. After
    /// commit(): removes the replaced files' old copies.
    ~RunOutputs();
    RunOutputs(const RunOutputs&) = delete;
    RunOutputs& operator=(const RunOutputs&) = delete;

    /// Creates `folder` and its missing parents. Throws InputError (exit 2) naming it when something in the
    /// way is a file or it cannot be created.
    void makeFolder(const std::filesystem::path& folder);
    /// Throws InputError naming `path` unless it can be written (requireWritableFile): for every output file,
    /// before the work that makes it.
    static void requireFile(const std::filesystem::path& path);

    /// A file of this run now exists. A stream output (standard output, a device, a pipe) is not recorded:
    /// what was streamed cannot be taken back, and the device must not be removed.
    void wrote(const std::filesystem::path& path);
    /// Numbered files (frame_0000.png, ...): `name(i)` is the i-th one's path. Counted, not listed, so a run
    /// of any length holds no per-file memory here.
    void sequence(std::function<std::filesystem::path(std::size_t)> name) { mSequenceName = std::move(name); }
    void wroteSequenceItem() { ++mSequenceCount; }

    /// The run succeeded: keep everything. A signal noted since the last frame still takes everything back
    /// (throws Interrupted), so no run ends with exit 0 after a SIGTERM.
    void commit() {
        throwIfInterrupted();
        mCommitted = true;
    }

    /// Where a replaced file waits while the run lasts: ".NAME.previous-PID" beside it.
    static std::filesystem::path previousCopy(const std::filesystem::path& path);

private:
    void moveAside(const std::filesystem::path& path);

    InterruptScope mInterrupts; ///< SIGINT/SIGTERM/SIGHUP unwind the run (throwIfInterrupted) while it lasts
    std::mutex mReplacedMutex;  ///< moveAside runs on the frame writers' threads
    std::unordered_set<std::string> mReplaced;          ///< files moved aside, by path
    std::vector<std::filesystem::path> mCreatedFolders; ///< outermost first
    std::vector<std::filesystem::path> mFiles;
    std::function<std::filesystem::path(std::size_t)> mSequenceName;
    std::size_t mSequenceCount = 0;
    bool mCommitted = false;
};

} // namespace photopic::cli
