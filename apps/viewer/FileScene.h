#pragma once
// Image files as a viewer scene: one file is a still, several play as a sequence (one file per frame, in
// the order given, looping), each through the live pipeline with adaptation running across frames.

#include "scenes/Scene.h"

#include <filesystem>
#include <memory>
#include <vector>

namespace photopic::viewer {

/// Throws SceneInputError naming the file when the first one cannot be read (the others are read as they
/// play; one that fails then is reported once and skipped).
std::unique_ptr<Scene> makeFileScene(std::vector<std::filesystem::path> files);

/// The size of the first file's image (for the window's initial size).
[[nodiscard]] Extent fileSceneExtent(const Scene& scene);

} // namespace photopic::viewer
