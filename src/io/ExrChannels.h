#pragma once
// Which channels of an OpenEXR file feed colour, depth, normals, motion, ambient occlusion and object ids,
// and in which conventions: a renderer preset (photopic, blender), a layer, and the user's per-kind
// overrides (`photopic image --aovs NAME --layer NAME --aov KIND=CHANNELS[:CONVENTIONS]`). GL-free; the
// user's manual is docs/interop.md.

#include <array>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace photopic {

/// What a channel can feed.
enum class Aov { Color, Depth, Normals, Motion, Ao, ObjectId };
inline constexpr std::size_t kAovCount = 6;
/// "color", "depth", "normals", "motion", "ao", "objectid": the KIND of `--aov KIND=...`.
[[nodiscard]] const char* aovName(Aov aov);

/// How the file stores what it stores. The reader turns everything into Photopic's own conventions (planar
/// depth, Y-up world or GL view-space normals, motion in pixels as current minus previous, x right, y down,
/// unjittered); `depth` and `normals` that need the camera are turned by the caller that has it.
struct AovConventions {
    enum class Depth {
        Planar, ///< distance along the view axis (OpenEXR's Z, Blender's Depth)
        Radial, ///< distance from the camera's centre (a ray's length)
    };
    enum class Normals {
        World,    ///< world space, Y up (OpenGL's, Photopic's)
        WorldZUp, ///< world space, Z up (Blender, 3ds Max): (x, y, z) is Y-up (x, z, -y)
        Camera,   ///< GL view space: x right, y up, +z towards the viewer
    };
    enum class MotionUnits {
        Pixels, ///< pixels of the data window
        Ndc,    ///< [-1, 1] across the frame: pixels = value * size / 2
        Uv,     ///< [0, 1] across the frame: pixels = value * size
    };
    /// Which displacement the vector is.
    enum class MotionSense {
        CurrentMinusPrevious, ///< where the point is minus where it was (Photopic, Unreal)
        PreviousMinusCurrent, ///< the way to the previous frame's position (Blender's first pair)
        NextMinusCurrent,     ///< the way to the next frame's position, read as constant velocity
        CurrentMinusNext,     ///< the way back from the next frame's position (Blender's second pair)
    };
    Depth depth = Depth::Planar;
    Normals normals = Normals::World;
    MotionUnits motionUnits = MotionUnits::Pixels;
    MotionSense motionSense = MotionSense::CurrentMinusPrevious;
    bool motionYUp = false;      ///< false: y grows down the rows, as the file stores them
    bool motionJittered = false; ///< measured between the frames' jittered samples, not their surfaces
    int motionPair = 1;          ///< of 4-channel motion: 1 = the first two channels, 2 = the last two
};

/// A renderer's naming and conventions.
enum class AovPreset {
    Photopic, ///< R G B A, Z, N.X/Y/Z (or normal.*), motion.X/Y: Photopic's own files and --write-aux
    Blender,  ///< Cycles and EEVEE multilayer: <layer>.Combined, .Depth, .Normal, .Vector, .AO, .IndexOB
};
[[nodiscard]] const char* aovPresetName(AovPreset preset);

/// `--aov KIND=CHANNELS[:CONVENTIONS]`, parsed: the channels (full names, names within the layer, or one
/// prefix that the kind's components complete) and the convention words given.
struct AovOverride {
    Aov kind = Aov::Color;
    std::vector<std::string> channels;   ///< empty: the kind is left out ("--aov motion=none")
    std::vector<std::string> convention; ///< words, checked against the kind by parseAovOverride
    bool none = false;                   ///< "none": the file's channels of this kind are not read
};

/// What the user asked for. Default: the preset the file calls for, its only layer.
struct AovRequest {
    /// --aovs; nothing: blender when the file says Blender wrote it (its BlenderMultiChannel attribute, or
    /// only <layer>.Combined colour and no R, G, B), else photopic
    std::optional<AovPreset> preset;
    std::string layer; ///< --layer; empty: the only layer, or the unprefixed one
    std::vector<AovOverride> overrides;
};

/// The channels chosen for one file. Colour has 3 or 4 names (R, G, B[, A]) or 1 (Y); depth, ao and objectId
/// 1; normals 3; motion 2 (the pair chosen); empty when the file has none or the user said none.
struct AovChannels {
    AovPreset preset = AovPreset::Photopic;
    std::string layer; ///< the layer chosen ("" when the channels are unprefixed)
    std::array<std::vector<std::string>, kAovCount> channels;
    AovConventions conventions;
    /// Of 4-channel motion, the pair not read (motion's other channels), for --info; else empty.
    std::vector<std::string> otherMotionPair;
    /// Where each kind came from ("photopic preset", "blender preset", "--aov"), for --info.
    std::array<std::string, kAovCount> origin;

    [[nodiscard]] const std::vector<std::string>& of(Aov aov) const { return channels[std::size_t(aov)]; }
    [[nodiscard]] bool has(Aov aov) const { return !of(aov).empty(); }
    /// The kind a channel feeds, or nothing.
    [[nodiscard]] std::optional<Aov> feeds(std::string_view channel) const;
};

/// An --aov, --aovs or --layer value that cannot be used, or a file whose channels do not fit what was
/// asked. The message names the value (and the channels or layers there are).
class AovError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Parses `--aov` text, e.g. "depth=ViewLayer.Depth.Z:radial", "motion=Vector:pixels,previous-minus-current,
/// y-up,pair=1", "normals=N" or "motion=none". Throws AovError naming the text and the bad part.
[[nodiscard]] AovOverride parseAovOverride(std::string_view text);
/// "photopic" or "blender"; throws AovError listing the names.
[[nodiscard]] AovPreset parseAovPreset(std::string_view name);

/// The file's layers as the preset sees them: for blender the view layers (the first part of
/// `<layer>.<pass>.<channel>` names), for photopic the prefixes P of P.R/P.G/P.B colour ("" for R, G, B).
[[nodiscard]] std::vector<std::string> aovLayers(const std::vector<std::string>& channels, AovPreset preset);

/// The channels `request` picks from a file with `channels` (its channel names, in the file's order);
/// `blenderMultiChannel`: the file carries Blender's BlenderMultiChannel attribute (the preset then defaults
/// to blender, as it does for a file whose only colour is <layer>.Combined: Blender leaves the attribute
/// out of a file with no other pass). Throws AovError: several layers and no --layer (listing them), a
/// --layer the file lacks, an
/// --aov channel the file lacks, a layer without colour, a kind with some of its components missing.
[[nodiscard]] AovChannels resolveAovs(const std::vector<std::string>& channels, bool blenderMultiChannel,
                                      const AovRequest& request);

} // namespace photopic
