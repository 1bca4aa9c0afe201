#pragma once
// `photopic image`'s 3D inputs: EXR frames decoded into the pipeline's conventions (linear view depth,
// view-space normals, UV motion with jitter removed, a GL camera), the camera JSON for files without camera
// attributes, the GL textures they are uploaded to, `--info` and `--write-aux`.

#include "CameraJson.h"

#include "core/Camera.h"
#include "core/Image.h"
#include "gl/Objects.h"
#include "gl/UploadRing.h"
#include "io/ExrFrame.h"
#include "pipeline/Pipeline.h"

#include <cstdint>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace photopic::cli {

/// One input frame in the pipeline's conventions, rows top to bottom like ImageF.
struct DecodedFrame {
    ImageF color; ///< the colour, unless `colorHalves` holds it (then empty)
    /// The colour as an EXR of half channels stores it (values that are halves exactly, nothing to convert):
    /// half the memory of `color`, which is then empty. Empty otherwise.
    ImageH colorHalves;
    std::vector<float> depth;   ///< width*height linear view depth (inf or >= far: background); or empty
    std::vector<float> normals; ///< width*height*3 view-space unit normals; or empty
    std::vector<float> motion; ///< width*height*2 UV (y up), current minus previous, jitter removed; or empty
    std::vector<float> objectId; ///< width*height object ids (integers as floats); or empty
    std::optional<Camera> camera;
    /// World space, towards the sun: the EXR's `sunDirection` attribute (finite, non-zero), else none.
    std::optional<glm::vec3> sunDirection;
    /// The frame's samples were jittered: it carries a `jitter` attribute, or the sequence was rendered with
    /// Photopic's Halton(2, 3) jitter (--jitter halton).
    bool jittered = false;

    [[nodiscard]] bool halfColor() const { return !colorHalves.empty(); }
    [[nodiscard]] int width() const { return halfColor() ? colorHalves.width : color.width; }
    [[nodiscard]] int height() const { return halfColor() ? colorHalves.height : color.height; }
};

/// `--lens fNumber=N,focus=D,shutter=DEG`: lens values that replace the file's (or the camera track's).
struct LensOverride {
    std::optional<float> fNumber;         ///< [0.5, 256]
    std::optional<float> focusDistance;   ///< scene units, > 0
    std::optional<float> shutterAngleDeg; ///< [0, 360]
    [[nodiscard]] bool empty() const { return !fNumber && !focusDistance && !shutterAngleDeg; }
};
/// Parses --lens text; throws InputError naming the key or value.
[[nodiscard]] LensOverride parseLensOverride(const std::string& text);

/// Decodes a sequence in order, remembering the previous frame's camera attributes (prevViewProjection and
/// the previous jitter). Layers that need a camera the frame lacks are dropped with one warning per run.
class InputDecoder {
public:
    /// `haltonCycle` > 0: frames without a `jitter` attribute were rendered with Halton(2, 3) jitter of that
    /// cycle, from index 1 for the first frame (the jitter Pipeline::beginFrame hands out).
    /// `maxPixels`: larger inputs are refused before they are decoded.
    explicit InputDecoder(std::optional<CameraTrack> cameras = std::nullopt, int haltonCycle = 0,
                          std::int64_t maxPixels = kDefaultMaxPixels);
    /// The Halton index of the first frame decoded: its place in its sequence (a chunk of a sequence
    /// starts where the chunk starts, so its frames get the single run's jitter). 0 by default.
    void setFirstIndex(std::uint64_t index) { mIndex = index; }
    /// Each input's frame number, by which a camera track (--camera) is looked up: the pattern's, else the
    /// last number in the file name. A file not here has none.
    void setFrameNumbers(std::map<std::filesystem::path, std::int64_t> numbers) {
        mFrameNumbers = std::move(numbers);
    }
    /// Lens values that replace each frame's camera's (--lens).
    void setLens(LensOverride lens) { mLens = lens; }
    /// Which channels feed what (--aovs, --layer, --aov), for every file decoded after this call.
    void setAovs(AovRequest request) { mReader.setAovs(std::move(request)); }
    /// Throws InputError naming the file for unreadable files and bad camera attributes.
    [[nodiscard]] DecodedFrame decode(const std::filesystem::path& path);
    /// Gives back a frame decode() returned and the caller is done with: the next decode() reads into its
    /// storage instead of allocating (and clearing) a frame's worth of memory.
    void recycle(DecodedFrame&& frame);
    /// The 3D layers the decodes that start after this call read (all until then): those the pipeline's
    /// passes read. May be called from another thread than the one decoding.
    void readLayers(ExrFrameReader::Layers layers);
    /// Frees the layers of `frame` that readLayers() left out: a frame whose decode started before the
    /// call has them all.
    void leaveOutUnread(DecodedFrame& frame);

private:
    /// What readLayers() was told last, under its lock.
    [[nodiscard]] ExrFrameReader::Layers layersRead();
    /// An HDR or PNG file (or a missing one): colour only, through readImage's errors.
    [[nodiscard]] DecodedFrame decodeColorOnly(const std::filesystem::path& path);
    /// The EXR file into mFrame, its unread layers' storage given back.
    void readExr(const std::filesystem::path& path);
    /// mFrame's camera (its attributes, else the track's) into `out`, with --lens; returns the track's sun.
    [[nodiscard]] std::optional<glm::vec3> takeCamera(const std::filesystem::path& path, DecodedFrame& out);
    /// mFrame's depth (planar), object ids and normals (view space) into `out`, each skipped with a warning
    /// where it needs a camera there is none of.
    void takeDepthAndNormals(const std::filesystem::path& path, DecodedFrame& out);
    /// The file's jitter attribute, else the Halton jitter's sample offset; none for an unjittered frame.
    [[nodiscard]] std::optional<glm::vec2> frameJitter() const;
    /// The file's sunDirection attribute, checked, else the track's.
    [[nodiscard]] std::optional<glm::vec3> sunDirection(const std::filesystem::path& path,
                                                        std::optional<glm::vec3> trackSun) const;

