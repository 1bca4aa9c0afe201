// Volumetric light, step 1: the occlusion source (Mitchell, GPU Gems 3 ch. 13, draws occluders black over
// the light source; here the depth buffer says which pixels are occluders): the colour where the depth is
// the sky (+inf, or the far plane's depth), 0 where it holds a surface, so the sun's disc and the sky shine
// and everything in front of them blocks. At full resolution although the march runs at half: a
// half-resolution source spreads the sun's disc sideways, off the rays through its centre (at 160x90, where
// the disc is 5 px across, the rays lost 9% of their light against the CPU reference).
#include "passes/volumetriclight/volumetric_light_common.h.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uScene;
layout(binding = 1) uniform sampler2D uDepth; // R32F, +inf: sky
layout(binding = 0, rgba16f) uniform writeonly image2D uSource;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uSource);
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    vec3 source = vec3(0.0);
    float z = texelFetch(uDepth, p, 0).r;
    if (uActive != 0 && z >= uSkyDepth) { // +inf passes, NaN fails
        source = sanitizeLight(texelFetch(uScene, p, 0).rgb);
    }
    imageStore(uSource, p, vec4(source, 1.0));
}
