// Tabletop battle map, scene-linear Rec.709: the host for token-based eye adaptation (exposure follows the
// light under a token). Sunlit grass and paths, a roofed building whose roof is the outdoors mask (1 = open
// sky, 0 = under a roof), torch-lit rooms, a battle grid and tokens. Tokens are lit like the ground under
// them, so a probe on a token reads what the token is exposed to. Torch falloff: inverse-square with a core
// radius, windowed to zero at the light's range (Karis, "Real Shading in Unreal Engine 4", SIGGRAPH 2013, the
// (1 - (d/R)^4)^2 window). World: x right, y down (map units, 100 per grid square); the view window is
// [uViewMin, uViewMin + uViewSize].
#include "passes/common/noise.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba16f) writeonly uniform image2D uOutput;
layout(binding = 0) uniform sampler2D uOutdoorsMask; // R8, v = 1 - (y - rect.y) / rect.h (y down, v up)

const int kMaxWalls = 16;
const int kMaxLights = 8;
const int kMaxTokens = 8;

uniform vec2 uViewMin;
uniform vec2 uViewSize;
uniform vec4 uSceneRect; // x, y, width, height (world)
uniform vec3 uSun;       // outdoor irradiance (sun + sky), already scaled by the darkness level
uniform vec3 uAmbient;   // indoor irradiance far from any torch
uniform int uWallCount;
uniform vec4 uWalls[kMaxWalls]; // x0, y0, x1, y1
uniform int uLightCount;
uniform vec4 uLightPos[kMaxLights];   // x, y, core radius, range
uniform vec4 uLightColor[kMaxLights]; // rgb irradiance at the core radius (flicker applied), flame luminance
uniform vec4 uLightRoom[kMaxLights];  // x0, y0, x1, y1: a torch lights its own room only (walls block it)
uniform int uTokenCount;
uniform vec4 uTokens[kMaxTokens];     // x, y, radius, 1 for the player
uniform vec4 uTokenColor[kMaxTokens]; // rgb albedo

float hash2(vec2 cell) {
    ivec2 c = ivec2(floor(cell));
    return float(pcgHash(uint(c.x) * 1973u + pcgHash(uint(c.y) * 9277u + 26699u))) * (1.0 / 4294967296.0);
}

float valueNoise(vec2 p) {
    vec2 i = floor(p);
    vec2 f = fract(p);
    vec2 u = f * f * (3.0 - 2.0 * f);
    return mix(mix(hash2(i), hash2(i + vec2(1, 0)), u.x), mix(hash2(i + vec2(0, 1)), hash2(i + vec2(1, 1)), u.x),
               u.y);
}

float fbm(vec2 p) {
    return 0.5 * valueNoise(p) + 0.3 * valueNoise(p * 2.03 + 17.0) + 0.2 * valueNoise(p * 4.1 + 43.0);
}

bool inRect(vec2 p, vec4 r) {
    return p.x >= r.x && p.x <= r.z && p.y >= r.y && p.y <= r.w;
}

float outdoorsAt(vec2 world) {
    vec2 uv = vec2((world.x - uSceneRect.x) / uSceneRect.z, 1.0 - (world.y - uSceneRect.y) / uSceneRect.w);
    return texture(uOutdoorsMask, uv).r;
}

