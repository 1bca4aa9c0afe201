#pragma once
// The point-spread functions of bloom.mode = glare (passes/glare/) and their sampled, normalised kernels.
// GL-free so that the kernel is unit-tested on its own (tests/core/test_glare.cpp) and the GPU convolution is
// checked against a direct CPU convolution with the same kernel (tests/gl/test_glare.cpp).
//
// Angles are in degrees of the field of view, so a picture's glare keeps its angular size whatever its
// resolution: a kernel is sampled for a pixel pitch (degrees per pixel) and an extent (degrees).
//
// `eye`: the photopic PSF of G. Spencer, P. Shirley, K. Zimmerman, D. Greenberg, "Physically-Based Glare
// Effects for Digital Images", SIGGRAPH 1995: 0.384 f0 + 0.478 f1 + 0.138 f2, with
//   f0 = 2.61e6 exp(-(t / 0.02)^2)   (the directly transmitted core),
//   f1 = 20.91 / (t + 0.02)^3,  f2 = 72.37 / (t + 0.02)^2   (the power-law halo of scattering in the eye),
// t in degrees; the flare lines and the lenticular halo (scotopic) are left out.
// `camera`: a lens: a diffraction-limited core, a veiling-glare power law and the diffraction spikes of the
// aperture's straight blade edges (each edge diffracts perpendicular to itself; a ray of an even count of
// blades coincides with the opposite edge's, an odd count gives twice as many rays).

#include "passes/bloom/BloomSettings.h"

#include <vector>

namespace photopic {

struct GlareKernelParameters {
    GlareKernel kernel = GlareKernel::Eye;
    float radiusDeg = 6.0f;        ///< extent: the PSF is 0 past it
    float degreesPerPixel = 0.05f; ///< pixel pitch of the image the kernel convolves
    int blades = 6;                ///< camera: aperture blades
    float bladeRotationDeg = 0.0f; ///< camera: the first spike's angle from +x
    bool operator==(const GlareKernelParameters&) const = default;
};

/// The analytic PSF at (x, y) degrees from the source (unnormalised: the paper's units for `eye`).
[[nodiscard]] double glarePsf(const GlareKernelParameters& p, double xDeg, double yDeg);
/// The PSF's energy within `radiusDeg` of the source, exactly (each term integrated in closed form).
[[nodiscard]] double glareEnclosedEnergy(const GlareKernelParameters& p, double radiusDeg);
/// The eye PSF's radial profile at `thetaDeg` (the azimuthal mean of glarePsf for `camera`).
[[nodiscard]] double glareRadialProfile(const GlareKernelParameters& p, double thetaDeg);
/// Diffraction spikes of a camera kernel: one ray per blade edge, both rays of a pair of opposite edges
/// coincide (even counts), so 2 x blades for odd counts and blades for even ones.
[[nodiscard]] int glareSpikeCount(int blades);

/// The kernel sampled on the pixel grid: the centre pixel holds the PSF's energy over its square (its inner
/// disc integrated in closed form, the rest supersampled), every other pixel the PSF at its centre times its
/// area; all divided by their total so that the samples sum to 1 by construction.
struct GlareKernelImage {
    int radius = 0;             ///< pixels: the kernel spans [-radius, radius]^2
    std::vector<float> weights; ///< (2 radius + 1)^2, row-major, centre at (radius, radius)
    /// What the samples were divided by: a pixel at (dx, dy) != 0 holds psf(dx p, dy p) p^2 / energy.
    double energy = 1.0;
    [[nodiscard]] int side() const { return 2 * radius + 1; }
    [[nodiscard]] float at(int dx, int dy) const {
        return weights[std::size_t((dy + radius) * side() + dx + radius)];
    }
    /// The centre's weight: the share of a pixel that stays in it (its delta-like core).
    [[nodiscard]] float core() const { return at(0, 0); }
};

/// Pixels of the kernel's support on either side of the centre: ceil(radiusDeg / degreesPerPixel), at most
/// `maxRadius`. Throws std::invalid_argument naming the value for a non-positive pitch or extent.
[[nodiscard]] int glareKernelRadius(const GlareKernelParameters& p, int maxRadius = 1 << 20);
[[nodiscard]] GlareKernelImage sampleGlareKernel(const GlareKernelParameters& p, int maxRadius = 1 << 20);

/// The halo: the kernel with its centre removed and renormalised (sums to 1), so that a convolution with the
/// kernel is scene (1 - s) + s (scene * halo), s = 1 - core(): the core stays the source's own pixels.
[[nodiscard]] GlareKernelImage glareHalo(const GlareKernelImage& kernel);

} // namespace photopic
