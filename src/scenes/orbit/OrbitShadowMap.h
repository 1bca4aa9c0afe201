#pragma once
// The orbit scene's sun shadow map: the ship alone (it is the only caster), seen from the sun through an
// orthographic projection fitted to the ship's bounding sphere, into a 32-bit float depth texture that the
// shading reads with hardware depth comparison and rotated Poisson-disc PCF (orbit_shadow.h.glsl). It
// shadows the sun's direct light only. docs/architecture.md ("Orbit sun shadow map") has the design, the
// bias model and the measured figures.
//
// Conventions: world units are the scene's (metres), `sunDirection` points from the scene towards the sun.
// Biases and the PCF radius are in shadow-map texels, so they keep their effect when the resolution or the
// ship's size changes.

#include "core/settings/Reflect.h"
#include "gl/Objects.h"
#include "gl/ShaderLibrary.h"

#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <functional>

namespace photopic::orbit {

struct ShadowSettings {
    bool enabled = true; ///< default on: off gives the sun full visibility everywhere
    /// Texels per side of the square map, a power of two in [256, 8192], default 2048.
    int resolution = 2048;
    /// Shadow texels, [0, 16], default 0.5: depth bias towards the sun, the same on every surface.
    float constantBias = 0.5f;
    /// Shadow texels, [0, 16], default 1.0: the lookup point moves this far along the surface normal, which
    /// takes it off the surface's own depth where the surface turns away from the sun.
    float normalBias = 1.0f;
    /// Shadow texels per unit of tan(angle between the normal and the sun), [0, 16], default 1.0: depth bias
    /// that grows where the surface is steep in the map (tan is capped at 8 for the bias).
    float slopeBias = 1.0f;
    /// Shadow texels, [0, 16], default 1.5: radius of the Poisson disc of PCF taps (each tap is itself a
    /// bilinear 2x2 depth comparison, so 0 still gives a one-texel ramp). A radius in texels keeps the
    /// filter's cost and its bias needs independent of the ship's size; the penumbra in metres is
    /// softness * 2 * radius(bounds) / resolution.
    float softness = 1.5f;
    int samples = 16; ///< [1, 32], default 16: PCF taps (the first N of a fixed best-candidate disc)

    template <class V>
    void visit(V& v) {
        v.field("enabled", enabled, "the ship's sun shadow map; off: the sun reaches every surface");
        v.field("resolution", resolution, Range{256, 8192},
                "texels per side of the square map, a power of two");
        v.field("constantBias", constantBias, Range{0, 16}, "shadow texels: depth bias towards the sun");
        v.field("normalBias", normalBias, Range{0, 16},
                "shadow texels: the lookup point moves this far along the surface normal");
        v.field("slopeBias", slopeBias, Range{0, 16},
                "shadow texels per unit of tan(angle between normal and sun): depth bias on steep surfaces");
        v.field("softness", softness, Range{0, 16}, "shadow texels: radius of the Poisson disc of PCF taps");
        v.field("samples", samples, Range{1, 32}, "PCF taps (the first N of a fixed best-candidate disc)");
        v.require((resolution & (resolution - 1)) == 0, "resolution", "must be a power of two");
    }
};

/// The most PCF taps (ShadowSettings::samples) and the disc the taps are taken from, in order.
inline constexpr int kMaxShadowSamples = 32;
/// kMaxShadowSamples points in the unit disc by Mitchell's best-candidate algorithm from a fixed seed, the
/// first at the centre: every prefix of N points is spread evenly (a progressive Poisson-disc set).
[[nodiscard]] const std::array<glm::vec2, kMaxShadowSamples>& shadowPoissonDisc();

/// A sphere that holds every caster. Its radius sets the map's world size: a sphere around the ship's
/// model-space bounds keeps its radius when the ship turns, so the texel size stays fixed.
struct ShadowBounds {
    glm::vec3 center{0.0f};
    float radius = 1.0f; ///< scene units, > 0

