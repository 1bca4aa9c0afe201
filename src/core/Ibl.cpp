#include "core/Ibl.h"

#include "core/Brdf.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace photopic {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr double kPiD = std::numbers::pi;

/// Reverses the 32 bits of v: the base-2 radical inverse of v times 2^32.
std::uint32_t reverseBits(std::uint32_t v) noexcept {
    v = (v << 16u) | (v >> 16u);
    v = ((v & 0x00ff00ffu) << 8u) | ((v & 0xff00ff00u) >> 8u);
    v = ((v & 0x0f0f0f0fu) << 4u) | ((v & 0xf0f0f0f0u) >> 4u);
    v = ((v & 0x33333333u) << 2u) | ((v & 0xccccccccu) >> 2u);
    v = ((v & 0x55555555u) << 1u) | ((v & 0xaaaaaaaau) >> 1u);
    return v;
}

/// An orthonormal tangent frame around n; which tangent does not matter for an isotropic lobe.
void tangentFrame(glm::vec3 n, glm::vec3& t, glm::vec3& b) noexcept {
    const glm::vec3 up = std::abs(n.z) < 0.999f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    t = glm::normalize(glm::cross(up, n));
    b = glm::cross(n, t);
}

} // namespace

glm::vec2 hammersley(std::uint32_t index, std::uint32_t count) noexcept {
    return {float(index) / float(count), float(reverseBits(index)) * 0x1p-32f};
}

glm::vec3 importanceSampleGgx(glm::vec2 xi, float roughness, glm::vec3 n) noexcept {
    const float alpha = roughness * roughness;
    const float phi = 2.0f * kPi * xi.x;
    const float cosTheta = std::sqrt((1.0f - xi.y) / (1.0f + (alpha * alpha - 1.0f) * xi.y));
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    glm::vec3 t;
    glm::vec3 b;
    tangentFrame(n, t, b);
    return glm::normalize(t * (sinTheta * std::cos(phi)) + b * (sinTheta * std::sin(phi)) + n * cosTheta);
}

float ggxReflectionPdf(float NdotH, float VdotH, float roughness) noexcept {
    const float alpha = roughness * roughness;
    if (alpha <= 0.0f) {
        return std::numeric_limits<float>::infinity();
    }
    return ggxDistribution(NdotH, alpha) * std::max(NdotH, 0.0f) / (4.0f * std::max(VdotH, 1e-6f));
}

float cubemapTexelSolidAngle(int faceSize) noexcept {
    return 4.0f * kPi / (6.0f * float(faceSize) * float(faceSize));
}

float filteredSampleLod(float pdf, int sampleCount, float texelSolidAngle, float bias) noexcept {
    const float omegaSample = 1.0f / (float(sampleCount) * pdf);
    if (!(omegaSample > 0.0f)) {
        return 0.0f;
    }
    return std::max(0.0f, 0.5f * std::log2(omegaSample / texelSolidAngle) + bias);
}

// For F0 (1 - w) + w the integral of F D V (n.l) splits into F0 times the integral of (1 - w) D V (n.l) and
// that of w D V (n.l). With l sampled through h, density D (n.h) / (4 v.h), the weight of a sample is
// D V (n.l) / pdf = 4 V (n.l) (v.h) / (n.h): D cancels, so the estimator is exact at roughness 0 (h = n).
glm::vec2 splitSumScaleBias(float NdotV, float roughness, int sampleCount) noexcept {
    NdotV = std::clamp(NdotV, 1e-4f, 1.0f);
    const float alpha = roughness * roughness;
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    const glm::vec3 v(std::sqrt(1.0f - NdotV * NdotV), 0.0f, NdotV);
    double a = 0.0;
    double b = 0.0;
    const auto count = std::uint32_t(std::max(sampleCount, 1));
    for (std::uint32_t i = 0; i < count; ++i) {
        const glm::vec3 h = importanceSampleGgx(hammersley(i, count), roughness, n);
        const float VdotH = glm::dot(v, h);
        const glm::vec3 l = 2.0f * VdotH * h - v;
        const float NdotL = l.z;
        if (NdotL <= 0.0f || VdotH <= 0.0f || h.z <= 0.0f) {
            continue;
        }
        const float weight = 4.0f * smithGgxVisibility(NdotV, NdotL, alpha) * NdotL * VdotH / h.z;
        const float w = schlickWeight(VdotH);
        a += double((1.0f - w) * weight);
        b += double(w * weight);
    }
    return {float(a / double(count)), float(b / double(count))};
}

