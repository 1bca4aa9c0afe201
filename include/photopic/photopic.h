#pragma once
/// @file photopic.h
/// Photopic's public API: HDR post-processing and eye adaptation for a host's OpenGL 4.5 renderer.
///
/// This header is the whole installed interface. It includes no GL header and no GL loader: GL object names
/// are plain `std::uint32_t` (GLuint), so a host keeps its own loader (glad, GLEW, libepoxy, GL/gl.h with
/// prototypes) and includes it before or after this header in any order. The library resolves its own GL
/// entry points for whatever context is current.
///
/// A frame, for a host that renders 3D:
/// @code
///   photopic::PostProcessor post({.settingsJson = json});     // once, with the host's context current
///   auto jitter = post.beginFrame(index, dt, &camera);            // add to the projection (optional: TAA)
///   auto lighting = post.renderLighting(frame);               // AO / contact shadows to shade with
///   ... host shades its HDR colour ...
///   post.execute(frame, photopic::FramebufferTarget{0, 0, 0, width, height}); // into the back buffer
/// @endcode
/// A host with a finished HDR image calls execute() alone. docs/integration.md walks through it.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#if defined(PHOTOPIC_STATIC)
#define PHOTOPIC_API
#elif defined(_WIN32)
#if defined(PHOTOPIC_BUILDING_LIBRARY)
#define PHOTOPIC_API __declspec(dllexport)
#else
#define PHOTOPIC_API __declspec(dllimport)
#endif
#else
/// Marks what the shared library exports.
#define PHOTOPIC_API __attribute__((visibility("default")))
#endif

