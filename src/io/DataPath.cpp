#include "io/DataPath.h"

#include "core/Environment.h"

#include <fmt/format.h>

#include <stdexcept>
#include <system_error>

// The build passes these three paths (CMakeLists.txt); the fallbacks keep the file compilable on its own.
#ifndef PHOTOPIC_DATA_RELATIVE_TO_BINDIR
#define PHOTOPIC_DATA_RELATIVE_TO_BINDIR "../share/photopic/data"
#endif
#ifndef PHOTOPIC_INSTALL_DATA_DIR
#define PHOTOPIC_INSTALL_DATA_DIR ""
#endif
#ifndef PHOTOPIC_SOURCE_DATA_DIR
#define PHOTOPIC_SOURCE_DATA_DIR ""
#endif

namespace photopic {

namespace fs = std::filesystem;

namespace {

bool isDir(const fs::path& path) {
    std::error_code ec;
    return !path.empty() && fs::is_directory(path, ec);
}

bool pathExists(const fs::path& path) {
    std::error_code ec;
    return fs::exists(path, ec);
}

fs::path executableDir() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::path{} : exe.parent_path();
}

// The nearest ancestor of the current directory (itself included) that is a Photopic checkout: it has
// data/SOURCES.md and src/io/DataPath.h. Both are needed so an unrelated data/ folder up the tree is not
// taken.
fs::path checkoutDataDir() {
    std::error_code ec;
    fs::path dir = fs::current_path(ec);
    if (ec) {
        return {};
    }
    for (;;) {
        if (pathExists(dir / "data" / "SOURCES.md") && pathExists(dir / "src" / "io" / "DataPath.h")) {
            return dir / "data";
        }
        if (!dir.has_parent_path() || dir.parent_path() == dir) {
            return {};
        }
        dir = dir.parent_path();
    }
}

// The flag, else the environment variable; an empty path when neither is given.
DataDirCandidate explicitChoice(const fs::path& explicitDir) {
    if (!explicitDir.empty()) {
        return {explicitDir, "--data"};
    }
    if (const auto env = environmentValue("PHOTOPIC_DATA_DIR")) {
        return {fs::path(*env), "PHOTOPIC_DATA_DIR"};
    }
    return {};
}

} // namespace

std::vector<DataDirCandidate> dataDirCandidates(const fs::path& explicitDir) {
    if (DataDirCandidate choice = explicitChoice(explicitDir); !choice.path.empty()) {
        return {std::move(choice)};
    }
    std::vector<DataDirCandidate> candidates;
    if (const fs::path exeDir = executableDir(); !exeDir.empty()) {
        candidates.push_back(
            {(exeDir / PHOTOPIC_DATA_RELATIVE_TO_BINDIR).lexically_normal(), "installed share folder"});
    }
    if (fs::path checkout = checkoutDataDir(); !checkout.empty()) {
        candidates.push_back({std::move(checkout), "checkout around the current directory"});
    }
    candidates.push_back({PHOTOPIC_INSTALL_DATA_DIR, "configured install prefix"});
    candidates.push_back({PHOTOPIC_SOURCE_DATA_DIR, "source tree"});
    std::erase_if(candidates, [](const DataDirCandidate& c) { return c.path.empty(); });
    return candidates;
}

fs::path findDataDir(const fs::path& explicitDir) {
    if (DataDirCandidate choice = explicitChoice(explicitDir); !choice.path.empty()) {
        return choice.path;
    }
    std::string tried;
    for (const DataDirCandidate& c : dataDirCandidates()) {
        if (isDir(c.path)) {
            return c.path;
        }
        tried += fmt::format("\n  {} ({})", c.path.string(), c.origin);
    }
    throw std::runtime_error(fmt::format(
        "no Photopic data folder found (pass --data DIR or set PHOTOPIC_DATA_DIR); tried:{}", tried));
}

} // namespace photopic