    /// The sphere through the corners of a world (or model) axis-aligned box.
    [[nodiscard]] static ShadowBounds aroundBox(const glm::vec3& boxMin, const glm::vec3& boxMax);
};

/// The light's projection for a sun direction and caster bounds (GL-free, used by ShadowMap and tests).
struct ShadowProjection {
    glm::mat4 view{1.0f};           ///< world -> light view (looks along -sunDirection, right-handed)
    glm::mat4 viewProjection{1.0f}; ///< world -> light clip (orthographic, z in [-1, 1])
    glm::vec3 right{1, 0, 0};       ///< light view's x axis in world
    glm::vec3 up{0, 1, 0};          ///< light view's y axis in world
    glm::vec3 toSun{0, 0, 1};       ///< unit, towards the sun (light view's z axis)
    float texelSize = 0.0f;         ///< scene units per texel: 2 radius / (resolution - 2)
    float depthRange = 0.0f;        ///< scene units from the near to the far plane
    glm::vec2 gridOrigin{0.0f};     ///< the map's lower-left texel in the light's world-fixed texel grid
};

/// Fits the orthographic light projection to `bounds`: the light basis depends only on `sunDirection`
/// (world +y as the reference up, +z when the sun is within 8 degrees of the zenith or nadir), the
/// sphere's centre is projected onto it and, with `snap`, moved to a whole texel of a grid fixed in world
/// space (so a drift of the bounds smaller than a texel leaves static casters on the same texels), and the
/// depth range is the sphere's extent along the sun plus one texel each side.
[[nodiscard]] ShadowProjection fitShadowProjection(const glm::vec3& sunDirection, const ShadowBounds& bounds,
                                                   int resolution, bool snap = true);

/// What the casters callback is handed: the depth program is bound, and each draw's model matrix is set
/// here (its uniform location is kModelMatrixLocation).
class ShadowCasterPass {
public:
    static constexpr GLint kModelMatrixLocation = 0; ///< `layout(location = 0) uniform mat4` of the program
    explicit ShadowCasterPass(GLuint program)
        : mProgram(program) {}
    /// Model -> world for the draws that follow.
    void setModel(const glm::mat4& model) const;

private:
    GLuint mProgram;
};

/// Issues the casters' draws: the caller binds its own vertex array (vec3 positions at attribute 0),
/// calls pass.setModel before each draw and draws. Every face is drawn (no culling).
using ShadowCasterDraws = std::function<void(const ShadowCasterPass& pass)>;

class ShadowMap {
public:
    /// Texture unit and uniform-block binding orbit_shadow.h.glsl uses unless the including shader defines
    /// ORBIT_SHADOW_TEXTURE_UNIT / ORBIT_SHADOW_BLOCK before the include.
    static constexpr GLuint kDefaultTextureUnit = 7;
    static constexpr GLuint kDefaultBlockBinding = 7;

    /// The defines that build orbit_shadow.h.glsl's bindings as `unit` and `blockBinding` (pass them to
    /// makeGraphicsProgram for a program that includes it, and the same numbers to bind()).
    [[nodiscard]] static ShaderDefines shaderDefines(GLuint unit = kDefaultTextureUnit,
                                                     GLuint blockBinding = kDefaultBlockBinding);

    /// Needs a current GL 4.5 context (compiles the depth and visibility programs).
    ShadowMap();

    struct RenderInfo {
        glm::vec3 sunDirection{0, 1, 0}; ///< towards the sun, any length > 0
        ShadowBounds bounds;             ///< holds every caster
        const ShadowSettings* settings = nullptr;
        ShadowCasterDraws drawCasters;
        /// Texel snapping of the light-space origin; off only to measure what it does.
        bool snap = true;
    };
    /// Renders the casters' depth (when settings->enabled) and updates the parameter block. Allocates the
    /// map when the resolution changes. Saves and restores the draw framebuffer, viewport, program, vertex
    /// array, depth test/function/mask and face culling. Throws std::invalid_argument on a non-finite or
    /// zero sun direction or bounds, or without settings or callback.
    void render(const RenderInfo& info);

    /// Binds the map (with depth comparison) to texture unit `unit` and the parameter block to uniform
    /// block `blockBinding`, as orbit_shadow.h.glsl reads them. Before the first map, a 1x1 depth texture
    /// with comparison stands in, so the unit always holds what a shadow sampler needs.
    void bind(GLuint unit = kDefaultTextureUnit, GLuint blockBinding = kDefaultBlockBinding) const;

    /// Debug view and measurement: draws the casters (the same callback) with `viewProjection` into the
    /// bound framebuffer, writing sunShadowVisibility (flat normals from the triangles) to colour 0 and the
    /// world position to colour 1, depth-tested. Binds the map with bind()'s defaults first.
    void drawVisibility(const glm::mat4& viewProjection, const ShadowCasterDraws& drawCasters) const;

    [[nodiscard]] const photopic::Texture& depth() const { return mDepth; }
    [[nodiscard]] const ShadowProjection& projection() const { return mProjection; }

    /// std140 mirror of orbit_shadow.h.glsl's OrbitSunShadow block.
    struct Block {
        glm::mat4 worldToShadow; ///< world -> (u, v, depth) in [0, 1]
        glm::vec4 right;         ///< xyz: light x axis; w: texel size (scene units)
        glm::vec4 up;            ///< xyz: light y axis; w: 1 / depth range (depth per scene unit)
        glm::vec4 toSun;         ///< xyz: towards the sun; w: 1 enabled, 0 disabled
        glm::vec4 bias;          ///< x: constant, y: normal, z: slope per tan (scene units); w: tan cap
        glm::vec4 pcf;           ///< x: PCF radius (texels), y: taps, z: 1 / resolution, w: resolution
        glm::vec4 grid;          ///< xy: the map's lower-left texel in the world-fixed light grid
        glm::vec4 disc[kMaxShadowSamples / 2]; ///< the Poisson disc, two points per vec4
    };
    static_assert(sizeof(Block) == 64 + 6 * 16 + 16 * 16);
    static_assert(offsetof(Block, toSun) == 96 && offsetof(Block, pcf) == 128 &&
                  offsetof(Block, disc) == 160);

private:
    Program mDepthProgram;
    Program mVisibilityProgram;
    photopic::Texture mDepth;
    photopic::Texture mStandIn; ///< 1x1, depth 1, comparison on: what bind() binds before the first map
    Framebuffer mTarget;
    ParameterBlock<Block> mBlock;
    ShadowProjection mProjection;
};

} // namespace photopic::orbit