/// Everything Photopic exports.
namespace photopic {

/// A GL object name (GLuint): a texture or a framebuffer the host owns. 0 is "none" (for a framebuffer:
/// the default framebuffer).
using GlName = std::uint32_t;

/// The library's version, "major.minor.patch".
PHOTOPIC_API const char* versionString() noexcept;

/// What the library throws at set-up boundaries (construction, settings): the message says what failed and
/// names the file, key or value. The per-frame calls do not throw for bad inputs; they report them in
/// Status::inputErrors.
class PHOTOPIC_API Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// How serious a log message is.
enum class LogSeverity { Debug, Info, Warning, Error };
/// Receives the library's log messages (degradations, input errors, GL debug output); `message` is valid for
/// the call only. May be called from any thread that calls the library.
using LogCallback = void (*)(LogSeverity severity, const char* message, void* user);
/// Routes the library's log to `callback` (nullptr: standard error, the default), with messages below
/// `minimum` dropped. Process-wide.
PHOTOPIC_API void setLogCallback(LogCallback callback, void* user = nullptr,
                                 LogSeverity minimum = LogSeverity::Info);

/// How the depth texture encodes distance.
enum class DepthEncoding {
    Standard,   ///< window depth in [0, 1] of a GL perspective projection: near -> 0, far -> 1
    Reversed,   ///< reversed-Z window depth (glClipControl zero-to-one): near -> 1, far or infinity -> 0
    LinearView, ///< R32F/R16F positive distance along the view axis in scene units; >= far or inf is sky
};

/// How the normals texture is stored. Normals are view-space unit vectors (right-handed, +z to the viewer).
enum class NormalsEncoding {
    ViewXyz,    ///< RGB(A)16F/32F holding x, y, z in [-1, 1]
    Octahedral, ///< RG16F/RG32F: octahedral encoding in [-1, 1]^2
};

/// A column-major 4x4 matrix, as glUniformMatrix4fv takes it with transpose = GL_FALSE (and as glm stores
/// one: `std::memcpy(m.data(), glm::value_ptr(x), 64)`).
using Matrix4 = std::array<float, 16>;

/// The identity matrix.
inline constexpr Matrix4 kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

/// A thin-lens model: depth of field, motion blur and physical exposure read it.
struct CameraLens {
    float focalLengthMm = 50.0f;    ///< mm, (0, 10000]
    float sensorHeightMm = 24.0f;   ///< mm, (0, 1000] (full frame: 24)
    float fNumber = 2.8f;           ///< aperture as an f-number, [0.5, 256]
    float focusDistance = 10.0f;    ///< scene units, > 0: the plane in focus
    float shutterAngleDeg = 180.0f; ///< degrees, [0, 360]: open time as a fraction of the frame
    float exposureTimeS = 0.0f;     ///< s, [0, 60]; 0: from the shutter angle and the frame time
    float iso = 100.0f;             ///< ISO sensitivity, [1, 1e6]
};

/// The host's camera, in GL conventions: right-handed view space looking down -z, +y up.
struct HostCamera {
    Matrix4 view = kIdentity;               ///< world -> view
    Matrix4 projection = kIdentity;         ///< view -> clip, unjittered (the library adds its own jitter)
    Matrix4 prevViewProjection = kIdentity; ///< last frame's unjittered projection * view
    float nearPlane = 0.1f;                 ///< scene units, > 0
    float farPlane = 1000.0f;               ///< scene units, > near; may be infinity
    float verticalFov = 1.0471976f;         ///< radians, (0, pi): the full vertical field of view
    CameraLens lens;                        ///< the lens: depth of field, motion blur, physical exposure
    bool cut = false; ///< a new shot or a teleport: histories are dropped, prevViewProjection ignored
};

/// A subject of the view (a token, a character): exposure can follow the light under it.
struct HostSubject {
    std::uint32_t id = 0;                      ///< the host's id, stable across frames
    std::array<float, 2> world{0.0f, 0.0f};    ///< world position (map units, y down)
    std::array<float, 2> screenUv{0.5f, 0.5f}; ///< image UV (u right, v down)
    std::optional<float> outdoors;             ///< 0..1 when the host knows it
    bool controlled = false;                   ///< the user controls it
    bool ownCharacter = false;                 ///< the user's own character
};

/// The light under a subject, as measured by the probe (a frame or more old: probes are never waited on).
struct SubjectLight {
    std::uint32_t id = 0;      ///< the subject's HostSubject::id
    float outdoors = 0.0f;     ///< 0..1
    float measuredLuma = 0.0f; ///< scene-linear luma under the subject; 0 before the first probe
    float targetLog2 = 0.0f;   ///< EV: the exposure that subject asks for
    float appliedLog2 = 0.0f;  ///< EV: the view's adapted exposure
    bool moving = false;       ///< it moved faster than the probe's threshold this frame
};

/// The sun's directional shadow map, for volumetric light's ray-marched in-scattering
/// (`volumetricLight.mode` shadowmap, or auto, which marches whenever a map is given). Any directional
/// shadow map fits: `worldToClip` takes a world point to the sun view's clip space (GL conventions: x, y, z
/// in [-1, 1] inside the map; an orthographic projection, w = 1; another w is divided out), and `depth`
/// holds at (u, v) = (x, y) * 0.5 + 0.5 the nearest caster's standard depth z * 0.5 + 0.5 (0 on the near
/// plane, the sun's side; 1 on the far plane), as a depth pass with glDepthRange(0, 1) writes it. Points
/// outside the map count as lit. The library reads the map with its own sampler (the texture's filtering and
/// comparison state are not used or changed).
struct SunShadow {
    /// DEPTH_COMPONENT16/24/32/32F or DEPTH24_STENCIL8/DEPTH32F_STENCIL8, any size; 0: no map.
    GlName depth = 0;
    Matrix4 worldToClip = kIdentity; ///< world -> the sun view's clip space; finite and invertible
    /// Linear Rec.709 illuminance of the sunlight arriving at the scene on a plane facing the sun (its
    /// radiance times its solid angle), in the colour texture's units, >= 0: the light the air scatters.
    std::array<float, 3> illuminance{1.0f, 1.0f, 1.0f};
};

/// What the host hands the library each frame. Textures are the host's, borrowed for the call: their size
/// and format are read from GL. Everything but `color` is optional; an effect that needs a missing input is
/// skipped and reported in Status::skipped. Every texture but `sunShadow.depth` has colour's size.
struct Frame {
    GlName color = 0; ///< scene-referred linear Rec.709 colour, a float format (RGBA16F, R11F_G11F_B10F...)
    GlName depth = 0; ///< depth buffer or linear view depth
    DepthEncoding depthEncoding = DepthEncoding::Standard;      ///< how `depth` encodes distance
    GlName normals = 0;                                         ///< view-space unit normals
    NormalsEncoding normalsEncoding = NormalsEncoding::ViewXyz; ///< how `normals` is stored
    /// RG16F/RG32F: UV-space displacement of each pixel, current minus previous, jitter removed
    /// (uv_prev = uv - motion). Without it, motion comes from depth and the camera (static scenes only).
    GlName motion = 0;
    /// RGBA16F/RGBA32F/RGBA8: specular F0 (RGB) and perceptual roughness (A), for reflections.
    GlName material = 0;
    GlName objectId = 0;                ///< R8UI/R16UI/R32UI object ids (0: sky), for contact-shadow masks
    const HostCamera* camera = nullptr; ///< needed by the 3D effects
    /// World space, towards the sun: the direction contact shadows and volumetric light use.
    std::optional<std::array<float, 3>> sunDirection;
    /// The sun's shadow map (with `sunDirection`): volumetric light marches it; `depth` 0: no map.
    SunShadow sunShadow;
    std::span<const HostSubject> subjects; ///< this frame's subjects; read during the call, not kept
    /// Time comes from the host, never from a wall clock, so frames are deterministic.
    float dt = 1.0f / 60.0f;      ///< s since the previous frame
    std::uint64_t frameIndex = 0; ///< increases by one per frame; drives jitter, dither and grain
};

/// The optional inputs of a Frame, for PostProcessor::inputsRead(): those a frame carries, or those its
/// passes read.
struct FrameInputSet {
    bool depth = false;        ///< Frame::depth
    bool normals = false;      ///< Frame::normals
    bool motion = false;       ///< Frame::motion
    bool material = false;     ///< Frame::material
    bool objectId = false;     ///< Frame::objectId
    bool camera = false;       ///< Frame::camera
    bool sunDirection = false; ///< Frame::sunDirection
    bool sunShadow = false;    ///< Frame::sunShadow

