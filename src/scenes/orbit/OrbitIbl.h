#pragma once
// Image-based lighting of the orbit scene from an equirectangular HDRI (linear Rec.709): the environment as
// a cube map, its GGX-prefiltered specular levels, its irradiance as nine spherical harmonics and the
// split-sum table, built once, then bound for orbit_pbr.h.glsl's pbrIbl(). The conventions (equirect
// orientation, SH order, table layout) are core/Ibl.h's; sizes, costs and measured errors are in
// docs/architecture.md ("Image-based lighting (orbit scene)").

#include "core/Ibl.h"
#include "core/Image.h"
#include "gl/Objects.h"
#include "gl/ShaderLibrary.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <filesystem>
#include <span>
#include <vector>

namespace photopic::orbit {

/// Texture unit of the prefiltered specular cube (orbit_pbr.h.glsl's uIblSpecular).
inline constexpr unsigned kIblSpecularUnit = 10;
/// Texture unit of the split-sum table (uIblLut).
inline constexpr unsigned kIblLutUnit = 11;
/// Uniform-block binding of GpuIblParameters (OrbitIblBlock).
inline constexpr unsigned kIblBlockBinding = 6;

/// The #defines every shader that includes orbit_pbr.h.glsl needs (the bindings above), after `extra`.
[[nodiscard]] ShaderDefines iblShaderDefines(ShaderDefines extra = {});

/// How the lighting is built. The defaults keep the build near a second on a 2-core software renderer and
/// keep each sphere of a roughness x metallic grid under a sunny HDRI within 5% of a Monte-Carlo reference
/// (docs/architecture.md has the measured costs and errors).
struct IblOptions {
    int faceSize = 128;         ///< texels, power of two in [16, 2048], 128: the environment cube's face
    int specularLevels = 6;     ///< [2, log2(faceSize) + 1], 6: prefiltered levels; level k has roughness
                                ///< k / (specularLevels - 1), level 0 the mirror (the environment itself)
    int prefilterSamples = 256; ///< [1, 4096], 256: GGX samples per prefiltered texel
    float lodBias = 0.5f;       ///< [0, 4], 0.5: filtered importance sampling's level bias (blur over alias)
    int lutSize = 32;           ///< [4, 512], 32: the split-sum table is lutSize x lutSize
    int lutSamples = 512;       ///< [16, 65536], 512: samples per table texel
};

/// std140 mirror of orbit_pbr.h.glsl's OrbitIblBlock.
struct GpuIblParameters {
    glm::vec4 sh[9]{}; ///< rgb: SH9 of radiance times A_l / pi (Lambert-convolved), w: 0
    float intensity = 1.0f;
    float specularMaxLevel = 0.0f; ///< specularLevels - 1
    float pad[2]{};
};
static_assert(sizeof(GpuIblParameters) == 160 && offsetof(GpuIblParameters, intensity) == 144 &&
              offsetof(GpuIblParameters, specularMaxLevel) == 148);

class Ibl {
public:
    /// Builds everything from `equirect` (any size, 2:1 expected; non-finite and negative texels count as 0).
    /// Throws std::invalid_argument for an empty image or options out of range (naming the option), GlError
    /// when a shader fails to build. Needs a current GL 4.5 context; enables GL_TEXTURE_CUBE_MAP_SEAMLESS.
    explicit Ibl(const ImageF& equirect, const IblOptions& options = {});

    /// iblIntensity: multiplies all image-based light (pbrIbl's result). Not finite or negative: 0. It is
    /// stored, never accumulated, so setting a value always gives the same frame.
    void setIntensity(float intensity);
    [[nodiscard]] float intensity() const noexcept { return mParameters.intensity; }

    /// Binds the specular cube to kIblSpecularUnit, the table to kIblLutUnit and the parameter block to
    /// kIblBlockBinding: call before a draw or dispatch whose program includes orbit_pbr.h.glsl.
    void bind() const noexcept;

