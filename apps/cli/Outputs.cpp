#include "Outputs.h"

#include "Commands.h"

#include "io/ImageIO.h"

#include <fmt/format.h>

#include <unistd.h>

namespace photopic::cli {

namespace fs = std::filesystem;

RunOutputs::RunOutputs() {
    setBeforeReplace([this](const fs::path& path) { moveAside(path); });
}

RunOutputs::~RunOutputs() {
    setBeforeReplace({});
    std::error_code ignored;
    if (mCommitted) {
        for (const std::string& path : mReplaced) {
            fs::remove(previousCopy(path), ignored);
        }
        return;
    }
    for (const fs::path& file : mFiles) {
        fs::remove(file, ignored);
    }
    for (std::size_t i = 0; mSequenceName && i < mSequenceCount; ++i) {
        fs::remove(mSequenceName(i), ignored);
    }
    // Files replaced by frames whose write was still in flight are put back too: moveAside listed them.
    for (const std::string& path : mReplaced) {
        fs::rename(previousCopy(path), path, ignored);
    }
    for (auto it = mCreatedFolders.rbegin(); it != mCreatedFolders.rend(); ++it) {
        if (fs::is_empty(*it, ignored)) {
            fs::remove(*it, ignored);
        }
    }
}

fs::path RunOutputs::previousCopy(const fs::path& path) {
    // ".NAME.previous-PID", built by appends: GCC 12 warns of a false overlap in `"." + std::string`.
    std::string name(1, '.');
    name.append(path.filename().string()).append(".previous-").append(std::to_string(::getpid()));
    return path.parent_path() / name;
}

void RunOutputs::moveAside(const fs::path& path) {
    const std::lock_guard lock(mReplacedMutex);
    if (mReplaced.contains(path.string())) {
        return; // this run's own file, written twice: its first version need not come back
    }
    std::error_code ec;
    fs::rename(path, previousCopy(path), ec);
    if (ec) {
        throw IoError(path, fmt::format("cannot move the existing file aside to {} before replacing it: {}",
                                        previousCopy(path).filename().string(), ec.message()));
    }
    mReplaced.insert(path.string());
}

void RunOutputs::makeFolder(const fs::path& folder) {
    // Walk down from the outermost missing folder, so that each one this run makes is known and can go again.
    std::vector<fs::path> missing;
    std::error_code ec;
    for (fs::path p = folder; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
        missing.push_back(p);
        if (p == p.parent_path()) {
            break;
        }
    }
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
        if (!fs::create_directory(*it, ec) && ec) {
            throw InputError(fmt::format("output folder \"{}\": cannot create \"{}\": {}", folder.string(),
                                         it->string(), ec.message()));
        }
        mCreatedFolders.push_back(*it);
    }
    if (!fs::is_directory(folder, ec)) {
        throw InputError(fmt::format("output folder \"{}\" is not a folder", folder.string()));
    }
}

void RunOutputs::requireFile(const fs::path& path) {
    try {
        requireWritableFile(path);
    } catch (const IoError& e) {
        throw InputError(fmt::format("output {}", e.what()));
    }
}

void RunOutputs::wrote(const fs::path& path) {
    if (isStreamOutput(path)) {
        return; // standard output, a device or a pipe: nothing to take back, and never to be removed
    }
    mFiles.push_back(path);
}

} // namespace photopic::cli
