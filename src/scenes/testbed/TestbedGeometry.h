#pragma once
// The testbed's analytic scene: one description, read by the GL rasteriser (TestbedRenderer, through
// testbed_shading.h.glsl, its GLSL twin) and by the CPU ray tracer (TestbedRaytracer). No GL here.
//
// World space: metres, right-handed, +y up; the ground's top is the plane y = 0. Every primitive is a rigid
// shape (sphere, box, capped cylinder along its local y) placed by a rotation + translation, so the same
// object-space intersection serves both renderers, and the previous frame's placement of the same object
// point gives its motion.
//
// Shading is LOCAL (no shadows, no occlusion, no reflections): for a surface with albedo a, metallic m and
// emission e, unit normal N and the sun's direction L,
//   colour = a (1 - m) (E_sun max(N.L, 0) V_sun + E_amb(N) V_amb) / pi + e
// where E_sun is the sun's illuminance at normal incidence, E_amb(N) = mix(E_ground, E_sky, 0.5 + 0.5 N.y)
// the hemispherical ambient irradiance, and V_sun, V_amb visibility factors that are 1 here: a lighting
// stage plugs its sun-visibility (contact shadows) and ambient-occlusion textures in there, and the ray
// tracer's `sun` and `ao` truths are their references. The background is a sky gradient plus the sun's disc
// of radiance E_sun / (pi r^2) inside its angular radius r.

#include "core/Camera.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace photopic::testbed {

enum class Shape : std::uint32_t {
    Sphere = 0,   ///< centred on the origin, radius size.x
    Box = 1,      ///< centred on the origin, half extents size
    Cylinder = 2, ///< capped, along local y: radius size.x, half height size.y
};

struct Material {
    glm::vec3 albedo{0.5f};
    glm::vec3 albedo2{0.5f};  ///< the checker's second colour (used when checker > 0)
    float checker = 0.0f;     ///< m, checker square size in object space; 0: plain albedo
    float metallic = 0.0f;    ///< [0, 1]; the diffuse weight is 1 - metallic
    float roughness = 0.5f;   ///< [0, 1], for glossy passes (SSR); the local model is diffuse
    glm::vec3 emissive{0.0f}; ///< scene-linear radiance added as is
};

/// One object at one instant.
struct Primitive {
    std::uint32_t id = 0; ///< >= 1 (0 is the sky); stable across frames, for outlines and edge masks
    Shape shape = Shape::Sphere;
    glm::vec3 size{1.0f};
    glm::mat4 toWorld{1.0f};     ///< object -> world at this instant (rigid)
    glm::mat4 toObject{1.0f};    ///< its inverse
    glm::mat4 prevToWorld{1.0f}; ///< object -> world one frame earlier (motion vectors)
    Material material;
    glm::vec3 boundCentre{0.0f}; ///< world-space bounding sphere
    float boundRadius = 0.0f;
};

/// The sky and the sun.
struct Environment {
    glm::vec3 sunDirection{0.0f, 1.0f, 0.0f}; ///< unit, towards the sun
    glm::vec3 sunIlluminance{1.0f};           ///< scene-linear illuminance at normal incidence
    float sunAngularRadius = 0.02f;           ///< radians (the real sun's is 0.0047; larger to be seen)
    glm::vec3 skyZenith{0.0f};                ///< radiance straight up
    glm::vec3 skyHorizon{0.0f};               ///< radiance at the horizon
    glm::vec3 groundRadiance{0.0f};           ///< below the horizon
    glm::vec3 ambientSky{0.0f};               ///< irradiance on an upward-facing surface
    glm::vec3 ambientGround{0.0f};            ///< irradiance on a downward-facing surface
};

/// The shots of the camera path. Shot 0: a pan (0 .. kPanEnd s), then a dolly in (.. kCutTime s); a cut to
/// shot 1: a low camera looking towards the sun through the grid of poles, panning slowly.
inline constexpr double kPanEnd = 0.6;
inline constexpr double kCutTime = 1.2; ///< s: frame 36 at 30 fps is the first of shot 1
inline constexpr float kNear = 0.1f;
inline constexpr float kFar = 400.0f;
inline constexpr float kVerticalFov = 0.78539816f; ///< 45 degrees

/// The eye, orientation and focus of the path at `seconds` (for times < 0, time 0).
struct CameraPose {
    glm::vec3 position{0.0f};
    float yaw = 0.0f;   ///< radians, turning left (towards -x) from looking down -z
    float pitch = 0.0f; ///< radians, up
    float focusDistance = 10.0f;
    int shot = 0;
};
[[nodiscard]] CameraPose cameraPoseAt(double seconds);
[[nodiscard]] glm::mat4 viewMatrix(const CameraPose& pose);

