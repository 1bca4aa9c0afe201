#pragma once
// What a CLI run writes, checked before any work starts and taken back if the run fails: a run either
// finishes with all its outputs or leaves nothing behind (no frames, no half-written file, no folder it
// made).

#include <cstddef>
#include <filesystem>
#include <functional>
#include <vector>

namespace photopic::cli {

class RunOutputs {
public:
    RunOutputs() = default;
    /// Unless commit() was called: removes every file recorded by wrote() and wroteSequenceItem(), then each
    /// folder makeFolder() created, if it is empty.
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

    void commit() { mCommitted = true; } ///< the run succeeded: keep everything

private:
    std::vector<std::filesystem::path> mCreatedFolders; ///< outermost first
    std::vector<std::filesystem::path> mFiles;
    std::function<std::filesystem::path(std::size_t)> mSequenceName;
    std::size_t mSequenceCount = 0;
    bool mCommitted = false;
};

} // namespace photopic::cli
