// Integer hash noise: deterministic per pixel and frame index (PCG-style mix, Jarzynski & Olano, "Hash Functions
// for GPU Rendering", JCGT 2020).
uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

/// Uniform in [0, 1) from pixel, frame and a channel salt.
float hashUniform(ivec2 p, uint frame, uint salt) {
    uint seed = pcgHash(frame * 4u + salt);
    return float(pcgHash(uint(p.x) + pcgHash(uint(p.y) + seed))) * (1.0 / 4294967296.0);
}

/// Triangular-PDF noise in (-1, 1): the sum of two uniforms (the salts `salt` and `salt + 7u`), noise that
/// removes banding without adding signal-dependent noise power.
float triangularNoise(ivec2 p, uint frame, uint salt) {
    return hashUniform(p, frame, salt) + hashUniform(p, frame, salt + 7u) - 1.0;
}

/// Three 32-bit hashes of a 3D integer point at once (pcg3d, Jarzynski & Olano 2020): a few multiply-adds of
/// the coordinates into each other around one xorshift, where the chained pcgHash above takes a full hash
/// per coordinate and per output.
uvec3 pcg3d(uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v;
}

/// Triangular-PDF noise in (-1, 1) for three channels at once, independent between channels: the sum of two
/// uniforms per channel, each the top 24 bits of a pcg3d word of (pixel, seed). `seedA` and `seedB` are two
/// per-frame seeds (TonemapPass.cpp). Two pcg3d hashes per pixel where triangularNoise takes twelve pcgHash:
/// the dither cost 44 instructions a pixel on llvmpipe that way.
vec3 triangularNoise3(ivec2 p, uint seedA, uint seedB) {
    vec3 a = vec3(pcg3d(uvec3(uvec2(p), seedA)) >> 8u);
    vec3 b = vec3(pcg3d(uvec3(uvec2(p), seedB)) >> 8u);
    return (a + b) * (1.0 / 16777216.0) - 1.0;
}
