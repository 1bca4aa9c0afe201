// ssao.apply = multiply: scene colour times visibility^power, for hosts without a lighting stage. Known error:
// direct light (the sun, emission) is darkened as well as the indirect light ambient occlusion is about.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uScene;
layout(binding = 1) uniform sampler2D uVisibility;
layout(binding = 0, rgba16f) uniform writeonly image2D uOut;

// Mirrors photopic::AoMultiplyParameters (passes/gtao/GtaoPass.h), std140.
layout(std140, binding = BINDING_PARAMETERS) uniform AoMultiplyParameters {
    float uPower;
};

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uOut);
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    float v = clamp(texelFetch(uVisibility, p, 0).r, 0.0, 1.0);
    vec4 c = texelFetch(uScene, p, 0);
    imageStore(uOut, p, vec4(c.rgb * pow(v, uPower), c.a));
}
