// Integer hash noise: deterministic per pixel and frame index (PCG-style mix, Jarzynski & Olano, "Hash Functions
// for GPU Rendering", JCGT 2020).
uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

/// Uniform in [0, 1) from pixel and a seed: pcgHash(frame * 4u + salt), the same for every pixel of a frame, so
/// a pass may hash it once on the CPU (TonemapPass.cpp) instead of once per pixel.
float hashUniformSeeded(ivec2 p, uint seed) {
    return float(pcgHash(uint(p.x) + pcgHash(uint(p.y) + seed))) * (1.0 / 4294967296.0);
}

/// Uniform in [0, 1) from pixel, frame and a channel salt.
float hashUniform(ivec2 p, uint frame, uint salt) {
    return hashUniformSeeded(p, pcgHash(frame * 4u + salt));
}

/// Triangular-PDF noise in (-1, 1): the sum of two uniforms, the dither that removes banding without adding
/// signal-dependent noise power. The seeds are those of `salt` and `salt + 7u`.
float triangularNoiseSeeded(ivec2 p, uint seed, uint seed7) {
    return hashUniformSeeded(p, seed) + hashUniformSeeded(p, seed7) - 1.0;
}

float triangularNoise(ivec2 p, uint frame, uint salt) {
    return triangularNoiseSeeded(p, pcgHash(frame * 4u + salt), pcgHash(frame * 4u + salt + 7u));
}
