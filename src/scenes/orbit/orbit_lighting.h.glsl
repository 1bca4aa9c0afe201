// The metallic-roughness BRDF of glTF 2.0 (its Appendix B): GGX distribution, Smith height-correlated
// visibility, Schlick Fresnel, Lambert diffuse; and the image-based light from the environment's nine SH
// coefficients (Ramamoorthi & Hanrahan 2001): irradiance for the diffuse lobe, the radiance along the
// reflection for the specular one, weighted by Lazarov's analytic fit of the split-sum scale and bias
// ("Getting More Physical in Call of Duty: Black Ops II", 2013).
// References: Walter et al. 2007 (GGX), Heitz 2014 (height-correlated Smith), Karis 2013 (split sum).

float orbitGgx(float NdotH, float alpha) {
    float a2 = alpha * alpha;
    float d = NdotH * NdotH * (a2 - 1.0) + 1.0;
    return a2 / (ORBIT_PI * d * d);
}

// V = G / (4 N.L N.V), height-correlated.
float orbitSmithVisibility(float NdotV, float NdotL, float alpha) {
    float a2 = alpha * alpha;
    float gv = NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2);
    float gl = NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2);
    return 0.5 / max(gv + gl, 1e-6);
}

vec3 orbitFresnel(vec3 f0, float VdotH) {
    return f0 + (1.0 - f0) * pow(1.0 - VdotH, 5.0);
}

// Radiance reflected towards V per unit irradiance from L at normal incidence, N.L included.
vec3 orbitDirect(vec3 n, vec3 v, vec3 l, vec3 diffuseColor, vec3 f0, float roughness) {
    float NdotL = dot(n, l);
    if (NdotL <= 0.0) {
        return vec3(0.0);
    }
    float NdotV = max(dot(n, v), 1e-4);
    vec3 h = normalize(v + l);
    float alpha = roughness * roughness;
    vec3 f = orbitFresnel(f0, max(dot(v, h), 0.0));
    vec3 specular = f * orbitGgx(max(dot(n, h), 0.0), alpha) * orbitSmithVisibility(NdotV, NdotL, alpha);
    return ((1.0 - f) * diffuseColor / ORBIT_PI + specular) * NdotL;
}

// Irradiance / pi at normal n from the SH9 radiance (clamped-cosine constants pi, 2pi/3, pi/4).
vec3 orbitShRadiance(vec3 n) {
    const float a0 = 1.0;       // pi / pi
    const float a1 = 2.0 / 3.0; // (2 pi / 3) / pi
    const float a2 = 0.25;      // (pi / 4) / pi
    vec3 e = a0 * 0.282095 * uSh[0].rgb;
    e += a1 * 0.488603 * (uSh[1].rgb * n.y + uSh[2].rgb * n.z + uSh[3].rgb * n.x);
    e += a2 * (1.092548 * (uSh[4].rgb * n.x * n.y + uSh[5].rgb * n.y * n.z + uSh[7].rgb * n.x * n.z) +
               0.315392 * uSh[6].rgb * (3.0 * n.z * n.z - 1.0) +
               0.546274 * uSh[8].rgb * (n.x * n.x - n.y * n.y));
    return max(e, vec3(0.0));
}

vec3 orbitEnvBrdfApprox(vec3 f0, float roughness, float NdotV) {
    const vec4 c0 = vec4(-1.0, -0.0275, -0.572, 0.022);
    const vec4 c1 = vec4(1.0, 0.0425, 1.04, -0.04);
    vec4 r = roughness * c0 + c1;
    float a004 = min(r.x * r.x, exp2(-9.28 * NdotV)) * r.x + r.y;
    vec2 ab = vec2(-1.04, 1.04) * a004 + r.zw;
    return f0 * ab.x + ab.y;
}

// The image-based light at unit intensity: diffuse from the irradiance, specular from the environment
// along the reflection (the SH keeps only its low frequencies: a rough-surface approximation).
vec3 orbitIbl(vec3 n, vec3 v, vec3 diffuseColor, vec3 f0, float roughness) {
    float NdotV = max(dot(n, v), 1e-4);
    vec3 r = reflect(-v, n);
    return diffuseColor * orbitShRadiance(n) + orbitEnvBrdfApprox(f0, roughness, NdotV) * orbitShRadiance(r);
}
