// The sun shadow's debug view and measuring pass: each caster pixel's sun visibility (colour 0) and world
// position (colour 1). The normal is the triangle's own, from the world position's screen derivatives:
// cross(d/dx, d/dy) points towards the viewer, which is the outward side of the closed surfaces seen.

#include "orbit_shadow.h.glsl"

in vec3 vWorld;
layout(location = 0) out vec4 oVisibility;
layout(location = 1) out vec4 oWorld;

void main() {
    vec3 normal = normalize(cross(dFdx(vWorld), dFdy(vWorld)));
    oVisibility = vec4(vec3(sunShadowVisibility(vWorld, normal)), 1.0);
    oWorld = vec4(vWorld, 1.0);
}
