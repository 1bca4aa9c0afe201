#pragma once
// The CPU side of image-based lighting for the metallic-roughness BRDF (core/Brdf.h): the constants and
// sampling rules that the 3D scene's shaders and prefilter passes will use, computed and tested here.
//
// References:
// - Karis 2013, "Real Shading in Unreal Engine 4" (the split-sum approximation, its scale-and-bias table and
//   the importance sampling of GGX with a Hammersley sequence).
// - Ramamoorthi & Hanrahan 2001, "An Efficient Representation for Irradiance Environment Maps" (irradiance as
//   nine spherical-harmonic coefficients and the clamped-cosine constants pi, 2pi/3, pi/4).
// - Colbert & Krivanek 2007, "GPU-Based Importance Sampling", GPU Gems 3 ch. 20 (filtered importance
//   sampling: the mip level of a sample from its density).
// - Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces" (the density of a reflected
//   direction, D (n.h) / (4 v.h)).
//
// Conventions:
// - Directions are world-space unit vectors, right-handed, +y up (Camera.h's frame).
// - Equirectangular environments (ImageF, rows top to bottom) map u = (x + 0.5) / width and
//   v = (y + 0.5) / height to the polar angle theta = pi v from +y and the longitude phi = 2 pi u - pi:
//   d = (sin theta sin phi, cos theta, -sin theta cos phi). The image centre looks down -z (a default GL
//   camera's view), the right quarter is +x, the left and right edges are +z (behind), the top row is up.
// - Spherical harmonics are the real, orthonormal ones (integral of Y^2 over the sphere is 1), ordered
//   (l, m) = (0, 0), (1, -1), (1, 0), (1, 1), (2, -2), (2, -1), (2, 0), (2, 1), (2, 2) and written as
//   polynomials in the world x, y, z: Y00 = 0.282095; Y1m = 0.488603 (y, z, x); Y2-2 = 1.092548 xy,
//   Y2-1 = 1.092548 yz, Y20 = 0.315392 (3 z^2 - 1), Y21 = 1.092548 xz, Y22 = 0.546274 (x^2 - y^2). Irradiance
//   needs no preferred axis: the cosine convolution acts on each band alone.

#include "core/Brdf.h"
#include "core/Image.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace photopic {

// --- Low-discrepancy sampling ---

/// Point `index` of the `count`-point Hammersley set in [0, 1)^2: (index / count, base-2 radical inverse of
/// index). Deterministic; its first point is (0, 0).
[[nodiscard]] glm::vec2 hammersley(std::uint32_t index, std::uint32_t count) noexcept;

// --- GGX importance sampling (the prefilter's and the split sum's) ---

/// A half vector h distributed with density D(h) (n.h) around the unit normal n, from a point xi in [0, 1)^2
/// (phi = 2 pi xi.x, cos theta = sqrt((1 - xi.y) / (1 + (alpha^2 - 1) xi.y)), alpha = roughness^2). Unit
/// length, n.h >= 0. At roughness 0 every sample is n.
[[nodiscard]] glm::vec3 importanceSampleGgx(glm::vec2 xi, float roughness, glm::vec3 n) noexcept;

/// Density per steradian of the reflected direction l = reflect(-v, h) when h comes from importanceSampleGgx:
/// D(n.h) (n.h) / (4 v.h). Infinite at roughness 0 (the lobe is a delta).
[[nodiscard]] float ggxReflectionPdf(float NdotH, float VdotH, float roughness) noexcept;

/// Solid angle of one texel of a cube map with faces of faceSize^2 texels, on average: 4 pi / (6 faceSize^2).
[[nodiscard]] float cubemapTexelSolidAngle(int faceSize) noexcept;

/// Filtered importance sampling: the source mip level whose texels cover the solid angle that one of
/// sampleCount samples of density pdf stands for, 1 / (sampleCount pdf), measured in texels of solid angle
/// texelSolidAngle at level 0: max(0, 0.5 log2(omegaSample / texelSolidAngle) + bias). A level is a factor
/// 4 in solid angle, hence the 0.5. bias 0 is the bare ratio; a positive bias blurs rather than aliases.
/// Level 0 for an infinite density (roughness 0).
[[nodiscard]] float filteredSampleLod(float pdf, int sampleCount, float texelSolidAngle,
                                      float bias = 0.0f) noexcept;

// --- Split-sum scale and bias (Karis 2013) ---

/// The specular integral of the BRDF with F0 factored out: for a view at n.v = NdotV and roughness,
/// integral of F D V (n.l) dl over the hemisphere = F0 A + B, with Schlick's F = F0 (1 - w) + w. Estimated
/// with sampleCount Hammersley points through importanceSampleGgx. NdotV is clamped to [1e-4, 1].
[[nodiscard]] glm::vec2 splitSumScaleBias(float NdotV, float roughness, int sampleCount) noexcept;

/// The split-sum table: size x size (A, B) pairs, row-major from texel (0, 0). Texel (x, y) holds
/// splitSumScaleBias(NdotV = (x + 0.5) / size, roughness = (y + 0.5) / size): uploaded bottom row first as a
/// GL RG32F/RG16F texture, texture(lut, vec2(NdotV, roughness)) reads it with a linear, clamp-to-edge
/// sampler.
struct SplitSumLut {
    int size = 0;
    std::vector<float> rg; ///< size * size * 2 floats: A, B

