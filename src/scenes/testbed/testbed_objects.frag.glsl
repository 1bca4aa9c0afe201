// Ray-casts the primitive of this proxy fragment: exact depth (gl_FragDepth), view-space normal, motion
// (UV, current minus previous, from the object's previous placement and the previous view-projection, both
// unjittered) and the local shading, which takes the lighting stage's textures when uFlags enables them.
#include "testbed_shading.h.glsl"

flat in int vPrimitive;

layout(binding = 0) uniform sampler2D uAmbientOcclusion; // R: visibility of ambient light
layout(binding = 1) uniform sampler2D uSunVisibility;    // R: visibility of the sun

layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oNormal;
layout(location = 2) out vec2 oMotion;
layout(location = 3) out uint oObjectId; // 0: the sky
layout(location = 4) out vec4 oMaterial; // rgb: specular weight F0, a: roughness

void main() {
    TestbedPrimitive p = uPrimitives[vPrimitive];
    vec3 origin, direction;
    testbedCameraRay(gl_FragCoord.xy, origin, direction);
    float t;
    vec3 objectPoint, objectNormal, n;
    if (!testbedIntersect(p, origin, direction, 0.0, 1e30, t, objectPoint, objectNormal, n)) {
        discard;
    }
    vec3 world = origin + t * direction;
    vec4 clip = uProjection * (uView * vec4(world, 1.0));
    gl_FragDepth = 0.5 * (clip.z / clip.w) + 0.5;

    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float ambientVisibility = uFlags.x != 0 ? pow(texelFetch(uAmbientOcclusion, pixel, 0).r, uAmbientOcclusionPower.x)
                                         : 1.0;
    float sunVisibility = uFlags.y != 0 ? texelFetch(uSunVisibility, pixel, 0).r : 1.0;
    oColor = vec4(testbedShade(p, objectPoint, objectNormal, n, sunVisibility, ambientVisibility), 1.0);
    oNormal = vec4(normalize(mat3(uView) * n), 0.0);
    vec4 before = p.prevToWorld * vec4(objectPoint, 1.0);
    oMotion = testbedMotion(vec4(world, 1.0), before);
    oObjectId = uint(p.emissive.w);
    oMaterial = vec4(mix(vec3(0.04), testbedAlbedo(p, objectPoint, objectNormal), p.albedo2.w), p.surface.x);
}
