#include "core/Brdf.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace photopic {

namespace {
constexpr float kPi = std::numbers::pi_v<float>;
} // namespace

float ggxDistribution(float NdotH, float alpha) noexcept {
    if (NdotH <= 0.0f) {
        return 0.0f;
    }
    const float a2 = alpha * alpha;
    const float c = std::min(NdotH, 1.0f);
    const float d = c * c * (a2 - 1.0f) + 1.0f;
    return a2 / (kPi * d * d);
}

float smithGgxVisibility(float NdotV, float NdotL, float alpha) noexcept {
    if (NdotV <= 0.0f || NdotL <= 0.0f) {
        return 0.0f;
    }
    const float a2 = alpha * alpha;
    const float ggxV = NdotL * std::sqrt(NdotV * NdotV * (1.0f - a2) + a2);
    const float ggxL = NdotV * std::sqrt(NdotL * NdotL * (1.0f - a2) + a2);
    return 0.5f / (ggxV + ggxL);
}

float schlickWeight(float VdotH) noexcept {
    const float m = 1.0f - std::clamp(VdotH, 0.0f, 1.0f);
    const float m2 = m * m;
    return m2 * m2 * m;
}

float fresnelSchlick(float f0, float VdotH) noexcept {
    return f0 + (1.0f - f0) * schlickWeight(VdotH);
}

glm::vec3 fresnelSchlick(glm::vec3 f0, float VdotH) noexcept {
    return f0 + (glm::vec3(1.0f) - f0) * schlickWeight(VdotH);
}

glm::vec3 specularF0(const PbrMaterial& material) noexcept {
    return glm::mix(glm::vec3(kDielectricF0), material.baseColor, material.metallic);
}

glm::vec3 diffuseColor(const PbrMaterial& material) noexcept {
    return glm::mix(material.baseColor, glm::vec3(0.0f), material.metallic);
}

BrdfLobes brdfLobes(glm::vec3 n, glm::vec3 v, glm::vec3 l, const PbrMaterial& material) noexcept {
    const float NdotV = glm::dot(n, v);
    const float NdotL = glm::dot(n, l);
    if (NdotV <= 0.0f || NdotL <= 0.0f) {
        return {};
    }
    const glm::vec3 h = glm::normalize(v + l);
    const float NdotH = glm::dot(n, h);
    const float VdotH = glm::dot(v, h);
    const float roughness = std::max(material.roughness, kMinRoughness);
    const float alpha = roughness * roughness;
    const glm::vec3 f = fresnelSchlick(specularF0(material), VdotH);
    const float dv = ggxDistribution(NdotH, alpha) * smithGgxVisibility(NdotV, NdotL, alpha);
    return {f * dv, (glm::vec3(1.0f) - f) * diffuseColor(material) / kPi};
}

glm::vec3 brdf(glm::vec3 n, glm::vec3 v, glm::vec3 l, const PbrMaterial& material) noexcept {
    const BrdfLobes lobes = brdfLobes(n, v, l, material);
    return lobes.specular + lobes.diffuse;
}

} // namespace photopic
