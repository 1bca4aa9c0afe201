// Writing files whole or not at all (AtomicFileWriter: a temporary file in the target's folder, renamed over
// it on commit), the hook a run registers to keep what a commit replaces, and the checks of an output path.
#include "io/ImageIoDetail.h"

#include "io/ExrDetail.h"

#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <mutex>
#include <system_error>
#include <utility>

namespace photopic {

namespace fs = std::filesystem;
using namespace detail;

namespace {

std::atomic<unsigned> gTemporaryCounter{0};

/// The folder a file goes into; throws unless `path` names a file in an existing folder.
fs::path outputFolder(const fs::path& path) {
    if (!path.has_filename() || path.filename() == "." || path.filename() == "..")
        throw IoError(path, "names a folder, not a file");
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        throw IoError(path, fs::exists(folder, ec) ? quoted(folder) + " is not a folder"
                                                   : "folder " + quoted(folder) + " does not exist");
    return folder;
}

} // namespace

void detail::writeAtomically(const fs::path& path, std::span<const unsigned char> bytes) {
    AtomicFileWriter file(path);
    file.write({reinterpret_cast<const char*>(bytes.data()), bytes.size()});
    file.commit();
}

AtomicFileWriter::AtomicFileWriter(fs::path path)
    : mPath(std::move(path)) {
    if (isStreamOutput(mPath)) {
        // A stream takes the bytes as they come: there is no folder to put a temporary in, and a rename would
        // replace the device or pipe rather than write to it. /dev/stdout redirected to a file is standard
        // output too: written through the process's stdout, from where it stands, not reopened and truncated.
        mFile = namesStandardOutput(mPath) ? stdout : std::fopen(mPath.c_str(), "wb");
        if (!mFile)
            throw IoError(mPath, "cannot open: " + errnoMessage(errno));
        return;
    }
    const fs::path folder = outputFolder(mPath);
    std::error_code ec;
    if (fs::is_directory(mPath, ec))
        throw IoError(mPath, "is a folder, not a file");
    // ".NAME.tmp-PID-N", built by appends: GCC 12 warns of a false overlap in `"." + std::string`.
    std::string name(1, '.');
    name.append(mPath.filename().string())
        .append(".tmp-")
        .append(std::to_string(::getpid()))
        .append("-")
        .append(std::to_string(gTemporaryCounter++));
    mTemporary = folder / name;
    mFile = std::fopen(mTemporary.c_str(), "wbx");
    if (!mFile)
        throw IoError(mPath,
                      "cannot create temporary file " + quoted(mTemporary) + ": " + errnoMessage(errno));
}

bool AtomicFileWriter::close() {
    const bool closed = mFile == stdout ? std::fflush(mFile) == 0 : std::fclose(mFile) == 0;
    mFile = nullptr;
    if (!mTemporary.empty()) {
        std::error_code ignored;
        fs::remove(mTemporary, ignored);
    }
    return closed;
}

AtomicFileWriter::~AtomicFileWriter() {
    if (mFile)
        close();
}

void AtomicFileWriter::fail(const std::string& problem) {
    close();
    throw IoError(mPath, problem);
}

void AtomicFileWriter::write(std::string_view text) {
    if (!mFile)
        throw IoError(mPath, "written after commit or after a failure");
    if (std::fwrite(text.data(), 1, text.size(), mFile) != text.size())
        fail("cannot write: " + errnoMessage(errno));
}

namespace {

std::mutex gBeforeReplaceMutex;
BeforeReplace gBeforeReplace;

void beforeReplace(const fs::path& path) {
    BeforeReplace hook;
    {
        const std::lock_guard lock(gBeforeReplaceMutex);
        hook = gBeforeReplace;
    }
    std::error_code ec;
    if (hook && fs::is_regular_file(fs::symlink_status(path, ec)))
        hook(path);
}

} // namespace

void setBeforeReplace(BeforeReplace hook) {
    const std::lock_guard lock(gBeforeReplaceMutex);
    gBeforeReplace = std::move(hook);
}

void AtomicFileWriter::commit() {
    if (!mFile)
        throw IoError(mPath, "committed twice or after a failure");
    if (mTemporary.empty()) { // a stream: flushed, and closed unless it is standard output
        if (!close())
            throw IoError(mPath, "cannot write: " + errnoMessage(errno));
        return;
    }
    // fsync before the rename: after a crash the path holds either the old file or the whole new one.
    if (std::fflush(mFile) != 0 || ::fsync(::fileno(mFile)) != 0)
        fail("cannot write: " + errnoMessage(errno));
    const int closed = std::fclose(mFile);
    mFile = nullptr;
    std::error_code ec;
    if (closed != 0) {
        fs::remove(mTemporary, ec);
        throw IoError(mPath, "cannot write: " + errnoMessage(errno));
    }
    try {
        beforeReplace(mPath);
    } catch (const IoError&) {
        std::error_code ignored;
        fs::remove(mTemporary, ignored);
        throw;
    }
    fs::rename(mTemporary, mPath, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(mTemporary, ignored);
        throw IoError(mPath, "cannot move the finished file into place: " + ec.message());
    }
}

bool namesStandardOutput(const fs::path& path) {
    struct stat target {};
    struct stat out {};
    return path == kStdoutPath || (::stat(path.c_str(), &target) == 0 && ::fstat(STDOUT_FILENO, &out) == 0 &&
                                   target.st_dev == out.st_dev && target.st_ino == out.st_ino);
}

bool isStreamOutput(const fs::path& path) {
    if (namesStandardOutput(path))
        return true;
    std::error_code ec;
    const fs::file_status target = fs::status(path, ec); // through links: /dev/stdout is one
    return !ec && fs::exists(target) && !fs::is_regular_file(target) && !fs::is_directory(target);
}

void requireWritableFile(const fs::path& path) {
    if (isStreamOutput(path))
        return;
    const fs::path folder = outputFolder(path);
    std::error_code ec;
    if (fs::is_directory(path, ec))
        throw IoError(path, "is a folder, not a file");
    // The atomic write renames a new file over the path: over a link that replaces the link, not what it
    // points to, and a device or pipe (/dev/stdout) would be replaced by a regular file.
    const fs::file_status link = fs::symlink_status(path, ec);
    if (!ec && fs::is_symlink(link))
        throw IoError(
            path, "is a symbolic link; writing would replace the link itself: name the file it points to");
    if (!ec && fs::exists(link) && !fs::is_regular_file(link))
        throw IoError(path, "is not a regular file (a device, pipe or socket): write to a file");
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        throw IoError(path, "folder " + quoted(folder) + " is not writable: " + errnoMessage(errno));
}

void writeTextFile(const fs::path& path, std::string_view text) {
    detail::writeAtomically(path, {reinterpret_cast<const unsigned char*>(text.data()), text.size()});
}

} // namespace photopic