    /// The same inputs.
    friend bool operator==(const FrameInputSet&, const FrameInputSet&) = default;
};

/// Which image execute() delivers.
enum class Output {
    /// Tone mapped, output-transformed and dithered: display-referred values, sRGB-encoded (RGBA8). Copy the
    /// bytes as they are: into an RGBA8 target, or an SRGB8_ALPHA8 one with GL_FRAMEBUFFER_SRGB off.
    Display,
    /// For hosts that tone map themselves: the exposed, bloomed and graded scene-referred image just before
    /// the tone curve, linear Rec.709 (RGBA32F). Write it to a float target.
    LinearHdr,
};

/// A rectangle of one of the host's framebuffers (0: the default framebuffer) to draw the output into. The
/// image is scaled to the rectangle (nearest when the sizes match, bilinear otherwise); what lies outside
/// is left alone. The framebuffer's current draw buffers receive it.
struct FramebufferTarget {
    GlName framebuffer = 0; ///< the host's framebuffer; 0: the default framebuffer
    int x = 0;              ///< lower-left corner, pixels
    int y = 0;              ///< lower-left corner, pixels
    int width = 0;          ///< pixels; 0: the output's own width
    int height = 0;         ///< pixels; 0: the output's own height
};

/// One of the host's textures (level 0) to write the output into, scaled to its size. Colour-renderable
/// formats only: RGBA8, SRGB8_ALPHA8 (bytes written as they are), RGBA16F, RGBA32F, R11F_G11F_B10F...
struct TextureTarget {
    GlName texture = 0; ///< the host's 2D texture
};

/// What the lighting stage hands the host for shading; a name is 0 when that effect did not run.
struct Lighting {
    /// R8/R16F visibility in [0, 1] for indirect light only (ambient, IBL): multiply by
    /// pow(visibility, ambientOcclusionPower).
    GlName ambientOcclusion = 0;
    float ambientOcclusionPower = 1.0f; ///< the exponent for ambientOcclusion (the ssao.power setting)
    GlName contactShadows = 0;          ///< R8/R16F visibility in [0, 1] for the sun's direct light only
};

/// One pass's GPU time, from timer queries read a few frames late (never stalling).
struct PassTime {
    std::string name;          ///< the pass's name, as in Status::ran
    double milliseconds = 0.0; ///< GPU time between its first and last command
};

/// What the library is doing: degradations are never silent.
struct Status {
    bool hdrPath = true;                  ///< false: the LDR fallback runs (see pathReason)
    std::string pathReason;               ///< why the path was chosen
    std::vector<std::string> ran;         ///< passes the last frame ran, in order
    std::vector<std::string> skipped;     ///< "pass: why" for passes the frame needed but could not run
    std::vector<std::string> inputErrors; ///< inputs the last frame ignored, each naming the input
    std::vector<PassTime> passTimes;      ///< the newest frame with GPU timings
};

/// Exposure state, from an asynchronous readback a frame or more old.
struct Telemetry {
    bool valid = false;         ///< false until the first record arrived
    std::uint64_t frame = 0;    ///< Frame::frameIndex it came from
    float meteredLuminance = 0; ///< the scene's metered luminance (scene-linear)
    float targetLog2 = 0;       ///< EV the adaptation is heading for
    float appliedLog2 = 0;      ///< EV applied this frame
    float exposure = 1;         ///< the total multiplier applied to the frame
    bool adapting = false;      ///< still moving towards the target
};

/// The post-processing chain. Every call needs a current OpenGL 4.5 context, the same one (or one sharing
/// objects with it) for the object's whole life, on one thread at a time. Each call saves the GL state it
/// touches and depends on, sets what it needs and restores the host's state before it returns
/// (docs/integration.md lists it): the host's scissor, masks, culling, polygon mode, blending, depth,
/// stencil, sRGB writes and bindings neither change the output nor are changed.
class PHOTOPIC_API PostProcessor {
public:
    /// How to create a PostProcessor.
    struct CreateInfo {
        /// Settings as JSON ({"version": 1, "preset": "stills", "postEffects": {...}}, what `photopic
        /// settings --defaults` prints). A preset (stills, realtime, neutral) sets the look first and the
        /// document's own keys land over it. Empty: the defaults (the realtime look).
        std::string settingsJson;
        bool forceLdr = false; ///< take the 8-bit LDR path whatever the GPU can do
    };

