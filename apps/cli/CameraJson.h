#pragma once
// `photopic image --camera FILE`: a camera given as JSON (docs/camera-json.md) for EXR frames without camera
// attributes. GL-free: the fuzz target links it alone.

#include "core/Camera.h"

#include <filesystem>
#include <string_view>

namespace photopic::cli {

/// A camera given as JSON (docs/camera-json.md): GL conventions, the projection built per frame size.
struct CameraJson {
    glm::vec3 position{0.0f};
    glm::vec3 target{0.0f, 0.0f, -1.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float verticalFovDeg = 60.0f; ///< degrees, (0, 180)
    float nearPlane = 0.1f;       ///< scene units, > 0
    float farPlane = 1000.0f;     ///< scene units, > near; omitted or null in the file: infinite
    Lens lens;

    /// The camera for a `width` x `height` frame (aspect from the frame; prevViewProjection = this frame's).
    [[nodiscard]] Camera camera(int width, int height) const;
};

/// The widest and the tallest frame parseCameraJson checks its camera for: no GPU takes a texture longer
/// than this side, and a frame's aspect is all the camera takes from its size.
inline constexpr int kCameraJsonMaxSide = 65536;

/// Parses and validates a camera JSON document; `name` names it in errors. Throws InputError, its message
/// starting with `name`, naming the key that is wrong (unknown, of the wrong type, outside its range, or
/// giving a view or projection that is not finite in single precision). A camera it returns gives, for
/// every frame with sides in [1, kCameraJsonMaxSide], a camera that invalidCameraReason accepts.
[[nodiscard]] CameraJson parseCameraJson(std::string_view text, const std::filesystem::path& name);

/// parseCameraJson on the file's text; throws InputError naming the file when it cannot be read.
[[nodiscard]] CameraJson loadCameraJson(const std::filesystem::path& path);

} // namespace photopic::cli
