// Canvas lighting shared by every shading path (tilt-driven lamp, Blinn-Phong, sparkle): the material
// decoding of CanvasMaterial.h and the diffuse term, which is all an unoccupied tile needs. References:
// J. F. Blinn, "Models of Light Reflection for Computer Synthesized Pictures", SIGGRAPH 1977 (the half-vector
// highlight).

layout(binding = 0) uniform sampler2D uColor;   // scene-linear albedo
layout(binding = 1) uniform usampler2D uMaterial; // RGBA8UI: normal xy, shininess code, glitter mask

uniform vec3 uLight;        // unit, towards the lamp, canvas frame (x right, y up, z towards the viewer)
uniform vec3 uLightColor;  // scene-linear
uniform float uAmbient;     // fill light as a fraction of the lamp
uniform float uSpecular;    // Blinn-Phong strength
uniform float uSparkleExposure;
uniform float uSparkleGate;     // 0.9: sparkle only near the facet's peak
uniform float uSparkleExponent; // 128: a sharp glint
uniform float uMaxShininessLog2;
uniform float uViewDistance; // eye above the canvas centre, image heights

vec3 decodeNormal(uvec4 m) {
    vec2 xy = vec2(m.rg) / 255.0 * 2.0 - 1.0;
    return vec3(xy, sqrt(max(0.0, 1.0 - dot(xy, xy))));
}

// Ambient + Lambert: every pixel gets this, material or not (the impasto normals shape it).
vec3 shadeDiffuse(vec3 base, vec3 n) {
    return base * uLightColor * (uAmbient + max(dot(n, uLight), 0.0));
}

// Blinn-Phong (N.H)^n with a per-pixel view vector (the eye sits uViewDistance in front of the canvas, so the
// lamp's highlight lands where the half vector meets the normal and travels as the light turns), plus the
// glitter's sparkle: a sharp (N_facet.L)^128 peak added only above 0.9, scaled by an exposure. Both are
// exactly 0 on a pixel without material, which is why the diffuse-only path of empty tiles gives the same
// bits.
vec3 shadeSpecular(vec3 n, uvec4 m, ivec2 p, ivec2 size) {
    vec3 c = vec3(0.0);
    float nl = dot(n, uLight);
    if (m.b > 0u && nl > 0.0) {
        float shininess = exp2(uMaxShininessLog2 * float(m.b) / 255.0);
        vec3 position = vec3((vec2(p) + 0.5 - 0.5 * vec2(size)) / float(size.y), 0.0);
        vec3 v = normalize(vec3(0.0, 0.0, uViewDistance) - position);
        vec3 h = normalize(uLight + v);
        c += uSpecular * pow(max(dot(n, h), 0.0), shininess) * uLightColor;
    }
    if (m.a >= 128u) {
        float sparkle = pow(max(nl, 0.0), uSparkleExponent);
        if (sparkle > uSparkleGate) {
            c += sparkle * uLightColor * uSparkleExposure;
        }
    }
    return c;
}
