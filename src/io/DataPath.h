#pragma once
// Where Photopic's data folder (the HDR images and glTF models of data/) is found, by the CLI and the tests
// alike.

#include <filesystem>
#include <string>
#include <vector>

namespace photopic {

/// One place the data lookup tries, and why it is on the list.
struct DataDirCandidate {
    std::filesystem::path path; ///< the folder that would hold Desk.exr, gltf/, ...
    std::string origin;         ///< e.g. "--data", "PHOTOPIC_DATA_DIR", "installed share folder"
};

/// The places the data folder may be, in the order they are tried:
/// 1. `explicitDir` when not empty (a command-line flag), else `$PHOTOPIC_DATA_DIR` when set and not empty:
/// either
///    is the only candidate, so a wrong explicit choice is reported rather than silently replaced.
/// 2. The installed share folder beside the running executable: `<exe dir>/../share/photopic/data` for the
///    layout `cmake --install` writes, found from /proc/self/exe so a relocated install tree still works.
/// 3. The Photopic checkout that contains the current directory (the nearest ancestor with `data/SOURCES.md`
/// and
///    this header), so binaries run from inside a copy of the repository read that copy's data.
/// 4. The install prefix the library was configured with (`<prefix>/share/photopic/data`).
/// 5. The source tree the library was built from (`<source>/data`).
/// Steps 2 and 3 describe where the program is running; 4 and 5 are paths baked in at build time, which may
/// name another tree (or none, once it is deleted), so they come last.
std::vector<DataDirCandidate> dataDirCandidates(const std::filesystem::path& explicitDir = {});

/// The first candidate of dataDirCandidates() that is an existing folder; an explicit choice (flag or
/// environment) is returned as given even when it does not exist, so the caller's error names it. Throws
/// std::runtime_error naming every place tried when none exists.
std::filesystem::path findDataDir(const std::filesystem::path& explicitDir = {});

} // namespace photopic
