// Packs level 0 of a colour texture into a buffer the CPU reads (gl/TextureReadback.h): RGBA samples of
// SAMPLE_BYTES bytes each (1 and 2: unsigned normalised, rounded to nearest as GL's pixel pack converts; 4:
// float bits), pixels row after row, and the rows top to bottom, so the CPU takes them as they lie. A texel
// fetch reads the value as stored (no filtering); the host passes no sRGB or integer format.
//
// A shader storage binding may be smaller than the whole image (GL guarantees 128 MiB; a 4K float image is
// 133 MB), so the host packs bands of rows, each dispatch with its own binding: uFirstRow is the band's first
// texel row, uBaseWord the word of the whole image at which the binding starts.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uSource;
layout(location = 0) uniform ivec2 uSize; // the texture's
layout(location = 1) uniform int uFirstRow;
layout(location = 2) uniform int uRows;
layout(location = 3) uniform uint uBaseWord;
layout(std430, binding = 0) writeonly buffer Packed {
    uint uWords[];
};

const uint kWordsPerPixel = uint(SAMPLE_BYTES);

void main() {
    ivec2 g = ivec2(gl_GlobalInvocationID.xy);
    if (g.x >= uSize.x || g.y >= uRows) {
        return;
    }
    ivec2 p = ivec2(g.x, uFirstRow + g.y);
    vec4 c = texelFetch(uSource, p, 0);
    // GL's texel rows run bottom to top: texel row y is the image's row height - 1 - y.
    uint word = (uint(uSize.y - 1 - p.y) * uint(uSize.x) + uint(p.x)) * kWordsPerPixel - uBaseWord;
    // Not packUnorm4x8 / packUnorm2x16: NVIDIA's narrow the float to a half first (0.61368 packs to 157, not
    // 156), where GL's pack converts the float itself.
#if SAMPLE_BYTES == 1
    uvec4 q = uvec4(roundEven(clamp(c, 0.0, 1.0) * 255.0));
    uWords[word] = q.r | (q.g << 8) | (q.b << 16) | (q.a << 24); // R, G, B, A in memory
#elif SAMPLE_BYTES == 2
    uvec4 q = uvec4(roundEven(clamp(c, 0.0, 1.0) * 65535.0));
    uWords[word] = q.r | (q.g << 16);
    uWords[word + 1u] = q.b | (q.a << 16);
#else
    uvec4 bits = floatBitsToUint(c);
    uWords[word] = bits.r;
    uWords[word + 1u] = bits.g;
    uWords[word + 2u] = bits.b;
    uWords[word + 3u] = bits.a;
#endif
}
