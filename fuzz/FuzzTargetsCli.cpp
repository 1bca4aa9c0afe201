// Entry point for the CLI's own GL-free reader: the camera JSON of `photopic image --camera FILE`.

#include "FuzzTargets.h"

#include "CameraJson.h"
#include "InputError.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace photopic::fuzz {

namespace {

[[noreturn]] void broken(const std::string& what) {
    std::fprintf(stderr, "fuzz target: promise broken: %s\n", what.c_str());
    std::abort();
}

constexpr std::string_view kName = "fuzz-camera.json";

} // namespace

void cameraJson(const std::uint8_t* data, std::size_t size) {
    cli::CameraTrack track;
    try {
        track = cli::parseCameraTrack({reinterpret_cast<const char*>(data), size}, kName);
    } catch (const cli::InputError& e) {
        if (!std::string_view(e.what()).starts_with(kName))
            broken(std::string("the error does not start with the file's name: ") + e.what());
        return;
    }
    // Every camera of the track (or the one) at every frame shape it may be asked for: the extreme aspects
    // bound every entry of the matrices.
    std::vector<const cli::CameraJson*> cameras;
    if (track.single)
        cameras.push_back(&*track.single);
    for (const auto& [frame, camera] : track.frames)
        cameras.push_back(&camera);
    constexpr int kMax = cli::kCameraJsonMaxSide;
    for (const cli::CameraJson* camera : cameras) {
        for (const auto& [width, height] : {std::pair{1, 1}, {16, 9}, {kMax, 1}, {1, kMax}, {kMax, kMax}}) {
            if (const char* reason = invalidCameraReason(camera->camera(width, height)))
                broken("an accepted camera at " + std::to_string(width) + "x" + std::to_string(height) +
                       ": " + reason);
        }
    }
}

} // namespace photopic::fuzz
