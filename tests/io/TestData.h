#pragma once
// Where the shared HDR test images live (see shared/data/SOURCES.md).

#include <cstdlib>
#include <filesystem>

#ifndef PHOTOPIC_SOURCE_DIR
#error "PHOTOPIC_SOURCE_DIR must name the repository root (the build defines it for tests)"
#endif

namespace photopic::test {

/// $PHOTOPIC_DATA_DIR when set, else ../shared/data next to the repository root.
inline std::filesystem::path dataDir() {
    if (const char* dir = std::getenv("PHOTOPIC_DATA_DIR"); dir != nullptr && *dir != '\0')
        return dir;
    return (std::filesystem::path(PHOTOPIC_SOURCE_DIR) / ".." / "shared" / "data").lexically_normal();
}

} // namespace photopic::test
