// The orbit scene's per-frame block (OrbitRenderer.cpp's GpuFrame) and the helpers every orbit shader
// shares. Included after orbit_pbr.h.glsl (ORBIT_PI).


layout(std140, binding = 0) uniform OrbitFrame {
    mat4 uView;
    mat4 uInvView;
    mat4 uProjection;     // jittered
    mat4 uViewProjection; // jittered
    mat4 uCurrViewProj;   // unjittered (motion)
    mat4 uPrevViewProj;   // unjittered, previous frame
    vec4 uViewport;       // width, height, 1 / width, 1 / height
    vec4 uCameraPos;      // xyz: the eye in world space, w: radians per pixel (vertical)
    vec4 uSunDirection;   // xyz towards the sun, w: cos(angular radius)
    vec4 uSunIlluminance; // rgb: illuminance at normal incidence, w: the disc's radiance per unit illuminance
    vec4 uAmbient;        // rgb: uniform fill irradiance (amb)
    vec4 uHemiSky;        // rgb: hemisphere fill irradiance on a surface facing uHemiUp (hemi)
    vec4 uHemiGround;     // rgb: the same facing away from uHemiUp
    vec4 uHemiUp;         // xyz: the hemisphere light's axis (away from the Earth)
    vec4 uEarth;          // xyz centre, w radius
    vec4 uMars;           // xyz centre, w radius
    vec4 uPlanetFx;       // x: atmosphere strength, y: glow strength, z: script time (s), w: nebula strength
    ivec4 uFlags;         // x: ambient occlusion texture, y: contact-shadow texture, z: shadow map, w: 0
    vec4 uAoPower;        // x: the exponent on the ambient visibility
};

// World-space ray through a window position (GL origin bottom-left) with the jittered projection.
void orbitCameraRay(vec2 fragCoord, out vec3 origin, out vec3 direction) {
    vec2 ndc = fragCoord * uViewport.zw * 2.0 - 1.0;
    vec3 viewDir = vec3((ndc.x + uProjection[2][0]) / uProjection[0][0],
                        (ndc.y + uProjection[2][1]) / uProjection[1][1], -1.0);
    origin = uInvView[3].xyz;
    direction = normalize(mat3(uInvView) * viewDir);
}

// UV displacement, current minus previous, of homogeneous points (w = 0: a direction at infinity).
vec2 orbitMotion(vec4 now, vec4 before) {
    vec4 a = uCurrViewProj * now;
    vec4 b = uPrevViewProj * before;
    return 0.5 * (a.xy / a.w - b.xy / b.w);
}

// Visibility of the sun's disc from `p` past a sphere (centre, radius): the CPU twin is
// OrbitWorld.cpp's sunVisibility, whose comment gives the penumbra.
float orbitSunVisibility(vec4 sphere, vec3 p) {
    vec3 toCentre = sphere.xyz - p;
    float along = dot(toCentre, uSunDirection.xyz);
    if (along <= 0.0) {
        return 1.0;
    }
    float miss = length(toCentre - along * uSunDirection.xyz);
    float w = along * sqrt(max(1.0 - uSunDirection.w * uSunDirection.w, 0.0)) / max(uSunDirection.w, 1e-6);
    return smoothstep(sphere.w - w, sphere.w + w, miss);
}
