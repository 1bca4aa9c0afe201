#pragma once
// `photopic image --camera FILE`: a camera given as JSON (docs/camera-json.md) for EXR frames without camera
// attributes, one for every frame or a track of cameras keyed by frame number (tools/blender writes one from
// Blender). GL-free: the fuzz target links it alone.

#include "core/Camera.h"

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace photopic::cli {

/// A camera given as JSON (docs/camera-json.md): GL conventions, the projection built per frame size.
struct CameraJson {
    glm::vec3 position{0.0f};
    glm::vec3 target{0.0f, 0.0f, -1.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    /// Camera space (GL: -z forward, +y up) to world, rigid; replaces position/target/up when given.
    std::optional<glm::mat4> cameraToWorld;
    float verticalFovDeg = 60.0f; ///< degrees, (0, 180)
    /// A physical camera's projection, replacing verticalFovDeg when `focalLengthMm` is given: the sensor
    /// dimension the fit names spans that side of the frame ("auto": the sensor width spans the larger side),
    /// and `shift` moves the view window by fractions of that side (x right, y up).
    struct Sensor {
        enum class Fit { Auto, Horizontal, Vertical };
        float widthMm = 36.0f;
        float heightMm = 24.0f;
        Fit fit = Fit::Auto;
    };
    std::optional<float> focalLengthMm;
    Sensor sensor;
    glm::vec2 shift{0.0f};
    float nearPlane = 0.1f;   ///< scene units, > 0
    float farPlane = 1000.0f; ///< scene units, > near; omitted or null in the file: infinite
    Lens lens;
    std::optional<glm::vec3> sunDirection; ///< world, towards the sun; finite, non-zero

    /// The camera for a `width` x `height` frame (aspect from the frame; prevViewProjection = this frame's).
    [[nodiscard]] Camera camera(int width, int height) const;
};

/// `--camera FILE`: one camera for every frame, or {"frames": {"N": camera, ...}} keyed by the inputs' frame
/// numbers (docs/camera-json.md).
struct CameraTrack {
    std::optional<CameraJson> single;
    std::map<std::int64_t, CameraJson> frames;
    std::optional<float> fps; ///< the track's frame rate, when it says (informational: --fps sets the run's)
    std::filesystem::path path;

    /// The camera of frame `number` (any, for a single camera); throws InputError naming the file, the
    /// frame and `input` when the track has no entry for it, or `input` has no frame number.
    [[nodiscard]] const CameraJson& at(std::optional<std::int64_t> number,
                                       const std::filesystem::path& input) const;
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

/// A camera file as a track: one camera (parseCameraJson's document) or {"fps": N, "source": "...",
/// "frames": {"N": camera, ...}}; errors name the file, the frame and the key.
[[nodiscard]] CameraTrack parseCameraTrack(std::string_view text, const std::filesystem::path& name);
/// parseCameraTrack on the file's text.
[[nodiscard]] CameraTrack loadCameraTrack(const std::filesystem::path& path);

} // namespace photopic::cli