    ExrFrameReader mReader{ExrFrameReader::Color::HalvesWhenStored};
    /// The storage decode() reads into; its layers move out to the caller (normals and motion converted
    /// in place) and come back through recycle().
    ExrFrame mFrame;
    /// `camera`'s lens with --lens's values.
    void applyLens(Camera& camera) const;
    /// The camera for `path` from the track, its prevViewProjection the previous frame's track camera, and
    /// the track's sun direction; nothing without a track.
    [[nodiscard]] std::optional<Camera> trackCamera(const std::filesystem::path& path, int width, int height,
                                                    std::optional<glm::vec3>& sun);

    std::optional<CameraTrack> mCameras;
    LensOverride mLens;
    std::map<std::filesystem::path, std::int64_t> mFrameNumbers;
    std::optional<glm::mat4> mPreviousTrackViewProjection; ///< the last frame's, when it came from the track
    std::optional<ExrCameraAttributes> mPrevious;
    std::optional<glm::vec2> mPreviousJitter; ///< pixels, x right, y down
    int mHaltonCycle = 0;
    std::int64_t mMaxPixels = kDefaultMaxPixels;
    std::mutex mLayersMutex;        ///< readLayers() may come from another thread than decode()
    ExrFrameReader::Layers mLayers; ///< readLayers(); all at first
    std::uint64_t mIndex = 0;
    bool mFirst = true;
};

/// The GL textures frames are uploaded to: created when the extent (or the set of layers) changes, and
/// re-uploaded every frame otherwise, so a sequence creates textures only for its first frame. Each frame's
/// texels go through a persistently mapped unpack buffer (gl/UploadRing.h, one slot): written there in
/// GL's row order (the half-float textures' texels as halves, rounded to nearest here rather than by the
/// driver, whose roundings differ between drivers and between its own paths), then one glTextureSubImage2D
/// a texture, which the GPU copies while the CPU moves on.
class InputTextures {
public:
    /// Uploads `frame` and returns inputs pointing at the textures and camera held here (valid until the
    /// next upload). `halfTexture`: the colour texture is RGBA16F instead of RGBA32F; only for a frame whose
    /// colour is halves (colorHalves) and a pipeline whose only reader of it fetches texels (the HDR
    /// path's sanitize pass), which then reads the same values from half the memory. Leaves no unpack
    /// buffer bound.
    [[nodiscard]] FrameInputs upload(const DecodedFrame& frame, bool halfTexture = false);

private:
    /// The upload slot, holding `bytes` at least, mapped for this frame's texels.
    [[nodiscard]] std::byte* beginSlot(std::size_t bytes);
    /// A layer this frame lacks gives its texture back.
    void releaseMissingLayers(const DecodedFrame& frame);

    /// One. A frame's copies from the slot are queued before its passes, and the next frame is written
    /// there only once this one's passes are submitted and the next frame decoded: the wait is for the
    /// copies alone, which are done by then (on llvmpipe a copy is done when its call returns). A second
    /// slot waited for nothing and held another frame's texels: 16 MB of half colour at 1080p, 33 of float.
    static constexpr int kUploadSlots = 1;
    UploadRing mRing;
    Texture mColor;
    Texture mDepth;
    Texture mNormals;
    Texture mMotion;
    Texture mObjectId;
    Camera mCamera;
    std::vector<std::uint16_t> mHalfRow; ///< a row of normals as halves, before they are spread to four
    std::vector<float> mFloatRow;        ///< a row of half colour widened, for a float texture
};

/// --aovs, --layer and --aov as the reader takes them; throws InputError naming a bad value.
[[nodiscard]] AovRequest aovRequest(const std::string& preset, const std::string& layer,
                                    const std::vector<std::string>& overrides);

/// Whether `path` starts as an OpenEXR file does (its magic number), whatever its name.
[[nodiscard]] bool isExr(const std::filesystem::path& path);

/// `photopic image --info`: the channels and attributes of each input and what each feeds under `aovs`.
int runImageInfo(const std::vector<std::filesystem::path>& inputs, const std::filesystem::path& cameraJson,
                 const AovRequest& aovs = {},
                 const std::map<std::filesystem::path, std::int64_t>& numbers = {});

/// `--write-aux DIR`: DIR/<input stem>.aux.exr with colour, Z (linear view depth), N.X/Y/Z (view space),
/// motion.X/Y (UV, y up) and the camera's attributes, for the layers the frame has. Returns the file's path.
std::filesystem::path writeAux(const std::filesystem::path& folder, const std::filesystem::path& input,
                               const DecodedFrame& frame);

/// The depth, normals and motion layers are decoded and uploaded only where a pass reads them: before the
/// first upload the pipeline plans what its passes read for every combination of the inputs a frame may
/// carry (each layer, the camera and the sun direction there or not), so a later frame that carries more or
/// fewer of them still finds what it needs, and the settings stay the same. A frame decoded before this
/// (the first) loses the others before its upload. Otherwise they cost up to 24 bytes a pixel on the CPU
/// and 16 on the GPU for nothing.
void readOnlyLayersRead(InputDecoder& decoder, Pipeline& pipeline, const DecodedFrame& first);

} // namespace photopic::cli