    [[nodiscard]] GLuint environmentCube() const noexcept { return mEnvironment.id(); } ///< full mip chain
    [[nodiscard]] GLuint specularCube() const noexcept { return mSpecular.id(); }
    [[nodiscard]] const photopic::Texture& lut() const noexcept { return mLut; } ///< RGBA16F (A, B, W, 0)
    [[nodiscard]] const Sh9& sh() const noexcept { return mSh; } ///< of radiance, core/Ibl.h's order
    [[nodiscard]] const IblOptions& options() const noexcept { return mOptions; }
    [[nodiscard]] const GpuIblParameters& parameters() const noexcept { return mParameters; }
    /// The table as uploaded: splitSumLut(lutSize, lutSamples) with W(n.v) as a third channel.
    [[nodiscard]] const std::vector<glm::vec3>& cpuLut() const noexcept { return mCpuLut; }
    /// Wall time of the build, GL work included (it ends with glFinish).
    [[nodiscard]] double buildMilliseconds() const noexcept { return mBuildMilliseconds; }

    /// A procedural sky (the fallback environment): a blue gradient above the horizon, a dim ground below
    /// and a sun disc 3 degrees wide of radiance 400, towards normalize(0.5, 0.55, -0.67).
    [[nodiscard]] static ImageF proceduralSky(int width = 256, int height = 128);
    /// data/blender_sunrise.exr in the data folder (io/DataPath.h); an empty path when no data folder exists.
    [[nodiscard]] static std::filesystem::path defaultEnvironmentPath();
    /// The HDRI at `path` (EXR, HDR or any format io/ImageIO.h reads). When it is missing, unreadable or
    /// empty, logs one warning naming the file and the problem and returns proceduralSky().
    [[nodiscard]] static ImageF loadEnvironmentOrFallback(const std::filesystem::path& path);

private:
    IblOptions mOptions;
    GlObject<detail::TextureDeleter> mEnvironment;
    GlObject<detail::TextureDeleter> mSpecular;
    photopic::Texture mLut;
    Sh9 mSh;
    std::vector<glm::vec3> mCpuLut;
    GpuIblParameters mParameters;
    ParameterBlock<GpuIblParameters> mBlock;
    double mBuildMilliseconds = 0.0;
};

/// What a program that includes orbit_pbr.h.glsl finds bound when there is no environment: a black 1x1
/// cube, a 1x1 table of zeros and a block of zero light and intensity. The block then has a buffer (a shader
/// reading a block with none bound is undefined behaviour), every sampler a complete texture of its kind,
/// and the image-based light is 0.
class IblStandIn {
public:
    /// Needs a current GL 4.5 context.
    IblStandIn();
    /// Binds to the units and block binding Ibl::bind() uses.
    void bind() const noexcept;

private:
    GlObject<detail::TextureDeleter> mCube;
    photopic::Texture mLut;
    ParameterBlock<GpuIblParameters> mBlock;
};

// --- Evaluating the shading at chosen points (tests, calibration) ---

enum class IblProbeMode : int {
    Shade = 0,    ///< pbrIbl(material, n, v)
    Diffuse = 1,  ///< pbrIblDiffuseRadiance(n)
    Lut = 2,      ///< pbrIblLut(view.x = n.v, view.y = roughness)
    Specular = 3, ///< the specular cube along n at level view.w
    Direct = 4,   ///< pbrDirect(material, n, v, light.xyz, vec3(light.w))
};

/// std430 mirror of orbit_ibl_probe.comp.glsl's IblProbeQuery.
struct GpuIblProbeQuery {
    glm::vec4 normalMode{0.0f, 0.0f, 1.0f, 0.0f}; ///< xyz: n, w: IblProbeMode
    glm::vec4 view{0.0f, 0.0f, 1.0f, 0.0f};       ///< xyz: v, w: level (Specular)
    glm::vec4 baseColorMetallic{1.0f, 1.0f, 1.0f, 0.0f};
    glm::vec4 surface{0.5f, 1.0f, 0.0f, 0.0f}; ///< x: roughness, y: occlusion
    glm::vec4 light{0.0f, 1.0f, 0.0f, 0.0f};   ///< xyz: l, w: irradiance (Direct)
};
static_assert(sizeof(GpuIblProbeQuery) == 80);

/// Runs orbit_pbr.h.glsl on every query with `ibl` bound, returning rgb per query (one dispatch and a
/// read-back: not for the frame loop).
[[nodiscard]] std::vector<glm::vec3> iblProbe(const Ibl& ibl, std::span<const GpuIblProbeQuery> queries);

} // namespace photopic::orbit