vec3 groundAlbedo(vec2 w, float outdoors, out bool isWall) {
    isWall = false;
    for (int i = 0; i < uWallCount; ++i) {
        if (inRect(w, uWalls[i])) {
            isWall = true;
        }
    }
    if (isWall) {
        float stone = fbm(w / 9.0);
        return vec3(0.2, 0.19, 0.18) * (0.7 + 0.6 * stone);
    }
    vec3 albedo;
    if (outdoors < 0.5) {
        // Wooden planks running along x, 25 units wide, staggered seams.
        float row = floor(w.y / 25.0);
        float along = w.x + 173.0 * hash2(vec2(row, 3.0));
        float plank = hash2(vec2(row, floor(along / 160.0)));
        float seam = min(smoothstep(0.0, 2.0, fract(w.y / 25.0) * 25.0), smoothstep(0.0, 2.0, fract(along / 160.0) * 160.0));
        albedo = vec3(0.34, 0.23, 0.13) * (0.75 + 0.4 * plank) * (0.55 + 0.45 * seam) * (0.9 + 0.2 * fbm(w / 6.0));
    } else {
        float g = fbm(w / 40.0);
        albedo = mix(vec3(0.07, 0.13, 0.035), vec3(0.16, 0.23, 0.07), g) * (0.85 + 0.3 * valueNoise(w / 5.0));
        // Dirt paths: east from the door, and north-south across the field.
        float pathA = abs(w.y - (1000.0 + 60.0 * sin(w.x / 250.0))) - 55.0 + 12.0 * valueNoise(w / 30.0);
        float pathB = abs(w.x - (2200.0 + 50.0 * sin(w.y / 200.0))) - 45.0 + 12.0 * valueNoise(w / 30.0 + 9.0);
        float onPath = 1.0 - smoothstep(-4.0, 4.0, min(pathA, pathB));
        vec3 dirt = vec3(0.36, 0.29, 0.19) * (0.8 + 0.35 * fbm(w / 12.0));
        albedo = mix(albedo, dirt, onPath);
    }
    // Battle grid, 100 units.
    vec2 cell = abs(fract(w / 100.0 + 0.5) - 0.5) * 100.0;
    float line = 1.0 - smoothstep(1.0, 2.5, min(cell.x, cell.y));
    return albedo * (1.0 - 0.35 * line);
}

// Tree canopies: dark discs in the field that shade the grass to the south-east of them.
const vec3 kTrees[5] = vec3[](vec3(2600.0, 560.0, 140.0), vec3(2900.0, 1650.0, 170.0), vec3(1850.0, 1780.0, 120.0),
                              vec3(2350.0, 330.0, 110.0), vec3(3050.0, 900.0, 130.0));

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uOutput);
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    // Image v runs down (row 0 of the read-back image is the top); GL rows run up.
    vec2 uv = vec2((float(p.x) + 0.5) / float(size.x), 1.0 - (float(p.y) + 0.5) / float(size.y));
    vec2 w = uViewMin + uv * uViewSize;

    float outdoors = outdoorsAt(w);
    bool isWall;
    vec3 albedo = groundAlbedo(w, outdoors, isWall);
    vec3 emitted = vec3(0.0);

    // Sun, with tree shadows; tree canopies replace the ground.
    float sunVisible = 1.0;
    for (int i = 0; i < 5; ++i) {
        vec3 t = kTrees[i];
        float r = t.z * (0.85 + 0.25 * valueNoise(w / 35.0 + float(i) * 5.0));
        if (distance(w, t.xy) < r) {
            albedo = vec3(0.04, 0.09, 0.03) * (0.6 + 0.8 * fbm(w / 14.0));
        } else if (distance(w, t.xy + vec2(45.0)) < r) {
            sunVisible = 0.3;
        }
    }

    // Tokens: disc, rim, and a soft contact shadow around each.
    float shadow = 1.0;
    for (int i = 0; i < uTokenCount; ++i) {
        vec4 t = uTokens[i];
        float d = distance(w, t.xy);
        if (d < t.z) {
            float rim = smoothstep(t.z - 8.0, t.z - 6.0, d);
            vec3 inner = uTokenColor[i].rgb;
            vec3 rimColor = t.w > 0.5 ? vec3(0.75, 0.6, 0.2) : vec3(0.6, 0.6, 0.6);
            albedo = mix(inner, rimColor, rim);
            isWall = false;
        } else if (d < t.z + 10.0) {
            shadow = min(shadow, mix(0.45, 1.0, (d - t.z) / 10.0));
        }
    }

    vec3 irradiance = uSun * outdoors * sunVisible;
    irradiance += uAmbient * (1.0 - outdoors);
    for (int i = 0; i < uLightCount; ++i) {
        if (!inRect(w, uLightRoom[i])) {
            continue;
        }
        vec4 lp = uLightPos[i];
        float d = distance(w, lp.xy);
        float x = d / lp.w;
        float window = clamp(1.0 - x * x * x * x, 0.0, 1.0);
        float falloff = window * window / (1.0 + (d / lp.z) * (d / lp.z));
        irradiance += uLightColor[i].rgb * falloff;
        // The flame itself: a small emissive core, the HDR highlight a probe must not be dominated by.
        float flame = 1.0 - smoothstep(6.0, 14.0, d);
        emitted += flame * uLightColor[i].a * normalize(uLightColor[i].rgb + 1e-6) * 1.7;
    }
    vec3 c = albedo * irradiance * shadow + emitted;
    imageStore(uOutput, p, vec4(c, 1.0));
}
