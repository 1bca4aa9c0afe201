// What the IBL build shaders share with core/Ibl.h: the equirectangular mapping, the cube-face directions,
// Hammersley points and GGX importance sampling, written to give the CPU code's numbers.
//
// References: Karis 2013, "Real Shading in Unreal Engine 4" (Hammersley points, GGX sampling); Colbert &
// Krivanek 2007, GPU Gems 3 ch. 20 (filtered importance sampling).

#define ORBIT_IBL_PI 3.14159265358979

// core/Ibl.h's equirectUv: u = (atan(x, -z) + pi) / 2 pi, v = acos(y) / pi (v = 0 at the top row).
vec2 iblEquirectUv(vec3 d) {
    float u = (atan(d.x, -d.z) + ORBIT_IBL_PI) / (2.0 * ORBIT_IBL_PI);
    return vec2(fract(u), acos(clamp(d.y, -1.0, 1.0)) / ORBIT_IBL_PI);
}

// The direction through (s, t) in [-1, 1]^2 of cube face `face` (+x, -x, +y, -y, +z, -z), as GL's cube-map
// lookup defines it (s along the face's texel columns, t along its rows). Not normalised.
vec3 iblCubeDirection(int face, vec2 st) {
    float s = st.x;
    float t = st.y;
    if (face == 0) {
        return vec3(1.0, -t, -s);
    } else if (face == 1) {
        return vec3(-1.0, -t, s);
    } else if (face == 2) {
        return vec3(s, 1.0, t);
    } else if (face == 3) {
        return vec3(s, -1.0, -t);
    } else if (face == 4) {
        return vec3(s, -t, 1.0);
    }
    return vec3(-s, -t, -1.0);
}

// core/Ibl.h's hammersley().
vec2 iblHammersley(uint i, uint count) {
    return vec2(float(i) / float(count), float(bitfieldReverse(i)) * 2.3283064365386963e-10);
}

// core/Ibl.h's importanceSampleGgx(), with the same tangent frame.
vec3 iblImportanceSampleGgx(vec2 xi, float roughness, vec3 n) {
    float alpha = roughness * roughness;
    float phi = 2.0 * ORBIT_IBL_PI * xi.x;
    float cosTheta = sqrt((1.0 - xi.y) / (1.0 + (alpha * alpha - 1.0) * xi.y));
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    vec3 up = abs(n.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    vec3 t = normalize(cross(up, n));
    vec3 b = cross(n, t);
    return normalize(t * (sinTheta * cos(phi)) + b * (sinTheta * sin(phi)) + n * cosTheta);
}
