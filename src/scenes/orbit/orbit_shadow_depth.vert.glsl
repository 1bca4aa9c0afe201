// The sun shadow map's casters: positions at attribute 0, the draw's model matrix and the light's (or, for
// the visibility view, the camera's) view-projection as uniforms at fixed locations, which
// ShadowCasterPass::setModel and ShadowMap set without looking them up.

layout(location = 0) in vec3 aPosition;
layout(location = 0) uniform mat4 uModel;
layout(location = 1) uniform mat4 uViewProjection;

#ifdef ORBIT_SHADOW_WORLD_OUT
out vec3 vWorld;
#endif

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
#ifdef ORBIT_SHADOW_WORLD_OUT
    vWorld = world.xyz;
#endif
    gl_Position = uViewProjection * world;
}
