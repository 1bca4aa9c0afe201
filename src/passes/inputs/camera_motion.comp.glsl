// Camera-only motion from depth: each pixel's surface point, un-projected with this frame's camera and
// projected with last frame's view-projection. Objects that move on their own get the camera's motion only,
// so temporal passes ghost on them: hosts that can should render motion vectors.
// Convention: UV displacement, current minus previous (uv_prev = uv - motion), jitter-free matrices.

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uLinearDepth;
layout(binding = 0, rg16f) uniform writeonly image2D uMotion;

// Mirrors photopic::CameraMotionParameters (passes/inputs/InputPasses.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform CameraMotionParameters {
    mat4 uInvProjection; // this frame, unjittered
    mat4 uInvView;
    mat4 uPrevViewProjection;
    int uCut;
};

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uMotion);
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    vec2 uv = (vec2(p) + 0.5) / vec2(size);
    vec2 motion = vec2(0.0);
    if (uCut == 0) {
        // The view-space point on the near plane through this pixel, then scaled to the surface's depth.
        vec4 near = uInvProjection * vec4(uv * 2.0 - 1.0, -1.0, 1.0);
        vec3 ray = near.xyz / near.w;
        float z = texelFetch(uLinearDepth, p, 0).r;
        // The sky is a direction (w = 0): only the camera's rotation moves it.
        vec4 world = isinf(z) ? uInvView * vec4(ray, 0.0) : uInvView * vec4(ray * (z / -ray.z), 1.0);
        vec4 prev = uPrevViewProjection * world;
        if (prev.w > 0.0) {
            vec2 prevUv = prev.xy / prev.w * 0.5 + 0.5;
            motion = uv - prevUv;
        }
    }
    imageStore(uMotion, p, vec4(motion, 0.0, 0.0));
}
