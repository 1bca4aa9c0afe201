// The surface the contact-shadow march tests against, one texel per pixel: the plane through the pixel's
// view-space point with its normal, as the unit normal (xyz, facing the camera) and the plane's constant
// dot(normal, point) (w), so that each step of the march reads one texel and needs no reconstruction. The
// host's normals when it gives them (a broken one, NaN or zero, faces the camera), else reconstructed from
// the depths around the pixel. All zero where
// there is no surface the march may use: the sky, a broken depth, or an object contactShadows.mask leaves out
// (which then neither receives nor casts).
#include "passes/contactshadows/contact_shadows_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

// Where the normals come from (0: reconstructed from depth, 1: the host's view xyz, 2: its octahedral
// pair): a define, a program per source, so that a frame with normals does not pay for the reconstruction
// a SIMD implementation would run beside the host's normal.
const int kNormals = CONTACT_SHADOWS_NORMALS;

layout(binding = 1, r32f) uniform readonly image2D uLinearDepth; // +inf: sky
layout(binding = 1) uniform sampler2D uNormalTexture;  // view space (or octahedral), when kNormals != 0
layout(binding = 2) uniform usampler2D uObjectId;      // when uMaskCount > 0
layout(binding = 0, rgba32f) uniform writeonly image2D uSurface;

#include "passes/common/depth_neighbours.h.glsl"

bool listed(ivec2 p) {
    if (uMaskCount == 0) {
        return true;
    }
    uint id = texelFetch(uObjectId, p, 0).r;
    for (int i = 0; i < uMaskCount; ++i) {
        if (uMask[i / 4][i % 4] == id) {
            return true;
        }
    }
    return false;
}

// p's neighbour along +o or -o whose depth is closer to z (the same surface, most likely), as the view-space
// step from the centre towards +o; without a valid neighbour, a step in the plane facing the camera.
vec3 neighbourStep(ivec2 p, ivec2 o, vec3 centre, float z) {
    vec3 towards;
    bool found = nearerNeighbourStep(p, o, centre, z, towards);
    return found ? towards : viewPositionAt(vec2(p + o) + 0.5, z) - centre;
}

// The host's normal when it gives one (facing the camera where it is broken), else the normal of the depths
// around the pixel.
vec3 normalAt(ivec2 p, float z) {
    vec3 centre = viewPositionAt(vec2(p) + 0.5, z);
    vec3 n;
    if (kNormals != 0) {
        vec4 t = texelFetch(uNormalTexture, p, 0);
        n = kNormals == 2 ? octahedralDecode(t.rg) : t.xyz;
        float len2 = dot(n, n);
        n = len2 > 1e-8 && !isinf(len2) ? n : -centre;
    } else {
        n = cross(neighbourStep(p, ivec2(1, 0), centre, z), neighbourStep(p, ivec2(0, 1), centre, z));
        float len2 = dot(n, n);
        n = len2 > 1e-20 && !isinf(len2) ? n : -centre;
    }
    n = normalize(n);
    return dot(n, centre) > 0.0 ? -n : n; // a visible surface faces the camera
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(uFullSize)))) {
        return;
    }
    float z = imageLoad(uLinearDepth, p).r;
    vec4 surface = vec4(0.0);
    if (validDepth(z) && listed(p)) {
        vec3 n = normalAt(p, z);
        surface = vec4(n, dot(n, viewPositionAt(vec2(p) + 0.5, z)));
    }
    imageStore(uSurface, p, surface);
}
