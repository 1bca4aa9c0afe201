#pragma once
// A renderer's EXR frame with the 3D layers Photopic's passes use: colour, depth, normals, motion, object ids
// and the camera. Which channels feed which, and their conventions, come from io/ExrChannels.h (a preset, a
// layer, --aov overrides; docs/interop.md); the reader turns them into these:
// - depth: linear depth in scene units, planar unless the mapping says radial (the caller, who has the
//   camera, turns radial depth planar); the background at or beyond the far plane, or infinite;
// - normals: world space, Y up (Z-up files are turned), or GL view space when the mapping says camera;
// - motion: pixels, current minus previous position, x right, y down in file rows; jittered only when the
//   mapping says so;
// - object ids: one float channel holding integers (Cycles' IndexOB);
// - camera: the standard attributes `worldToCamera` and `worldToNDC` (Imath row-vector matrices; OpenEXR
//   camera space is left-handed with +z forward, its NDC has (0, 0) at the top-left and (1, 1) at the
//   bottom-right of the display window), `focus` (m), `aperture` (f-number), `expTime` (s), `isoSpeed`, and,
//   when present, the lens attributes `pinholeFocalLength` (mm), `sensorOverallDimensions` (mm),
//   `shutterAngle` (degrees), `nearClipPlane`/`farClipPlane` (scene units) and `jitter` (v2f, pixels: the
//   offset of the frame's samples from the pixel centres, x right, y down);
// - sun: `sunDirection` (v3f, world space, pointing towards the sun; Photopic's own attribute): the light
//   contact shadows march towards and volumetric light scatters from.
// `worldToNDC` is the unjittered projection; `jitter` says how the samples (and so the motion vectors) were
// moved. Its z row, when it is a projective depth, follows RenderMan: z_ndc = 0 at the near plane and 1 at
// the far plane (z_ndc = f (z - n) / (z (f - n)) for camera depth z).
//
// Attribute types: matrices m44f (m44d accepted), scalars float (double accepted), vectors v2f/v3f (v2d/v3d
// accepted); an attribute of any other type is an error, not silently ignored.

#include "core/Camera.h"
#include "core/Image.h"
#include "io/ExrChannels.h"
#include "io/ImageIO.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace photopic {

/// Camera attributes as stored in the file. Matrices are copied element for element from Imath's row-vector
/// matrices (m[i][j] = M[i][j]); read as glm's column-vector matrices they are the same transforms: glm's
/// m * p is Imath's p * M.
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
    std::optional<float> nearClip;         ///< scene units (`nearClipPlane`, when a renderer writes it)
    std::optional<float> farClip;          ///< scene units (`farClipPlane`)
    std::optional<glm::vec3> sunDirection; ///< world space, towards the sun (`sunDirection`)
};

/// One EXR frame with its optional 3D layers, each row-major, rows top to bottom like ImageF.
struct ExrFrame {
    ImageF color; ///< the colour, unless `colorHalves` holds it (then empty)
    /// The colour as the file stores it, when read by an ExrFrameReader that keeps halves and the file's
    /// colour is halves with nothing to convert (detail::exrColorIsHalves): the same values as `color` would
    /// hold, in half the memory; `color` is then empty. Empty otherwise.
    ImageH colorHalves;
    std::vector<float> depth;   ///< width*height linear view depth; empty when the file has none
    std::vector<float> normals; ///< width*height*3 world-space normals; empty when none
    std::vector<float>
        motion; ///< width*height*2 pixels (x right, y down), current minus previous; empty when none
    std::vector<float> objectId; ///< width*height object ids as stored (integers); empty when none
    ExrCameraAttributes camera;
    /// The channels read for each kind and the file's conventions (of which the reader has applied those of
    /// motion and of Z-up normals; radial depth, camera-space normals and jittered motion are the caller's).
    AovChannels aovs;
    /// Every channel, as the mapping names it: a single-part file's as they are; in a multi-part file the
    /// first part's as they are and another part's bare names (no '.') behind its part's name ("depth.Z").
    std::vector<std::string> channels;
    /// A multi-part file's parts by name ("(part N)" for one without), in file order; empty for one part.
    std::vector<std::string> parts;
    /// Every attribute of the first part's header (of a multi-part file, the colour's part) as
    /// "name (type)", in the header's (alphabetical) order.
    std::vector<std::string> attributes;
    /// The display window's size and the data window's top-left corner in it: the layers above hold the
    /// data window (like readImage), while worldToNDC refers to the display window.
    glm::ivec2 displaySize{0, 0};
    glm::ivec2 dataOrigin{0, 0};
    /// Every colour channel read (R, G, B, A or Y; luminance/chroma, which OpenEXR converts in half) is
    /// stored as half, and the file's primaries are Rec.709 (others are converted to it in float): each
    /// colour value is a half float exactly, so a half-float texture holds it unchanged.
    bool halfColor = false;

