#pragma once
// Where the tests find their inputs: the images of data/ (data/SOURCES.md) and the test-only files of
// tests/data/.

#include "io/DataPath.h"

#include <filesystem>

#ifndef PHOTOPIC_SOURCE_DIR
#error "PHOTOPIC_SOURCE_DIR must name the repository root (the build defines it for tests)"
#endif

namespace photopic::test {

/// The data folder as the CLI finds it (photopic::findDataDir): $PHOTOPIC_DATA_DIR when set, else the
/// checkout around the current directory, else this source tree's data/.
inline std::filesystem::path dataDir() {
    return findDataDir();
}

/// Test-only inputs (malformed glTF, fuzzing reproducers): tests/data/ of this source tree.
inline std::filesystem::path testInputDir() {
    return std::filesystem::path(PHOTOPIC_SOURCE_DIR) / "tests" / "data";
}

} // namespace photopic::test
