// Equirectangular environment -> cube map (photopic::orbit::Ibl): each texel averages 2 x 2 directions
// spread over it, read with bilinear filtering at the equirect level whose texels match their spacing, so a
// sun a few texels wide keeps its power at any face size.
#include "orbit_ibl_sampling.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
// Rows uploaded bottom-up (gl/Objects.h Texture::uploadRgba32f): the image's v is 1 - t. Repeats in s.
layout(binding = 0) uniform sampler2D uEquirect;
layout(binding = 0, rgba16f) writeonly uniform imageCube uCube;
uniform int uFaceSize;
uniform float uLod; // equirect level to read

void main() {
    ivec3 p = ivec3(gl_GlobalInvocationID);
    if (p.x >= uFaceSize || p.y >= uFaceSize) {
        return;
    }
    vec3 sum = vec3(0.0);
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            vec2 st = (vec2(p.xy) + (vec2(i, j) + 0.5) * 0.5) / float(uFaceSize) * 2.0 - 1.0;
            vec2 uv = iblEquirectUv(normalize(iblCubeDirection(p.z, st)));
            sum += textureLod(uEquirect, vec2(uv.x, 1.0 - uv.y), uLod).rgb;
        }
    }
    imageStore(uCube, p, vec4(sum * 0.25, 1.0));
}