    /// The colour's size, whichever of `color` and `colorHalves` holds it.
    [[nodiscard]] int width() const { return color.empty() ? colorHalves.width : color.width; }
    [[nodiscard]] int height() const { return color.empty() ? colorHalves.height : color.height; }
};

/// Reads colour as readImage does, plus the layers and attributes above when present, in one pass: each
/// layer the file has holds the colour's width*height pixels, the display window has at least one pixel.
/// The channels are the file's own preset's (Blender's when it carries BlenderMultiChannel), of its only
/// layer; several layers are an IoError listing them (ExrFrameReader::setAovs picks one).
/// Values are kept as stored (NaN, infinite), the attributes too except `jitter`, which is finite. Throws
/// IoError naming the file for anything readImage rejects, a layer with some of its components missing
/// (N.X and N.Y without N.Z), a camera attribute of the wrong type and a non-finite `jitter`.
[[nodiscard]] ExrFrame readExrFrame(const std::filesystem::path& path, const ImageReadLimits& limits = {},
                                    const AovRequest& aovs = {});
/// readExrFrame on bytes in memory; `name` only names the source in errors. Any byte string gives a frame
/// or an IoError (the fuzzers hold it to that).
[[nodiscard]] ExrFrame decodeExrFrame(std::span<const unsigned char> bytes, const std::filesystem::path& name,
                                      const ImageReadLimits& limits = {});

/// readExrFrame for a sequence: each frame is read into storage kept from the one before (the file's bytes
/// here, the layers in the ExrFrame passed in), so after its first frame a sequence of one size allocates
/// no pixel memory: no page faults, no clearing of buffers that are overwritten anyway.
class ExrFrameReader {
public:
    /// How the colour is kept: always as floats (`color`), or as halves (`colorHalves`) when the file's
    /// colour is halves with nothing to convert, else as floats.
    enum class Color { Floats, HalvesWhenStored };
    explicit ExrFrameReader(Color color = Color::Floats)
        : mColor(color) {}
    /// The 3D layers read when the file has them (all, unless set otherwise): a layer left out stays empty
    /// in the frames read after this call, though its channels are still checked (a layer with some of its
    /// components missing is an error either way) and listed in `channels`.
    struct Layers {
        bool depth = true;
        bool normals = true;
        bool motion = true;
        bool objectId = true;
    };
    void setLayers(Layers layers) { mLayers = layers; }
    /// Which channels feed what (io/ExrChannels.h): resolved for each file read after this call, an
    /// AovError becoming an IoError naming the file. Default: the file's own preset and only layer.
    void setAovs(AovRequest request) { mAovs = std::move(request); }

