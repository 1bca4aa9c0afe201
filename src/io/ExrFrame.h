#pragma once
// A renderer's EXR frame with the 3D layers Photopic's passes use: colour, depth, normals, motion and the
// camera, in the conventions renderers write (docs/architecture.md, "EXR input"):
// - depth: channel `Z` (or `depth.Z`), linear view depth in scene units; the background at or beyond the far
//   plane, or infinite;
// - normals: `N.X`/`N.Y`/`N.Z` (or `normal.X/Y/Z`), world space;
// - motion: `motion.X`/`motion.Y`, pixels, current minus previous position, x right, y down in file rows;
// - camera: the standard attributes `worldToCamera` and `worldToNDC` (Imath row-vector matrices; OpenEXR
// camera
//   space is left-handed with +z forward, its NDC has (0, 0) at the top-left and (1, 1) at the bottom-right
//   of the display window), `focus` (m), `aperture` (f-number), `expTime` (s), `isoSpeed`, and, when present,
//   the lens attributes `pinholeFocalLength` (mm), `sensorOverallDimensions` (mm), `shutterAngle` (degrees)
//   and `jitter` (v2f, pixels: the sample's offset from the pixel centre, x right, y down).

#include "core/Camera.h"
#include "core/Image.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace photopic {

/// Camera attributes as stored in the file (matrices in Imath's row-vector layout: m[row][col], p' = p * M).
struct ExrCameraAttributes {
    std::optional<glm::mat4> worldToCamera;
    std::optional<glm::mat4> worldToNDC;
    std::optional<float> focus;                       ///< m
    std::optional<float> aperture;                    ///< f-number
    std::optional<float> expTime;                     ///< s
    std::optional<float> isoSpeed;                    ///< ISO
    std::optional<float> pinholeFocalLength;          ///< mm
    std::optional<glm::vec2> sensorOverallDimensions; ///< mm
    std::optional<float> shutterAngle;                ///< degrees
    std::optional<glm::vec2> jitter;                  ///< pixels, x right, y down
    std::optional<float> nearClip; ///< scene units (`nearClipPlane`, when a renderer writes it)
    std::optional<float> farClip;  ///< scene units (`farClipPlane`)
};

/// One EXR frame with its optional 3D layers, each row-major, rows top to bottom like ImageF.
struct ExrFrame {
    ImageF color;
    std::vector<float> depth;   ///< width*height linear view depth; empty when the file has none
    std::vector<float> normals; ///< width*height*3 world-space normals; empty when none
    std::vector<float>
        motion; ///< width*height*2 pixels (x right, y down), current minus previous; empty when none
    ExrCameraAttributes camera;
    std::vector<std::string> channels; ///< every channel of the first part, as named in the file
};

/// Reads colour as readImage does, plus the layers and attributes above when present. Throws IoError naming
/// the file.
[[nodiscard]] ExrFrame readExrFrame(const std::filesystem::path& path);
/// Writes colour (half RGBA), Z (float), N.X/Y/Z (half), motion.X/Y (float) for the layers that are not
/// empty, and the camera attributes that are set. Atomic, like writeExr.
void writeExrFrame(const std::filesystem::path& path, const ExrFrame& frame);

/// The file's camera attributes in a `width` x `height` frame as the pipeline's Camera (GL conventions);
/// `previous`, the previous frame's attributes in a sequence, gives prevViewProjection (else the current
/// view-projection). Nothing when the file has no worldToCamera/worldToNDC pair; throws IoError-free
/// std::invalid_argument with the reason when the matrices are not invertible or not finite.
[[nodiscard]] std::optional<Camera> cameraFromExr(const ExrCameraAttributes& attributes, int width,
                                                  int height, const ExrCameraAttributes* previous = nullptr);
/// The inverse of cameraFromExr for the attributes a renderer writes (worldToCamera, worldToNDC, focus,
/// aperture, expTime, isoSpeed, pinholeFocalLength, sensorOverallDimensions, shutterAngle, near/far clip).
[[nodiscard]] ExrCameraAttributes exrFromCamera(const Camera& camera, int width, int height);

} // namespace photopic
