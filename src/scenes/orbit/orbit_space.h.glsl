// The orbit scene's background and planets, procedural: value noise and fBm on the unit sphere, the
// starfield and the nebula (a background of their own, never the environment map: the image-based light
// does not reach them), the sun's disc, and the two planets with their atmospheres.
//
// The atmosphere is a stylised, explicitly bounded term rather than a scattering simulation: on the disc a
// Fresnel-like rim (1 - N.V)^4 tinted by the air's colour, outside it a glow that falls off over 3% of the
// radius. Both scale with the sun's illuminance and the limb's lighting, and at strength 1 neither exceeds
// kOrbitAtmosphereCap times the radiance of a sun-lit white Lambertian surface (E / pi), so the glow cannot
// by itself push pixels far into bloom's range (docs/architecture.md, "Orbit scene").

const float kOrbitAtmosphereCap = 0.08;

float orbitHash(ivec3 c) {
    uvec3 q = uvec3(c + 65536);
    uint h = q.x * 73856093u ^ q.y * 19349663u ^ q.z * 83492791u;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return float(h & 0xffffffu) / 16777215.0;
}

float orbitNoise(vec3 p) {
    vec3 i = floor(p);
    vec3 f = fract(p);
    f = f * f * (3.0 - 2.0 * f);
    ivec3 c = ivec3(i);
    float x00 = mix(orbitHash(c), orbitHash(c + ivec3(1, 0, 0)), f.x);
    float x10 = mix(orbitHash(c + ivec3(0, 1, 0)), orbitHash(c + ivec3(1, 1, 0)), f.x);
    float x01 = mix(orbitHash(c + ivec3(0, 0, 1)), orbitHash(c + ivec3(1, 0, 1)), f.x);
    float x11 = mix(orbitHash(c + ivec3(0, 1, 1)), orbitHash(c + ivec3(1, 1, 1)), f.x);
    return mix(mix(x00, x10, f.y), mix(x01, x11, f.y), f.z);
}

// Fractal sum in [0, 1].
float orbitFbm(vec3 p, int octaves) {
    float sum = 0.0;
    float amplitude = 0.5;
    float total = 0.0;
    for (int i = 0; i < octaves; ++i) {
        sum += amplitude * orbitNoise(p);
        total += amplitude;
        p = p * 2.03 + vec3(17.1, 9.2, 3.7);
        amplitude *= 0.5;
    }
    return sum / total;
}

// Stars: one candidate per cell of a grid on each cube face (two grid sizes), looked up in the 3x3 cells
// around the direction. Each star is a Gaussian spot about one pixel wide, so it neither flickers under
// sub-pixel jitter nor vanishes between pixels; its brightness follows a steep power law.
vec3 orbitStars(vec3 d) {
    vec3 a = abs(d);
    int face = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    float major = d[face];
    vec3 uAxis = face == 0 ? vec3(0, 0, 1) : vec3(1, 0, 0);
    vec3 vAxis = face == 1 ? vec3(0, 0, 1) : vec3(0, 1, 0);
    vec2 uv = vec2(dot(d, uAxis), dot(d, vAxis)) / abs(major);
    vec3 axis = vec3(0.0);
    axis[face] = sign(major);
    float sigma = max(0.6 * uCameraPos.w, 4e-4);
    vec3 result = vec3(0.0);
    for (int level = 0; level < 2; ++level) {
        float cells = level == 0 ? 24.0 : 70.0;
        vec2 g = (uv * 0.5 + 0.5) * cells;
        ivec2 cell = ivec2(floor(g));
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                ivec3 key = ivec3(cell + ivec2(dx, dy), face * 2 + (major < 0.0 ? 1 : 0) + 8 * level);
                float present = orbitHash(key + ivec3(0, 0, 100));
                if (present > (level == 0 ? 0.35 : 0.18)) {
                    continue;
                }
                vec2 at = (vec2(cell + ivec2(dx, dy)) + vec2(orbitHash(key + ivec3(0, 0, 200)),
                                                              orbitHash(key + ivec3(0, 0, 300)))) /
                              cells * 2.0 - 1.0;
                vec3 s = normalize(axis + at.x * uAxis + at.y * vAxis);
                float angle = length(cross(d, s));
                float b = orbitHash(key + ivec3(0, 0, 400));
                float brightness = 0.004 + 0.12 * pow(b, 12.0);
                float warm = orbitHash(key + ivec3(0, 0, 500));
                vec3 tint = mix(vec3(0.75, 0.85, 1.0), vec3(1.0, 0.85, 0.65), warm);
                result += tint * brightness * exp(-0.5 * angle * angle / (sigma * sigma));
            }
        }
    }
    return result;
}

vec3 orbitNebula(vec3 d) {
    float density = orbitFbm(d * 2.2 + vec3(3.0, 1.0, 0.0), 4);
    float hue = orbitFbm(d * 3.1 + vec3(-5.0, 2.0, 7.0), 3);
    float cloud = smoothstep(0.48, 0.78, density);
    vec3 colour = mix(vec3(0.45, 0.18, 0.55), vec3(0.10, 0.35, 0.50), hue);
    return colour * cloud * 0.012 * uPlanetFx.w;
}

