// The parameter block every step of the bloom chain reads (prefilter, downsample, blur, upsample), and the
// mapping between a level's texels and the texels it reads. Mirrors photopic::BloomStepParameters
// (passes/bloom/BloomPass.h), std140.
//
// Every level's texture holds the frame's region (core/Bloom.h bloomLevelFrame) and kBloomMargin texels of
// guard band around it; coordinates here are texel-centre coordinates (texel t's centre at t, not t + 0.5).
layout(std140, binding = BINDING_PARAMETERS) uniform BloomStepParameters {
    vec2 uSourceTexel;  // 1 / the extent of the texture read (the frame's, for the prefilter)
    vec2 uSourceScale;  // the source coordinate of target texel t's centre: t * uSourceScale + uSourceOrigin
    vec2 uSourceOrigin;
    vec2 uCoarseTexel;  // upsample: 1 / the extent of the coarser level's result
    vec2 uCoarseOrigin; // upsample: the coarse coordinate of level texel q: q / 2 + uCoarseOrigin
    ivec2 uFrameSize;   // prefilter: the frame's size, for the share of a footprint inside it
    int uThreshold;     // prefilter: 1 in threshold mode
    float uRadius;      // upsample: the share handed to the wider levels
    ivec2 uTargetOffset; // upsample: the level texel of target texel t (t + offset: the result has no band)
    vec4 uKnee;          // prefilter: T, T - knee, 2 knee, 1 / (4 knee)
    vec4 uWeights[3];    // blur and upsample: the Gaussian's weights 0 .. 8 texels out (core/Bloom.h)
};

#ifdef BLUR_RUN
// The blur's reach in texels (core/Bloom.h kBloomBlurReach) and the texels an invocation of the blurs computes
// along the blurred axis, both from the host: the run's texels share the kRun + 2 kBlurReach fetches under them
// (texture reads are what a software renderer pays for).
const int kBlurReach = BLUR_REACH;
const int kRun = BLUR_RUN;
#endif

// A bilinear read of `source` at texel-centre coordinate `c`; the sampler's border is transparent black.
vec4 readAt(sampler2D source, vec2 c) {
    return textureLod(source, (c + 0.5) * uSourceTexel, 0.0);
}

#ifdef BLUR_RUN
// The Gaussian along `axis` of the kRun texels from `first` on, from the kRun + 2 kBlurReach texels under
// them, each fetched once; the weights are symmetric, so each pair of texels d either side is one product.
void blurRun(sampler2D source, ivec2 first, ivec2 axis, out vec4 sums[kRun]) {
    ivec2 size = textureSize(source, 0);
    float w[kBlurReach + 1];
    for (int d = 0; d <= kBlurReach; ++d) {
        w[d] = uWeights[d / 4][d % 4];
    }
    vec4 t[kRun + 2 * kBlurReach];
    for (int k = 0; k < kRun + 2 * kBlurReach; ++k) {
        ivec2 at = first + axis * (k - kBlurReach);
        t[k] = any(lessThan(at, ivec2(0))) || any(greaterThanEqual(at, size)) ? vec4(0.0) : texelFetch(source, at, 0);
    }
    for (int r = 0; r < kRun; ++r) {
        int c = r + kBlurReach;
        vec4 sum = t[c] * w[0];
        for (int d = 1; d <= kBlurReach; ++d) {
            sum += (t[c - d] + t[c + d]) * w[d];
        }
        sums[r] = sum;
    }
}
#endif
