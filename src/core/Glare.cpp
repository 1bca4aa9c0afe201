#include "core/Glare.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace photopic {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Spencer et al. 1995, photopic: the weights of f0, f1, f2 and their constants (degrees).
constexpr double kEyeW0 = 0.384, kEyeW1 = 0.478, kEyeW2 = 0.138;
constexpr double kEyeCorePeak = 2.61e6, kEyeCoreWidth = 0.02;
constexpr double kEyeF1 = 20.91, kEyeF2 = 72.37, kEyeOffset = 0.02;

// The camera kernel, as shares of a unit of light: a diffraction-limited core keeps most of it (a pixel
// wide at any ordinary pitch), a lens's veiling glare spreads a few percent as 1 / t^2 (the stray light of
// surface reflections and scattering falls off like the eye's f2 term), and each spike carries a fraction of
// a percent along its ray with the 1 / t^2 envelope of a straight edge's diffraction.
constexpr double kCameraCoreShare = 0.9, kCameraCoreWidth = 0.02;
constexpr double kCameraVeil = 0.0015, kCameraVeilOffset = 0.05;
constexpr double kCameraSpike = 0.0005, kCameraSpikeOffset = 0.1;
constexpr double kCameraSpikeWidth = 0.01; ///< degrees: the ray's half-width (widened to half a pixel)
constexpr int kCentreSubsamples = 64;      ///< per side, for the centre pixel's square outside its disc

/// The share of a unit Gaussian exp(-(t/w)^2) / (pi w^2) within radius r.
double gaussianEnclosed(double w, double r) {
    return 1.0 - std::exp(-(r * r) / (w * w));
}
/// Integral over 0..r of 2 pi t / (t + a)^3 dt.
double inverseCubeEnclosed(double a, double r) {
    return 2.0 * kPi * (0.5 / a - 1.0 / (r + a) + a / (2.0 * (r + a) * (r + a)));
}
/// Integral over 0..r of 2 pi t / (t + a)^2 dt.
double inverseSquareEnclosed(double a, double r) {
    return 2.0 * kPi * (std::log((r + a) / a) + a / (r + a) - 1.0);
}

double cameraSpikes(const GlareKernelParameters& p, double x, double y, double t) {
    const int rays = glareSpikeCount(p.blades);
    // At least most of a pixel wide: the kernel samples the PSF at pixel centres, and a thinner ray would
    // fall between them.
    const double width = std::max(kCameraSpikeWidth, 0.75 * double(p.degreesPerPixel));
    const double along = kCameraSpike / ((t + kCameraSpikeOffset) * (t + kCameraSpikeOffset));
    double sum = 0.0;
    for (int k = 0; k < rays; ++k) {
        const double a = (double(p.bladeRotationDeg) + 360.0 * double(k) / double(rays)) * kPi / 180.0;
        const double projection = x * std::cos(a) + y * std::sin(a);
        // A ray starts at the source: half of it where a point lies square to it (so that the kernel stays
        // point symmetric when rounding puts such a point a hair before one ray and behind its opposite).
        const double share = projection > 1e-9 ? 1.0 : projection > -1e-9 ? 0.5 : 0.0;
        const double across = -x * std::sin(a) + y * std::cos(a);
        sum += share * std::exp(-(across * across) / (width * width)) / (width * std::sqrt(kPi));
    }
    return along * sum;
}

void requireValid(const GlareKernelParameters& p) {
    if (!(p.degreesPerPixel > 0.0f) || !std::isfinite(p.degreesPerPixel))
        throw std::invalid_argument(
            fmt::format("glare kernel: degrees per pixel {} must be > 0", p.degreesPerPixel));
    if (!(p.radiusDeg > 0.0f) || !std::isfinite(p.radiusDeg))
        throw std::invalid_argument(fmt::format("glare kernel: radiusDeg {} must be > 0", p.radiusDeg));
    if (p.kernel == GlareKernel::Camera && p.blades < 3)
        throw std::invalid_argument(fmt::format("glare kernel: blades {} must be >= 3", p.blades));
}

/// The PSF's energy over the pixel (dx, dy) by an n x n midpoint rule, leaving out the disc of radius
/// `skip` about the source (integrated in closed form by the caller).
double pixelEnergy(const GlareKernelParameters& p, int dx, int dy, int n, double skip) {
    const double pitch = p.degreesPerPixel;
    const double step = pitch / n;
    double sum = 0.0;
    for (int j = 0; j < n; ++j) {
        const double y = (double(dy) - 0.5) * pitch + (double(j) + 0.5) * step;
        for (int i = 0; i < n; ++i) {
            const double x = (double(dx) - 0.5) * pitch + (double(i) + 0.5) * step;
            if (skip > 0.0 && std::hypot(x, y) < skip)
                continue;
            sum += glarePsf(p, x, y);
        }
    }
    return sum * step * step;
}

} // namespace

int glareSpikeCount(int blades) {
    return blades % 2 == 0 ? blades : 2 * blades;
}

