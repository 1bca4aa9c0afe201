// The orbit scene's full-screen background pass: each pixel's camera ray hits a planet (ray-cast exactly:
// depth through gl_FragDepth, normal, id, motion of the surface point) or sees space: stars, nebula, the
// sun's disc and the planets' limb glow, with the motion of a direction at infinity.
#include "orbit_pbr.h.glsl"
#include "orbit_frame.h.glsl"
#include "orbit_space.h.glsl"
#include "scenes/pixel_angle.h.glsl"
#include "scenes/sun_disc.h.glsl"

layout(location = 0) in vec2 vUv;

layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oNormal;
layout(location = 2) out vec2 oMotion;
layout(location = 3) out uint oObjectId;
layout(location = 4) out vec4 oMaterial;

void main() {
    vec3 o, d;
    orbitCameraRay(gl_FragCoord.xy, o, d);
    float tEarth = orbitHitSphere(uEarth, o, d);
    float tMars = orbitHitSphere(uMars, o, d);
    bool earth = tEarth > 0.0 && (tMars < 0.0 || tEarth < tMars);
    bool mars = !earth && tMars > 0.0;
    if (earth || mars) {
        vec4 sphere = earth ? uEarth : uMars;
        vec3 p = o + (earth ? tEarth : tMars) * d;
        vec3 n = normalize(p - sphere.xyz);
        vec3 colour = earth ? orbitEarth(n, -d) : orbitMarsPlanet(n, -d);
        vec4 clip = uProjection * (uView * vec4(p, 1.0));
        gl_FragDepth = min(0.5 * (clip.z / clip.w) + 0.5, 0.9999999);
        oColor = vec4(colour, 1.0);
        oNormal = vec4(normalize(mat3(uView) * n), 0.0);
        oMotion = orbitMotion(vec4(p, 1.0), vec4(p, 1.0));
        oObjectId = earth ? 100u : 101u;
        oMaterial = vec4(vec3(0.02), 0.8);
        return;
    }
    vec3 colour = orbitStars(d) + orbitNebula(d);
    colour += uSunIlluminance.rgb * uSunIlluminance.w *
              sunDiscCoverage(d, uSunDirection.xyz, uSunDirection.w, pixelAngleOf(d));
    colour += orbitLimbGlow(uEarth, o, d, vec3(0.35, 0.55, 1.0));
    colour += orbitLimbGlow(uMars, o, d, vec3(0.8, 0.55, 0.40)) * 0.5;
    gl_FragDepth = 1.0;
    oColor = vec4(colour, 1.0);
    oNormal = vec4(0.0);
    oMotion = orbitMotion(vec4(d, 0.0), vec4(d, 0.0));
    oObjectId = 0u;
    oMaterial = vec4(0.0);
}
