// Integer hash noise: deterministic per pixel and frame index (PCG-style mix, Jarzynski & Olano, "Hash Functions
// for GPU Rendering", JCGT 2020).
uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

/// Uniform in [0, 1) from pixel, frame and a channel salt.
float hashUniform(ivec2 p, uint frame, uint salt) {
    return float(pcgHash(uint(p.x) + pcgHash(uint(p.y) + pcgHash(frame * 4u + salt)))) * (1.0 / 4294967296.0);
}

/// Triangular-PDF noise in (-1, 1): the sum of two uniforms, the dither that removes banding without adding
/// signal-dependent noise power.
float triangularNoise(ivec2 p, uint frame, uint salt) {
    return hashUniform(p, frame, salt) + hashUniform(p, frame, salt + 7u) - 1.0;
}