SplitSumLut splitSumLut(int size, int sampleCount) {
    if (size <= 0 || sampleCount <= 0) {
        throw std::invalid_argument("splitSumLut: size and sampleCount must be positive");
    }
    SplitSumLut lut;
    lut.size = size;
    lut.rg.resize(std::size_t(size) * std::size_t(size) * 2);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const glm::vec2 ab = splitSumScaleBias((float(x) + 0.5f) / float(size),
                                                   (float(y) + 0.5f) / float(size), sampleCount);
            const std::size_t i = (std::size_t(y) * std::size_t(size) + std::size_t(x)) * 2;
            lut.rg[i] = ab.x;
            lut.rg[i + 1] = ab.y;
        }
    }
    return lut;
}

glm::vec3 equirectDirection(glm::vec2 uv) noexcept {
    const float theta = kPi * uv.y;
    const float phi = 2.0f * kPi * uv.x - kPi;
    const float s = std::sin(theta);
    return {s * std::sin(phi), std::cos(theta), -s * std::cos(phi)};
}

glm::vec2 equirectUv(glm::vec3 d) noexcept {
    const float phi = std::atan2(d.x, -d.z);
    float u = (phi + kPi) / (2.0f * kPi);
    if (u >= 1.0f) {
        u -= 1.0f;
    }
    return {u, std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi};
}

std::array<float, 9> shBasis9(glm::vec3 d) noexcept {
    // sqrt(1 / 4pi), sqrt(3 / 4pi), sqrt(15 / 4pi), sqrt(5 / 16pi), sqrt(15 / 16pi).
    constexpr float k0 = 0.28209479f;
    constexpr float k1 = 0.48860251f;
    constexpr float k2 = 1.09254843f;
    constexpr float k20 = 0.31539157f;
    constexpr float k22 = 0.54627422f;
    return {k0,
            k1 * d.y,
            k1 * d.z,
            k1 * d.x,
            k2 * d.x * d.y,
            k2 * d.y * d.z,
            k20 * (3.0f * d.z * d.z - 1.0f),
            k2 * d.x * d.z,
            k22 * (d.x * d.x - d.y * d.y)};
}

Sh9 projectEquirectSh9(const ImageF& environment) {
    if (environment.empty()) {
        throw std::invalid_argument("projectEquirectSh9: the environment image is empty");
    }
    const int w = environment.width;
    const int h = environment.height;
    std::array<glm::dvec3, 9> sum{};
    for (int y = 0; y < h; ++y) {
        // Every texel of a row covers the same band of the sphere; its exact area, rather than sin(theta)
        // at the centre, makes a constant environment integrate to exactly 4 pi L.
        const double cos0 = std::cos(kPiD * double(y) / double(h));
        const double cos1 = std::cos(kPiD * double(y + 1) / double(h));
        const double solidAngle = (cos0 - cos1) * 2.0 * kPiD / double(w);
        const float v = (float(y) + 0.5f) / float(h);
        for (int x = 0; x < w; ++x) {
            const float* p = environment.at(x, y);
            const glm::dvec3 radiance = glm::dvec3(p[0], p[1], p[2]) * solidAngle;
            const std::array<float, 9> basis = shBasis9(equirectDirection({(float(x) + 0.5f) / float(w), v}));
            for (std::size_t i = 0; i < 9; ++i) {
                sum[i] += radiance * double(basis[i]);
            }
        }
    }
    Sh9 sh;
    for (std::size_t i = 0; i < 9; ++i) {
        sh.c[i] = glm::vec3(sum[i]);
    }
    return sh;
}

glm::vec3 shIrradiance(const Sh9& sh, glm::vec3 n) noexcept {
    constexpr std::array<float, 9> kBand{kPi,        2.0f * kPi / 3.0f, 2.0f * kPi / 3.0f, 2.0f * kPi / 3.0f,
                                         kPi / 4.0f, kPi / 4.0f,        kPi / 4.0f,        kPi / 4.0f,
                                         kPi / 4.0f};
    const std::array<float, 9> basis = shBasis9(n);
    glm::vec3 e(0.0f);
    for (std::size_t i = 0; i < 9; ++i) {
        e += sh.c[i] * (kBand[i] * basis[i]);
    }
    return e;
}

glm::vec3 shLambertRadiance(const Sh9& sh, glm::vec3 n) noexcept {
    return shIrradiance(sh, n) / kPi;
}

} // namespace photopic
