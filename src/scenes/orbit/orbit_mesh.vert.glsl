// Mesh vertices of the orbit scene's ship (or a glTF model): world position, normal, tangent and UV for the
// material shader, and the unjittered clip positions now and one frame earlier for motion vectors (the
// ship's own motion through uPrevModel, the camera's through uPrevViewProj).
#include "orbit_frame.h.glsl"
#include "orbit_draw.h.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexCoord;
layout(location = 3) in vec4 aTangent;

out vec3 vWorld;
out vec3 vNormal;
out vec4 vTangent;
out vec2 vTexCoord;
out vec4 vClipNow;
out vec4 vClipBefore;

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorld = world.xyz;
    mat3 nm = mat3(uNormalMatrix);
    vNormal = nm * aNormal;
    vTangent = vec4(nm * aTangent.xyz, aTangent.w);
    vTexCoord = aTexCoord;
    vClipNow = uCurrViewProj * world;
    vClipBefore = uPrevViewProj * (uPrevModel * vec4(aPosition, 1.0));
    gl_Position = uViewProjection * world;
}
