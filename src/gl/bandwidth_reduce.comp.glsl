// The reduction reference of `photopic bench`: the 2x2 box mean of the frame's texture into an RGBA16F image
// of half its size (four texel fetches, one image store per target texel, 8x8 groups), the least work a pass
// that reads a full-resolution frame and writes a quarter of it (the bloom prefilter) can do. Its bytes over
// its time, against the copy's, say what such a pass can reach on the device.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uInput;
layout(binding = 0, rgba16f) uniform writeonly image2D uOutput;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(uOutput)))) {
        return;
    }
    ivec2 q = 2 * p;
    vec4 sum = texelFetch(uInput, q, 0) + texelFetch(uInput, q + ivec2(1, 0), 0) +
               texelFetch(uInput, q + ivec2(0, 1), 0) + texelFetch(uInput, q + ivec2(1, 1), 0);
    imageStore(uOutput, p, 0.25 * sum);
}