double glarePsf(const GlareKernelParameters& p, double xDeg, double yDeg) {
    const double t = std::hypot(xDeg, yDeg);
    if (t > double(p.radiusDeg))
        return 0.0;
    if (p.kernel == GlareKernel::Eye) {
        const double c = t / kEyeCoreWidth;
        const double o = t + kEyeOffset;
        return kEyeW0 * kEyeCorePeak * std::exp(-c * c) + kEyeW1 * kEyeF1 / (o * o * o) +
               kEyeW2 * kEyeF2 / (o * o);
    }
    const double w = kCameraCoreWidth;
    const double core = kCameraCoreShare * std::exp(-(t * t) / (w * w)) / (kPi * w * w);
    const double v = t + kCameraVeilOffset;
    return core + kCameraVeil / (v * v) + cameraSpikes(p, xDeg, yDeg, t);
}

double glareEnclosedEnergy(const GlareKernelParameters& p, double radiusDeg) {
    const double r = std::min(radiusDeg, double(p.radiusDeg));
    if (r <= 0.0)
        return 0.0;
    if (p.kernel == GlareKernel::Eye) {
        const double core = kEyeCorePeak * kPi * kEyeCoreWidth * kEyeCoreWidth;
        return kEyeW0 * core * gaussianEnclosed(kEyeCoreWidth, r) +
               kEyeW1 * kEyeF1 * inverseCubeEnclosed(kEyeOffset, r) +
               kEyeW2 * kEyeF2 * inverseSquareEnclosed(kEyeOffset, r);
    }
    const double spikes = double(glareSpikeCount(p.blades)) * kCameraSpike *
                          (1.0 / kCameraSpikeOffset - 1.0 / (r + kCameraSpikeOffset));
    return kCameraCoreShare * gaussianEnclosed(kCameraCoreWidth, r) +
           kCameraVeil * inverseSquareEnclosed(kCameraVeilOffset, r) + spikes;
}

double glareRadialProfile(const GlareKernelParameters& p, double thetaDeg) {
    if (p.kernel == GlareKernel::Eye || thetaDeg <= 0.0)
        return glarePsf(p, thetaDeg, 0.0);
    if (thetaDeg > double(p.radiusDeg))
        return 0.0;
    // The spikes' energy per unit radius spread over the circle.
    const double s = thetaDeg + kCameraSpikeOffset;
    const double spikes = double(glareSpikeCount(p.blades)) * kCameraSpike / (s * s) / (2.0 * kPi * thetaDeg);
    const double w = kCameraCoreWidth, v = thetaDeg + kCameraVeilOffset;
    return kCameraCoreShare * std::exp(-(thetaDeg * thetaDeg) / (w * w)) / (kPi * w * w) +
           kCameraVeil / (v * v) + spikes;
}

int glareKernelRadius(const GlareKernelParameters& p, int maxRadius) {
    requireValid(p);
    // Less a float rounding of the ratio (4 / 0.04 is 100.000002 in floats).
    const double r = std::ceil(double(p.radiusDeg) / double(p.degreesPerPixel) - 1e-4);
    return int(std::clamp(r, 1.0, double(std::max(1, maxRadius))));
}

GlareKernelImage sampleGlareKernel(const GlareKernelParameters& p, int maxRadius) {
    GlareKernelImage k;
    k.radius = glareKernelRadius(p, maxRadius);
    const int side = k.side();
    k.weights.assign(std::size_t(side) * std::size_t(side), 0.0f);
    std::vector<double> energy(k.weights.size(), 0.0);
    // The centre pixel's inscribed disc holds the delta-like core (and the steepest of the halo): exact.
    const double inner = 0.5 * double(p.degreesPerPixel);
    const double reach = double(p.radiusDeg) + 0.75 * double(p.degreesPerPixel);
    double total = 0.0;
    for (int dy = -k.radius; dy <= k.radius; ++dy) {
        for (int dx = -k.radius; dx <= k.radius; ++dx) {
            if (std::hypot(double(dx), double(dy)) * double(p.degreesPerPixel) > reach)
                continue;
            const bool centre = dx == 0 && dy == 0;
            // The centre pixel holds all that falls on its square; the others the PSF at their centres (a
            // square's mean would blur the steep halo by a square pixel, which a round glow cannot afford).
            double e = centre ? pixelEnergy(p, 0, 0, kCentreSubsamples, inner) + glareEnclosedEnergy(p, inner)
                              : glarePsf(p, dx * double(p.degreesPerPixel), dy * double(p.degreesPerPixel)) *
                                    double(p.degreesPerPixel) * double(p.degreesPerPixel);
            energy[std::size_t((dy + k.radius) * side + dx + k.radius)] = e;
            total += e;
        }
    }
    for (std::size_t i = 0; i < energy.size(); ++i)
        k.weights[i] = float(energy[i] / total);
    k.energy = total;
    return k;
}

GlareKernelImage glareHalo(const GlareKernelImage& kernel) {
    GlareKernelImage halo = kernel;
    const double share = 1.0 - double(kernel.core());
    halo.weights[std::size_t(kernel.radius * kernel.side() + kernel.radius)] = 0.0f;
    if (share > 0.0) {
        for (float& w : halo.weights)
            w = float(double(w) / share);
    }
    return halo;
}

} // namespace photopic