    [[nodiscard]] glm::vec2 at(int x, int y) const noexcept {
        const std::size_t i = (std::size_t(y) * std::size_t(size) + std::size_t(x)) * 2;
        return {rg[i], rg[i + 1]};
    }
};
/// Throws std::invalid_argument unless size and sampleCount are positive. Cost and accuracy, measured against
/// 65536 samples: 1024 samples per texel err by at most 0.005 where n.v >= 0.27 and up to 0.04 in the most
/// grazing column (samples reflected below the horizon are lost there); 4096 samples by 0.0016 and 0.016.
/// 128 x 128 x 1024 takes about 1 s on one core (optimised build), so tests use smaller tables.
[[nodiscard]] SplitSumLut splitSumLut(int size, int sampleCount);

// --- The diffuse lobe's Fresnel weight ---

/// The cosine-weighted mean of Schlick's weight over the hemisphere of light directions for a view at
/// n.v = NdotV: W = integral of (1 - v.h)^5 (n.l) / pi dl with h = normalize(v + l). The diffuse lobe of
/// brdf(), (1 - F) c / pi with 1 - F = (1 - F0) (1 - w), reflects c (1 - F0) (1 - W) of a uniform
/// environment, so W is what image-based lighting multiplies its diffuse term by. It depends on n.v alone
/// (not on roughness). Estimated with sampleCount cosine-distributed Hammersley directions; NdotV is clamped
/// to [1e-4, 1]. W is 8e-5 at normal incidence, 0.011 at n.v = 0.3 and 0.024 at n.v = 0.05.
[[nodiscard]] float diffuseSchlickWeight(float NdotV, int sampleCount) noexcept;

// --- Monte-Carlo reference of the BRDF under an environment ---

/// An equirectangular environment as a piecewise-constant radiance (each texel constant over its patch of
/// the sphere) with a sampler of directions in proportion to max(r, g, b) times the texel's solid angle:
/// the reference the GPU's prefiltered lighting is measured against.
class EnvironmentDistribution {
public:
    /// Throws std::invalid_argument for an empty image. Negative and non-finite texels count as 0.
    explicit EnvironmentDistribution(const ImageF& environment);

    /// Radiance arriving from unit direction d (the texel that d falls in, no filtering).
    [[nodiscard]] glm::vec3 radiance(glm::vec3 d) const noexcept;
    /// A direction drawn from xi in [0, 1)^2: xi.x picks the texel by the cumulative table and places the
    /// direction across its longitudes, xi.y across its band of cos theta. Returns (direction, pdf) with the
    /// density per steradian; pdf 0 when the whole environment is black.
    [[nodiscard]] glm::vec4 sample(glm::vec2 xi) const noexcept;
    /// Density per steradian with which sample() returns direction d.
    [[nodiscard]] float pdf(glm::vec3 d) const noexcept;

private:
    [[nodiscard]] std::size_t texelOf(glm::vec3 d) const noexcept;

    int mWidth = 0;
    int mHeight = 0;
    std::vector<glm::vec3> mRadiance;   ///< row-major, rows top to bottom
    std::vector<double> mCdf;           ///< inclusive running sum of the texel weights, last = 1
    std::vector<float> mBandSolidAngle; ///< solid angle of one texel of each row
    double mTotal = 0.0;                ///< sum of max(r, g, b) x solid angle
};

/// Radiance reflected towards v by a surface with normal n and the metallic-roughness BRDF (brdf()) lit by
/// the environment: integral of brdf(n, v, l) L(l) (n.l) dl, estimated by multiple importance sampling with
/// the balance heuristic over three strategies of samplesPerStrategy directions each: the environment's
/// own distribution (finds the sun), GGX reflection (the specular lobe) and cosine (the diffuse lobe). The
/// points are Hammersley sets shifted by a random rotation (Cranley-Patterson) drawn from `seed`, so the
/// estimate is deterministic for a seed. Zero when n.v <= 0.
[[nodiscard]] glm::vec3 integrateEnvironmentBrdf(const EnvironmentDistribution& environment, glm::vec3 n,
                                                 glm::vec3 v, const PbrMaterial& material,
                                                 int samplesPerStrategy, std::uint32_t seed) noexcept;

// --- Equirectangular environments ---

/// The unit direction at (u, v) of an equirectangular image (see the conventions above).
[[nodiscard]] glm::vec3 equirectDirection(glm::vec2 uv) noexcept;
/// The (u, v) of a unit direction: u in [0, 1), v in [0, 1].
[[nodiscard]] glm::vec2 equirectUv(glm::vec3 direction) noexcept;

// --- Diffuse irradiance as nine spherical harmonics (Ramamoorthi & Hanrahan 2001) ---

/// The nine basis functions at a unit direction, in the order above.
[[nodiscard]] std::array<float, 9> shBasis9(glm::vec3 d) noexcept;

/// Nine RGB coefficients of radiance: L_lm = integral of L(d) Y_lm(d) dd over the sphere.
struct Sh9 {
    std::array<glm::vec3, 9> c{};
};

/// Projects an equirectangular environment (RGB used, alpha ignored) onto the nine functions, weighting each
/// texel by its exact solid angle (2 pi / width) (cos theta0 - cos theta1), the integral of sin theta dtheta
/// dphi over it. Throws std::invalid_argument for an empty image.
[[nodiscard]] Sh9 projectEquirectSh9(const ImageF& environment);

/// Irradiance at a surface with unit normal n: E(n) = sum over l, m of A_l L_lm Y_lm(n), with the clamped
/// cosine's coefficients A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4. A constant radiance L gives pi L.
[[nodiscard]] glm::vec3 shIrradiance(const Sh9& sh, glm::vec3 n) noexcept;

/// The radiance a white Lambertian surface reflects, E(n) / pi: what the shader multiplies by the diffuse
/// colour.
[[nodiscard]] glm::vec3 shLambertRadiance(const Sh9& sh, glm::vec3 n) noexcept;

} // namespace photopic