/// The Camera for the pipeline at path time `seconds` on a `width` x `height` target: unjittered projection,
/// prevViewProjection at `prevSeconds` (the previous frame's path time), and `cut` on the first frame of a
/// shot, whose previous camera is then its own (motion is the objects' alone). `lens` gives the f-number,
/// shutter and ISO; its focal length follows the field of view and its focus distance the path's.
[[nodiscard]] Camera testbedCamera(double seconds, double prevSeconds, int width, int height,
                                   const Lens& lens = {});

/// A clock of the scene: path time = start + rate * frame time (rate 0 holds it at `start`).
struct Clock {
    double start = 0.0; ///< s
    double rate = 1.0;  ///< path seconds per second of frame time, >= 0
};

/// The camera's and the objects' times in one frame and the one before it, and their rates (the shutter
/// interval, in frame time, maps to rate x interval of path time).
struct FrameTimes {
    double camera = 0.0;
    double prevCamera = 0.0;
    double objects = 0.0;
    double prevObjects = 0.0;
    double cameraRate = 1.0;
    double objectRate = 1.0;
};
/// Frame `frameIndex` at interval `dt` (frame time = frameIndex * dt; frame 0's previous frame is itself).
[[nodiscard]] FrameTimes frameTimes(std::uint64_t frameIndex, double dt, const Clock& camera = {},
                                    const Clock& objects = {});

[[nodiscard]] const Environment& environment();
/// Every object at `seconds`, with its placement at `prevSeconds` (the previous frame) as prevToWorld.
[[nodiscard]] std::vector<Primitive> primitivesAt(double seconds, double prevSeconds);

/// Named objects (ids) tests look for.
namespace ids {
inline constexpr std::uint32_t kGround = 1;
inline constexpr std::uint32_t kWall = 2;
inline constexpr std::uint32_t kStrip = 3;
inline constexpr std::uint32_t kBigSphere = 4;
inline constexpr std::uint32_t kSmallSphere = 5;
inline constexpr std::uint32_t kCube = 6;
inline constexpr std::uint32_t kTallBox = 7;
inline constexpr std::uint32_t kSpinner = 8;
inline constexpr std::uint32_t kMover = 9;
inline constexpr std::uint32_t kFirstPole = 10; ///< poles, then the fence's posts and wires
} // namespace ids

// ---- analytic queries shared by the ray tracer and mirrored in testbed_shading.h.glsl ----

struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f}; ///< unit
};

struct Hit {
    float t = 0.0f;
    int primitive = -1;           ///< index into the primitive list; -1: sky
    glm::vec3 objectPoint{0.0f};  ///< hit point in object space
    glm::vec3 objectNormal{0.0f}; ///< unit, object space
    glm::vec3 worldNormal{0.0f};  ///< unit
};

/// Nearest hit of `ray` with `prim` in (tMin, tMax); false when none.
bool intersect(const Primitive& prim, const Ray& ray, float tMin, float tMax, Hit& hit);
/// Nearest hit over every primitive in (tMin, tMax).
bool intersectScene(const std::vector<Primitive>& prims, const Ray& ray, float tMin, float tMax, Hit& hit);
/// Any hit in (tMin, tMax).
bool occluded(const std::vector<Primitive>& prims, const Ray& ray, float tMin, float tMax);

/// The albedo at an object-space point (checker in object space, on the face's tangent axes for boxes).
[[nodiscard]] glm::vec3 albedoAt(const Primitive& prim, const glm::vec3& objectPoint,
                                 const glm::vec3& objectNormal);
/// The local shading model above, with both visibility factors given.
[[nodiscard]] glm::vec3 shadeLocal(const Primitive& prim, const Hit& hit, float sunVisibility = 1.0f,
                                   float ambientVisibility = 1.0f);
/// The background along a unit direction: sky gradient, ground colour below the horizon, the sun's disc.
[[nodiscard]] glm::vec3 skyRadiance(const glm::vec3& direction);
/// Radiance along a camera ray: the local shading of its nearest hit, else the sky.
[[nodiscard]] glm::vec3 radiance(const std::vector<Primitive>& prims, const Ray& ray);

/// The primary ray through a point in NDC (x right, y up, [-1, 1]) of `camera` (world-space origin at the
/// eye, unit direction), using its (unjittered) projection.
[[nodiscard]] Ray cameraRay(const Camera& camera, glm::vec2 ndc);
/// Motion of a world point on object `prim` (or of a sky direction when prim is null): UV of the point now
/// minus UV of the same object point one frame earlier through camera.prevViewProjection.
[[nodiscard]] glm::vec2 motionUv(const Camera& camera, const Primitive* prim, const glm::vec3& worldPoint,
                                 const glm::vec3& skyDirection);

} // namespace photopic::testbed