    /// readExrFrame into `frame`, every field replaced; its vectors' capacity is reused. On IoError
    /// `frame` is left empty (as a default ExrFrame, its capacity kept), never half filled.
    void read(const std::filesystem::path& path, ExrFrame& frame, const ImageReadLimits& limits = {});
    /// read() on bytes in memory (`name` only names them in errors), into the same kept storage.
    void decode(std::span<const unsigned char> bytes, const std::filesystem::path& name, ExrFrame& frame,
                const ImageReadLimits& limits = {});

private:
    std::vector<unsigned char> mBytes;
    Color mColor;
    Layers mLayers;
    AovRequest mAovs;
};
/// Writes colour (half RGBA: `color` rounded, or `colorHalves` as they are when `color` is empty), Z (float),
/// N.X/Y/Z (half), motion.X/Y (float) for the layers that are not
/// empty, and the camera attributes that are set; data window = display window = the colour image (the
/// displaySize/dataOrigin fields are not written). Atomic, like writeExr; throws IoError naming the file when
/// a layer's size does not match the colour.
void writeExrFrame(const std::filesystem::path& path, const ExrFrame& frame);
/// writeExrFrame's file as bytes in memory; `name` only names the frame in errors.
[[nodiscard]] std::string encodeExrFrame(const ExrFrame& frame, const std::filesystem::path& name);

/// The file's camera attributes as the pipeline's Camera (GL conventions) for the file's display window
/// (`width` x `height` pixels, which the NDC conversion does not need but the arguments are checked);
/// `previous`, the previous frame's attributes in a sequence, gives prevViewProjection (else the current
/// view-projection). Nothing when the file has no worldToCamera/worldToNDC pair. Throws std::invalid_argument
/// naming the attribute when the matrices are not finite or not invertible, worldToNDC is not a perspective
/// projection of camera space, or a lens attribute is out of Lens's range.
///
/// view = diag(1, 1, -1, 1) * worldToCamera (left-handed +z forward -> right-handed -z forward).
/// projection: K = worldToNDC * inverse(worldToCamera) * diag(1, 1, -1, 1) maps GL view space to OpenEXR
/// NDC; scaled so that its w row is (0, 0, -1, 0), its x and y rows become 2x - w and w - 2y (GL NDC,
/// y up) and its z row is GL's for near/far. near/far: the nearClipPlane/farClipPlane attributes when
/// present, else solved from K's z row read as RenderMan's NDC depth (0 at near, 1 at far; a row that gives
/// no 0 < near < far is ignored), else near 0.1 and far +inf. verticalFov = 2 atan(1 / projection[1][1]).
/// The lens: pinholeFocalLength and sensorOverallDimensions.y when present; one of them alone gives the
/// other through the field of view; neither: a 24 mm sensor height.
/// `jitter` is not applied: worldToNDC is taken as unjittered.
[[nodiscard]] std::optional<Camera> cameraFromExr(const ExrCameraAttributes& attributes, int width,
                                                  int height, const ExrCameraAttributes* previous = nullptr);
/// The camera for the pixels readExrFrame returned: cameraFromExr over `frame`'s display window, cropped to
/// its data window (dataWindowCrop, on projection and prevViewProjection) where the two differ. Nothing when
/// the frame has no camera; throws std::invalid_argument as cameraFromExr does, and when the cropped camera
/// is not finite (a display window far larger than the data window, with a projection near the float range).
[[nodiscard]] std::optional<Camera> frameCamera(const ExrFrame& frame,
                                                const ExrCameraAttributes* previous = nullptr);
/// The inverse of cameraFromExr for the attributes a renderer writes (worldToCamera, worldToNDC, focus,
/// aperture, expTime when the lens sets one, isoSpeed, pinholeFocalLength, sensorOverallDimensions from the
/// sensor height and the width/height aspect, shutterAngle, nearClip/farClip). worldToNDC's z row is
/// RenderMan's NDC depth for the camera's near/far, so cameraFromExr recovers them without the clip
/// attributes. jitter is left unset.
[[nodiscard]] ExrCameraAttributes exrFromCamera(const Camera& camera, int width, int height);

/// The matrix that takes GL clip coordinates over the display window to GL clip coordinates over the data
/// window (identity when they are the same): left-multiply a projection by it to render only the pixels
/// readExrFrame returned.
[[nodiscard]] glm::mat4 dataWindowCrop(glm::ivec2 displaySize, glm::ivec2 dataOrigin, glm::ivec2 dataSize);

} // namespace photopic
