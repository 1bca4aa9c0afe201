// The background: sky gradient and sun disc; no normal; the motion of directions (points at infinity).
#include "testbed_shading.h.glsl"
#include "scenes/pixel_angle.h.glsl"

layout(location = 0) in vec2 vUv;

layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oNormal;
layout(location = 2) out vec2 oMotion;
layout(location = 3) out uint oObjectId; // 0: the sky
layout(location = 4) out vec4 oMaterial; // none: the sky

void main() {
    vec3 origin, direction;
    testbedCameraRay(gl_FragCoord.xy, origin, direction);
    oColor = vec4(testbedSky(direction, pixelAngleOf(direction)), 1.0);
    oNormal = vec4(0.0);
    oMotion = testbedMotion(vec4(direction, 0.0), vec4(direction, 0.0));
    oObjectId = 0u;
    oMaterial = vec4(0.0);
}
