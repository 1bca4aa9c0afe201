#pragma once
// Image files as a viewer scene: one file is a still, several play as a sequence (one file per frame, in
// the order given, looping), each through the live pipeline with adaptation running across frames. EXR files
// bring their 3D layers (depth, normals, motion, object ids, the camera) as `photopic image` reads them: the
// same channel mapping (--aovs, --layer, --aov), camera track (--camera) and lens (--lens).

#include "ImageInputs.h"

#include "scenes/Scene.h"

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace photopic::viewer {

/// How the files are read: the CLI's channel mapping, camera track and lens.
struct FileInputs {
    AovRequest aovs;
    std::optional<cli::CameraTrack> cameras;
    cli::LensOverride lens;
    std::map<std::filesystem::path, std::int64_t> frameNumbers; ///< by which the track is looked up
};

/// Throws SceneInputError naming the file when the first one cannot be read (the others are read as they
/// play; one that fails then is reported once and skipped).
std::unique_ptr<Scene> makeFileScene(std::vector<std::filesystem::path> files, FileInputs inputs = {});

/// The size of the first file's image (for the window's initial size).
[[nodiscard]] Extent fileSceneExtent(const Scene& scene);

} // namespace photopic::viewer
