#include "Outputs.h"

#include "Commands.h"

#include "io/ImageIO.h"

#include <fmt/format.h>

namespace photopic::cli {

namespace fs = std::filesystem;

RunOutputs::~RunOutputs() {
    if (mCommitted) {
        return;
    }
    std::error_code ignored;
    for (const fs::path& file : mFiles) {
        fs::remove(file, ignored);
    }
    for (std::size_t i = 0; mSequenceName && i < mSequenceCount; ++i) {
        fs::remove(mSequenceName(i), ignored);
    }
    for (auto it = mCreatedFolders.rbegin(); it != mCreatedFolders.rend(); ++it) {
        if (fs::is_empty(*it, ignored)) {
            fs::remove(*it, ignored);
        }
    }
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
