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

/// A cosine-distributed direction around n from xi in [0, 1)^2 (Malley's method), density (n.l) / pi.
glm::vec3 cosineSample(glm::vec2 xi, glm::vec3 n) noexcept {
    const float r = std::sqrt(xi.y);
    const float phi = 2.0f * kPi * xi.x;
    glm::vec3 t;
    glm::vec3 b;
    tangentFrame(n, t, b);
    return glm::normalize(t * (r * std::cos(phi)) + b * (r * std::sin(phi)) +
                          n * std::sqrt(std::max(0.0f, 1.0f - xi.y)));
}

/// A 32-bit integer hash (the PCG output permutation on a linear-congruential step), for the random
/// rotations of the Hammersley points.
std::uint32_t hashU32(std::uint32_t v) noexcept {
    const std::uint32_t state = v * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

float unitFloat(std::uint32_t v) noexcept {
    return float(v >> 8u) * 0x1p-24f;
}

/// Point i of the count-point Hammersley set, shifted by `rotation` modulo 1 (Cranley-Patterson).
glm::vec2 rotatedHammersley(std::uint32_t i, std::uint32_t count, glm::vec2 rotation) noexcept {
    glm::vec2 p = hammersley(i, count) + rotation;
    p -= glm::floor(p);
    // The float sum can round up to exactly 1.
    return glm::min(p, glm::vec2(0x1.fffffep-1f));
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

float diffuseSchlickWeight(float NdotV, int sampleCount) noexcept {
    NdotV = std::clamp(NdotV, 1e-4f, 1.0f);
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    const glm::vec3 v(std::sqrt(1.0f - NdotV * NdotV), 0.0f, NdotV);
    const auto count = std::uint32_t(std::max(sampleCount, 1));
    double sum = 0.0;
    for (std::uint32_t i = 0; i < count; ++i) {
        const glm::vec3 l = cosineSample(hammersley(i, count), n);
        sum += double(schlickWeight(glm::dot(v, glm::normalize(v + l))));
    }
    return float(sum / double(count));
}

EnvironmentDistribution::EnvironmentDistribution(const ImageF& environment) {
    if (environment.empty()) {
        throw std::invalid_argument("EnvironmentDistribution: the environment image is empty");
    }
    mWidth = environment.width;
    mHeight = environment.height;
    mRadiance.resize(environment.pixelCount());
    mCdf.resize(environment.pixelCount());
    mBandSolidAngle.resize(std::size_t(mHeight));
    double running = 0.0;
    for (int y = 0; y < mHeight; ++y) {
        const double cos0 = std::cos(kPiD * double(y) / double(mHeight));
        const double cos1 = std::cos(kPiD * double(y + 1) / double(mHeight));
        const double solidAngle = (cos0 - cos1) * 2.0 * kPiD / double(mWidth);
        mBandSolidAngle[std::size_t(y)] = float(solidAngle);
        for (int x = 0; x < mWidth; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(mWidth) + std::size_t(x);
            const float* p = environment.at(x, y);
            glm::vec3 c(p[0], p[1], p[2]);
            for (int k = 0; k < 3; ++k) {
                c[k] = std::isfinite(c[k]) ? std::max(c[k], 0.0f) : 0.0f;
            }
            mRadiance[i] = c;
            running += double(std::max({c.x, c.y, c.z})) * solidAngle;
            mCdf[i] = running;
        }
    }
    mTotal = running;
    if (mTotal > 0.0) {
        for (double& c : mCdf) {
            c /= mTotal;
        }
        mCdf.back() = 1.0;
    }
}

std::size_t EnvironmentDistribution::texelOf(glm::vec3 d) const noexcept {
    const glm::vec2 uv = equirectUv(d);
    const int x = std::clamp(int(uv.x * float(mWidth)), 0, mWidth - 1);
    const int y = std::clamp(int(uv.y * float(mHeight)), 0, mHeight - 1);
    return std::size_t(y) * std::size_t(mWidth) + std::size_t(x);
}

glm::vec3 EnvironmentDistribution::radiance(glm::vec3 d) const noexcept {
    return mRadiance[texelOf(d)];
}

glm::vec4 EnvironmentDistribution::sample(glm::vec2 xi) const noexcept {
    if (!(mTotal > 0.0)) {
        return glm::vec4(0.0f, 1.0f, 0.0f, 0.0f);
    }
    const auto it = std::upper_bound(mCdf.begin(), mCdf.end(), double(xi.x));
    const std::size_t i = std::min(std::size_t(it - mCdf.begin()), mCdf.size() - 1);
    const double below = i == 0 ? 0.0 : mCdf[i - 1];
    const double p = mCdf[i] - below;
    // Where xi.x fell inside the texel's share places the sample across the texel's longitudes.
    const double across = p > 0.0 ? std::clamp((double(xi.x) - below) / p, 0.0, 1.0) : 0.5;
    const int x = int(i % std::size_t(mWidth));
    const int y = int(i / std::size_t(mWidth));
    const double cos0 = std::cos(kPiD * double(y) / double(mHeight));
    const double cos1 = std::cos(kPiD * double(y + 1) / double(mHeight));
    const double cosTheta = cos0 + (cos1 - cos0) * double(xi.y);
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const double phi = 2.0 * kPiD * (double(x) + across) / double(mWidth) - kPiD;
    const glm::vec3 d(float(sinTheta * std::sin(phi)), float(cosTheta), float(-sinTheta * std::cos(phi)));
    return glm::vec4(d, float(p / double(mBandSolidAngle[std::size_t(y)])));
}

float EnvironmentDistribution::pdf(glm::vec3 d) const noexcept {
    if (!(mTotal > 0.0)) {
        return 0.0f;
    }
    const std::size_t i = texelOf(d);
    const double p = mCdf[i] - (i == 0 ? 0.0 : mCdf[i - 1]);
    return float(p / double(mBandSolidAngle[i / std::size_t(mWidth)]));
}

// With equal sample counts the balance heuristic weights a sample of strategy k by p_k / sum of p_j, so each
// of the 3N samples contributes f L (n.l) / sum of p_j, whichever strategy drew it.
glm::vec3 integrateEnvironmentBrdf(const EnvironmentDistribution& environment, glm::vec3 n, glm::vec3 v,
                                   const PbrMaterial& material, int samplesPerStrategy,
                                   std::uint32_t seed) noexcept {
    if (glm::dot(n, v) <= 0.0f) {
        return glm::vec3(0.0f);
    }
    const float roughness = std::max(material.roughness, kMinRoughness);
    const auto count = std::uint32_t(std::max(samplesPerStrategy, 1));
    const auto contribution = [&](glm::vec3 l) {
        const float NdotL = glm::dot(n, l);
        if (NdotL <= 0.0f) {
            return glm::dvec3(0.0);
        }
        const glm::vec3 h = glm::normalize(v + l);
        const float VdotH = glm::dot(v, h);
        const double pdfGgx = VdotH > 0.0f ? double(ggxReflectionPdf(glm::dot(n, h), VdotH, roughness)) : 0.0;
        const double pdfSum = double(environment.pdf(l)) + pdfGgx + double(NdotL) / kPiD;
        const glm::vec3 f = brdf(n, v, l, material) * environment.radiance(l) * NdotL;
        return glm::dvec3(f) / pdfSum;
    };
    glm::vec2 rotation[3];
    for (std::uint32_t k = 0; k < 3; ++k) {
        rotation[k] = {unitFloat(hashU32(seed * 6u + 2u * k)), unitFloat(hashU32(seed * 6u + 2u * k + 1u))};
    }
    glm::dvec3 sum(0.0);
    for (std::uint32_t i = 0; i < count; ++i) {
        const glm::vec4 e = environment.sample(rotatedHammersley(i, count, rotation[0]));
        if (e.w > 0.0f) {
            sum += contribution(glm::vec3(e));
        }
        const glm::vec3 h = importanceSampleGgx(rotatedHammersley(i, count, rotation[1]), roughness, n);
        sum += contribution(glm::reflect(-v, h));
        sum += contribution(cosineSample(rotatedHammersley(i, count, rotation[2]), n));
    }
    return glm::vec3(sum / double(count));
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
