// The bandwidth reference of `photopic bench`: a plain copy of the frame's texture into an image of the same
// format and size (one texel fetch, one image store per pixel, 8x8 groups), the least work a full-resolution
// pass can do. A pass's bytes over its time, divided by this copy's, says how far it is from the memory's pace.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uInput;
layout(binding = 0, FORMAT) uniform writeonly image2D uOutput;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(uOutput)))) {
        return;
    }
    imageStore(uOutput, p, texelFetch(uInput, p, 0));
}
