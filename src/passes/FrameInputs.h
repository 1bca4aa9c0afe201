#pragma once
// What a host hands the pipeline each frame: its colour, optionally depth, normals, motion vectors, the
// camera and subjects, and the frame's time. docs/architecture.md ("Inputs") draws the conventions.

#include "core/Camera.h"
#include "core/Subjects.h"
#include "gl/Objects.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <span>

namespace photopic {

/// The formats a motion input may have (the pipeline refuses others). A pass that loads motion as an image
/// builds a program per format: an image is declared in its texture's format.
inline constexpr GLenum kMotionFormats[] = {GL_RG16F, GL_RG32F, GL_RGBA16F, GL_RGBA32F};

/// How a depth input encodes distance (docs/architecture.md, "Inputs").
enum class DepthKind {
    Standard,   ///< window depth in [0, 1] of a GL perspective projection: near -> 0, far -> 1
    Reversed,   ///< reversed-Z window depth (glClipControl zero-to-one): near -> 1, far or infinity -> 0
    LinearView, ///< R32F/R16F: positive distance along the view axis in scene units; >= far or inf = sky
};

/// How a normals input is stored. Normals are view-space unit vectors (right-handed, +z towards the viewer).
enum class NormalEncoding {
    ViewXyz,    ///< RGB(A)16F/32F holding x, y, z in [-1, 1]
    Octahedral, ///< RG16F/RG32F: octahedral encoding in [-1, 1]^2
};

/// A directional shadow map of the sun, for volumetric light's shadow-map march (docs/architecture.md,
/// "Volumetric light"). Any host's directional shadow map fits: `worldToClip` takes a world point to the
/// sun view's clip space (GL conventions: x, y, z in [-1, 1] inside the map, w = 1 for the orthographic
/// projection a directional light uses; a w other than 1 is divided out), and `depth` holds at (u, v) =
/// (x, y) * 0.5 + 0.5 the nearest caster's z * 0.5 + 0.5, standard [0, 1] depth (0 at the near plane, the
/// sun's side, 1 at the far plane), as a GL depth pass with glDepthRange(0, 1) writes it. A point whose
/// (u, v, depth) lies outside [0, 1]^3 counts as lit. Any size; the host's own sampler state is not used.
struct SunShadowMap {
    /// DEPTH_COMPONENT16/24/32/32F or DEPTH24_STENCIL8/DEPTH32F_STENCIL8 (its depth read). Null: no map.
    const Texture* depth = nullptr;
    glm::mat4 worldToClip{1.0f}; ///< world -> the sun view's clip space; finite, invertible
    /// Linear Rec.709 illuminance of the sun's light arriving at the scene, on a plane facing it (its
    /// radiance times its solid angle), in the colour input's units: what the medium scatters.
    glm::vec3 illuminance{1.0f};
};

/// What the host hands the pipeline each frame. Textures are the host's: adopted, never owned. Everything
/// but colour is optional; a pass that needs an input the frame lacks is skipped and reported in
/// PipelineStatus::skipped. Every texture has colour's extent.
struct FrameInputs {
    const Texture* color = nullptr; ///< scene-referred linear Rec.709 colour, any float format
    const Texture* depth = nullptr; ///< depth buffer or linear view depth, see depthKind
    DepthKind depthKind = DepthKind::Standard;
    const Texture* normals = nullptr; ///< view-space unit normals, see normalEncoding
    NormalEncoding normalEncoding = NormalEncoding::ViewXyz;
    /// RG16F/RG32F: UV-space displacement of each pixel's surface point, current minus previous frame, with
    /// both frames' jitter removed (uv_prev = uv - motion). Static scene, static camera: 0.
    const Texture* motion = nullptr;
    const Camera* camera = nullptr; ///< view, unjittered projection, previous view-projection, lens
    /// World space, pointing towards the sun (normalised by the pipeline): the direction contact shadows
    /// march in. The view matrix of `camera` turns it into view space. Absent: no sun, no contact shadows.
    std::optional<glm::vec3> sunDirection{};
    /// R32UI/R16UI/R8UI: each pixel's object id (0: none, the sky), for contactShadows.mask. Unused
    /// otherwise.
    const Texture* objectId = nullptr;
    /// RGBA16F/RGBA32F/RGBA8: each pixel's specular weight (RGB, the Fresnel F0: mix(0.04, albedo,
    /// metallic) for a metal-roughness material) and perceptual roughness (A), for screen-space reflections.
    /// Absent: every surface a dielectric mirror (F0 0.04, roughness 0).
    const Texture* material = nullptr;
    /// This frame's subjects (tokens, characters) in the host's order; read during execute(), not kept.
    /// Empty: no subject (subject metering holds exposure, or probes the screen centre with
    /// subjects.fallback = center).
    std::span<const Subject> subjects{};
    glm::vec2 viewCentreWorld{0.0f}; ///< world position under the screen centre (the centre subject's)
    /// The sun's shadow map (its own size, not colour's), with sunDirection: volumetric light's shadow-map
    /// march. Absent (depth null): screen-space volumetric light only.
    SunShadowMap sunShadow{};
};

/// Time comes from the caller, never from a wall clock: a frame renders the same whatever the machine's
/// speed, and offline sequences, tests and replays are deterministic.
struct FrameTime {
    float dt = 1.0f / 30.0f;      ///< seconds since the previous frame
    std::uint64_t frameIndex = 0; ///< monotonically increasing; drives dither/grain patterns
};

} // namespace photopic