// Nearest positive hit of a ray with a sphere; -1 when none.
float orbitHitSphere(vec4 sphere, vec3 o, vec3 d) {
    vec3 oc = o - sphere.xyz;
    float b = dot(oc, d);
    float c = dot(oc, oc) - sphere.w * sphere.w;
    float disc = b * b - c;
    if (disc < 0.0) {
        return -1.0;
    }
    float t = -b - sqrt(disc);
    return t > 0.0 ? t : -1.0;
}

// The sunlit white Lambertian radiance E / pi: the atmosphere's yardstick.
vec3 orbitWhiteRadiance() {
    return uSunIlluminance.rgb / ORBIT_PI;
}

// The Earth-like planet at surface normal n (world), seen along -v.
vec3 orbitEarth(vec3 n, vec3 v) {
    vec3 l = uSunDirection.xyz;
    float NdotL = dot(n, l);
    float height = orbitFbm(n * 2.6, 5);
    float land = smoothstep(0.50, 0.53, height);
    float ice = smoothstep(0.80, 0.86, abs(n.y) + 0.05 * height);
    vec3 ground = mix(vec3(0.10, 0.16, 0.06), vec3(0.30, 0.24, 0.14), orbitFbm(n * 9.0, 3));
    vec3 ocean = vec3(0.015, 0.04, 0.10);
    vec3 albedo = mix(mix(ocean, ground, land), vec3(0.75), ice);
    float cloud = smoothstep(0.50, 0.72, orbitFbm(n * 4.5 + vec3(0.01 * uPlanetFx.z, 0.0, 0.0), 5)) * 0.9;
    vec3 e = uSunIlluminance.rgb;
    vec3 surface = albedo / ORBIT_PI * e * max(NdotL, 0.0);
    // The ocean's sun glint (GGX, roughness 0.25, water's F0 0.02), under the clouds.
    if (NdotL > 0.0 && land < 0.5) {
        vec3 h = normalize(v + l);
        float a = 0.25 * 0.25;
        float NdotV = max(dot(n, v), 1e-3);
        float spec = pbrGgxDistribution(dot(n, h), a) * pbrSmithVisibility(NdotV, NdotL, a) *
                     (0.02 + 0.98 * pow(1.0 - max(dot(v, h), 0.0), 5.0));
        surface += e * spec * NdotL * (1.0 - land);
    }
    vec3 clouds = vec3(0.8) / ORBIT_PI * e * max(NdotL, 0.0);
    vec3 colour = mix(surface, clouds, cloud);
    // City lights on the night side's land, fading in past the terminator.
    float night = smoothstep(0.05, -0.15, NdotL);
    float cities = smoothstep(0.58, 0.70, orbitFbm(n * 90.0, 3)) * land * (1.0 - ice) * (1.0 - cloud);
    colour += vec3(1.0, 0.72, 0.38) * 0.05 * cities * night;
    // Atmosphere rim on the disc (bounded, see above).
    float rim = pow(1.0 - max(dot(n, v), 0.0), 4.0);
    float lit = smoothstep(-0.25, 0.35, NdotL);
    colour += vec3(0.35, 0.55, 1.0) * orbitWhiteRadiance() * (kOrbitAtmosphereCap * uPlanetFx.x * rim * lit);
    return colour;
}

vec3 orbitMarsPlanet(vec3 n, vec3 v) {
    vec3 l = uSunDirection.xyz;
    float NdotL = dot(n, l);
    float f = orbitFbm(n * 3.5 + vec3(11.0), 5);
    vec3 albedo = mix(vec3(0.32, 0.14, 0.06), vec3(0.55, 0.32, 0.17), f);
    albedo = mix(albedo, vec3(0.8, 0.75, 0.7), smoothstep(0.88, 0.93, abs(n.y)));
    vec3 colour = albedo / ORBIT_PI * uSunIlluminance.rgb * max(NdotL, 0.0);
    float rim = pow(1.0 - max(dot(n, v), 0.0), 4.0);
    colour += vec3(0.8, 0.55, 0.40) * orbitWhiteRadiance() *
              (0.5 * kOrbitAtmosphereCap * uPlanetFx.x * rim * smoothstep(-0.1, 0.4, NdotL));
    return colour;
}

// The glow just outside a planet's limb (bounded, see above): how far the ray misses the sphere, in 3% of
// the radius, and how lit the limb below it is.
vec3 orbitLimbGlow(vec4 sphere, vec3 o, vec3 d, vec3 tint) {
    vec3 oc = sphere.xyz - o;
    float along = dot(oc, d);
    if (along <= 0.0) {
        return vec3(0.0);
    }
    vec3 closest = o + along * d;
    float miss = length(closest - sphere.xyz);
    float x = (miss - sphere.w) / (0.03 * sphere.w);
    if (x < 0.0 || x > 4.0) {
        return vec3(0.0);
    }
    float lit = smoothstep(-0.3, 0.4, dot(normalize(closest - sphere.xyz), uSunDirection.xyz));
    return tint * orbitWhiteRadiance() * (kOrbitAtmosphereCap * uPlanetFx.y * exp(-1.5 * x) * lit);
}
