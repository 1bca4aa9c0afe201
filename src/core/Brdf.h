#pragma once
// The metallic-roughness BRDF of glTF 2.0 (specification, appendix B) on the CPU: the source of truth that
// the 3D shaders must match, and what the image-based-lighting tables (core/Ibl.h) are integrated from.
//
// References:
// - Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces" (the GGX distribution).
// - Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs" (Smith's
//   height-correlated masking-shadowing).
// - Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering" (the Fresnel approximation).
// - Karis 2013, "Real Shading in Unreal Engine 4" (alpha = roughness^2, the sampling of GGX).
//
// Conventions: every vector is a unit vector in the same frame; n is the shading normal, v points to the
// viewer and l to the light, both away from the surface. Roughness is glTF's perceptual roughness in [0, 1].

#include <glm/glm.hpp>

namespace photopic {

/// A perfectly smooth GGX lobe is a delta that a point evaluation cannot represent (D is infinite at the
/// mirror direction and zero elsewhere), so brdf() evaluates at least this roughness: alpha 0.002, a lobe
/// about 0.1 degree wide, narrower than a texel of a 512 x 512 cube face. Sampling and the split-sum table
/// take the exact roughness: sampling a delta is well defined.
inline constexpr float kMinRoughness = 0.045f;

/// Reflectance at normal incidence of glTF's dielectrics (index of refraction 1.5).
inline constexpr float kDielectricF0 = 0.04f;

/// GGX (Trowbridge-Reitz) normal distribution for alpha = roughness^2:
/// D = alpha^2 / (pi (c^2 (alpha^2 - 1) + 1)^2) with c = n.h, normalised so that its projected integral over
/// the hemisphere of h is 1; 0 where n.h <= 0. Needs alpha > 0.
[[nodiscard]] float ggxDistribution(float NdotH, float alpha) noexcept;

/// Smith's height-correlated masking-shadowing for GGX with the microfacet denominator folded in,
/// V = G2 / (4 n.l n.v) = 0.5 / (n.l sqrt(v^2 (1 - a^2) + a^2) + n.v sqrt(l^2 (1 - a^2) + a^2)) with v = n.v,
/// l = n.l and a = alpha; 0 where n.l or n.v is not positive. Defined for alpha = 0 too (then G2 = 1).
[[nodiscard]] float smithGgxVisibility(float NdotV, float NdotL, float alpha) noexcept;

/// Schlick's Fresnel F0 + (F90 - F0) (1 - v.h)^5 with F90 = 1.
[[nodiscard]] float fresnelSchlick(float f0, float VdotH) noexcept;
[[nodiscard]] glm::vec3 fresnelSchlick(glm::vec3 f0, float VdotH) noexcept;

/// The weight (1 - v.h)^5 that Schlick's Fresnel gives F90; F = F0 (1 - w) + w. The split sum separates it.
[[nodiscard]] float schlickWeight(float VdotH) noexcept;

/// glTF's metallic-roughness material inputs.
struct PbrMaterial {
    glm::vec3 baseColor{1.0f}; ///< linear RGB, [0, 1]
    float metallic = 0.0f;     ///< [0, 1], 0 dielectric, 1 metal
    float roughness = 0.5f;    ///< perceptual roughness, [0, 1]; alpha = roughness^2
};

/// The specular reflectance at normal incidence: mix(0.04, baseColor, metallic).
[[nodiscard]] glm::vec3 specularF0(const PbrMaterial& material) noexcept;
/// The Lambertian albedo: mix(baseColor, 0, metallic).
[[nodiscard]] glm::vec3 diffuseColor(const PbrMaterial& material) noexcept;

/// The two lobes of the BRDF, each already multiplied by its Fresnel factor.
struct BrdfLobes {
    glm::vec3 specular{0.0f}; ///< F D V, 1/sr
    glm::vec3 diffuse{0.0f};  ///< (1 - F) diffuseColor / pi, 1/sr
};

/// glTF 2.0's BRDF (appendix B): F D V + (1 - F) c_diff / pi, with F Schlick's Fresnel at v.h, D GGX and V
/// Smith height-correlated, at roughness max(roughness, kMinRoughness). Zero where n.l <= 0 or n.v <= 0.
/// Reciprocal: brdf(n, v, l) == brdf(n, l, v).
[[nodiscard]] BrdfLobes brdfLobes(glm::vec3 n, glm::vec3 v, glm::vec3 l,
                                  const PbrMaterial& material) noexcept;
[[nodiscard]] glm::vec3 brdf(glm::vec3 n, glm::vec3 v, glm::vec3 l, const PbrMaterial& material) noexcept;

} // namespace photopic