    /// Compiles the passes. Throws Error when there is no usable GL 4.5 context, or for invalid settings
    /// (every issue, by JSON path).
    explicit PostProcessor(const CreateInfo& info);
    ~PostProcessor();
    PostProcessor(PostProcessor&&) noexcept;            ///< moves the chain; the source is left empty
    PostProcessor& operator=(PostProcessor&&) noexcept; ///< moves the chain; the source is left empty
    PostProcessor(const PostProcessor&) = delete;
    PostProcessor& operator=(const PostProcessor&) = delete;

    /// Replaces every setting with `json` over the defaults. Throws Error naming every issue; the
    /// settings in use do not change then.
    void setSettingsJson(std::string_view json);
    /// Changes one setting, "path=value" below postEffects ("bloom.intensity=0.1", "tonemapping.mode=agx").
    /// Throws Error naming the key or value; nothing changes then.
    void setSetting(std::string_view assignment);
    /// Every setting as JSON; setSettingsJson(settingsJson()) changes nothing.
    [[nodiscard]] std::string settingsJson() const;

    /// Starts a frame (3D hosts): the sub-pixel jitter in pixels (x right, y up) to add to this frame's
    /// projection; zero unless a temporal effect asks for it. A camera with `cut` set drops the histories.
    std::array<float, 2> beginFrame(std::uint64_t frameIndex, float dt, const HostCamera* camera = nullptr);
    /// Adds `jitter` (pixels, from beginFrame) to a projection matrix for a width x height target.
    [[nodiscard]] static Matrix4 jitteredProjection(const Matrix4& projection, std::array<float, 2> jitter,
                                                    int width, int height) noexcept;

    /// Lighting stage (3D hosts, after beginFrame, before shading): ambient occlusion and contact shadows
    /// from the frame's depth and normals. The textures stay valid until the next call.
    Lighting renderLighting(const Frame& frame);

    /// Runs the post chain on the frame and returns the output as a texture the library owns (RGBA8 for
    /// Display, RGBA32F for LinearHdr), valid until the next call. A frame without usable colour gives a 1x1
    /// black image and an input error; never throws for bad inputs.
    GlName execute(const Frame& frame, Output output = Output::Display);
    /// Runs the chain and draws the output into the host's framebuffer rectangle.
    void execute(const Frame& frame, const FramebufferTarget& target, Output output = Output::Display);
    /// Runs the chain and writes the output into the host's texture.
    void execute(const Frame& frame, const TextureTarget& target, Output output = Output::Display);

    /// Of the inputs a frame carries (`offered`), those its passes will read at the current settings, with
    /// the lighting stage's when the host calls renderLighting() for the frame (`lighting`). A host may stop
    /// rendering and handing over the others (a normals or motion-vector pass, say) until the settings
    /// change: nothing reads them, so the images are the same. Plans only: no GL work, nothing changes.
    [[nodiscard]] FrameInputSet inputsRead(const FrameInputSet& offered, bool lighting = false);

    /// The next frame's exposure snaps to its target (a camera cut, a teleport).
    void resetExposure() noexcept;
    /// A new shot: exposure snaps and every temporal history is dropped on the next frame.
    void reset() noexcept;

    /// The newest exposure telemetry that has arrived, without blocking.
    [[nodiscard]] Telemetry telemetry();
    /// What the last frame ran, skipped and ignored, and the newest GPU timings.
    [[nodiscard]] Status status() const;
    /// The light under subject `id` registered in the last frame, or nothing.
    [[nodiscard]] std::optional<SubjectLight> subjectContext(std::uint32_t id) const;
    /// The subject the view follows (controlled, else own character, else the screen centre), or nothing.
    [[nodiscard]] std::optional<SubjectLight> viewSubject() const;

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

/// An OpenGL 4.5 core context without a window (EGL: a GPU when there is one, else Mesa's software
/// renderer), for offline hosts and tests. Interactive hosts use their own context instead.
class PHOTOPIC_API HeadlessGlContext {
public:
    /// Creates the context and makes it current on this thread. Throws Error saying what was tried.
    HeadlessGlContext();
    ~HeadlessGlContext();
    HeadlessGlContext(const HeadlessGlContext&) = delete;
    HeadlessGlContext& operator=(const HeadlessGlContext&) = delete;

    /// Makes the context current on this thread.
    void makeCurrent() const;
    /// The GL renderer string, e.g. "NVIDIA H100 80GB HBM3/PCIe/SSE2" or "llvmpipe (LLVM 15.0.6, 256 bits)".
    [[nodiscard]] std::string renderer() const;

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace photopic
