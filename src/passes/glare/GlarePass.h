#pragma once
// bloom.mode = glare: the exposed scene convolved with a physical point-spread function (core/Glare.h) by
// FFT in compute shaders (glare_fft.comp.glsl). The kernel splits into its centre pixel, the share of a
// pixel that stays where it is, and the halo around it (core glareHalo): this pass convolves the scene with
// the halo alone and writes s times it, with s in alpha, as Resource::Bloom; the tone-map pass composites it
// as it does energy-conserving bloom, scene (1 - intensity alpha) + intensity bloom, which is
// mix(scene, mix(scene, halo, s), intensity): a light's core is the source's own pixels at full resolution
// and the composite is energy-conserving.
//
// The FFT runs over a padded power-of-two frame, Nx x Ny >= (width + r) x (height + r) for a kernel of r
// pixels, so the circular convolution's wrap-around never carries one edge of the image onto the other. The
// padding repeats the nearer edge of the image (the last column or row, or across the wrap-around the first),
// as if the world went on past the frame: a uniform image stays uniform up to its edges instead of darkening
// where the kernel reaches past them (zero padding), and a light's halo past the edge is lost. The image sum
// is kept wherever the halo of what is bright stays inside the image. Rows of the padding are never
// transformed: the forward row pass runs on the image's rows only, the forward column pass reads an edge
// row's transform for each padding row (the transform is linear), and the inverse stores the image's rows. A
// side is at most kMaxFftSize (one line's complex signal fills 32 KiB of shared memory); a kernel reaching
// past that is clipped (reported once). The kernel's spectrum is computed once per kernel parameters, pitch
// and padded size, and kept.
//
// Tests: tests/gl/test_glare.cpp (the CPU twin: a direct convolution; the analytic profile; roundness;
// energy; the LDR path's warning), tests/core/test_glare.cpp (the kernel).

#include "core/Glare.h"
#include "passes/bloom/BloomSettings.h"
#include "gl/ShaderLibrary.h"
#include "passes/FramePass.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>

namespace photopic {

/// std140 mirror of glare_fft.comp.glsl's parameter block, rewritten before each dispatch.
struct GlareFftParameters {
    std::int32_t columns = 0;   ///< texels of a row that hold the image
    std::int32_t loadRows = 0;  ///< rows a column pass loads (the rest: zero padding)
    std::int32_t storeRows = 0; ///< rows a column pass stores
    std::int32_t divisor = 1;   ///< scene texels per glare pixel side (the scene's row pass)
    float scale = 1.0f;         ///< 1 / (Nx Ny): the inverse transform's normalisation (the last pass)
    float haloShare = 0.0f;     ///< written to the glare image's alpha (the tone-map pass's mix weight)
    float padding[2] = {};
};
static_assert(sizeof(GlareFftParameters) == 32);
static_assert(offsetof(GlareFftParameters, scale) == 16 && offsetof(GlareFftParameters, haloShare) == 20);

/// The longest FFT line: a complex signal of kMaxFftSize floats pairs fills 32 KiB of shared memory, the
/// least GL 4.5 guarantees.
inline constexpr int kMaxFftSize = 4096;

/// The smallest power of two >= n (n >= 1).
[[nodiscard]] int fftSize(int n);

class GlarePass final : public FramePass {
public:
    struct Inputs {
        const Texture* scene = nullptr; ///< sanitised or raw scene-referred colour (each read sanitised)
        const Buffer* exposureState = nullptr; ///< GpuExposureState
        const BloomSettings* settings = nullptr;
        float verticalFovDeg = 60.0f; ///< the frame's vertical field of view
        GpuTimers* timers = nullptr;
    };
    /// The halo is convolved at the scene's size (setDivisor(2) halves it, for measuring; a frame too large
    /// for the longest FFT line halves it by itself).
    GlarePass();
    [[nodiscard]] std::string_view name() const override { return "glare"; }
    [[nodiscard]] bool sanitizesSceneReads() const override { return true; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override;
    void resize(Extent extent) override;
    void execute(FrameContext& ctx, FrameResources& resources) override;
    const Texture& execute(const Inputs& in);

    /// Glare pixels per scene pixel side: 1 (full resolution) or 2 (half: the halo at half size, bilinear in
    /// the composite; the core stays full resolution either way).
    void setDivisor(int divisor);
    [[nodiscard]] int divisor() const { return mDivisor; }
    /// The frame's vertical field of view: the camera's when the host gives a valid one, else
    /// bloom.fieldOfViewDeg.
    [[nodiscard]] static float verticalFovDeg(const FrameContext& ctx, const FrameResources& resources);

    // The last execute's figures (tests, telemetry).
    [[nodiscard]] Extent paddedSize() const { return mPadded; }
    [[nodiscard]] const GlareKernelParameters& kernelParameters() const { return mKernelKey; }
    [[nodiscard]] int kernelRadius() const { return mKernelRadius; }
    /// 1 - the kernel's centre weight: the share of light the halo carries.
    [[nodiscard]] float haloShare() const { return mHaloShare; }
    /// Kernel spectra computed since the pass was made (the cache's misses).
    [[nodiscard]] int kernelBuilds() const { return mKernelBuilds; }

private:
    /// The FFT's programs for one pair of line sizes, and their samplers and images: every program that
    /// declares one has it on the same unit (the UNIT_* and IMAGE_* #defines), so one slot binds it for all.
    struct Programs {
        Program rowsScene, columnsForward, columnsInverse, rowsInverse, kernelRows, kernelColumns;
        SamplerSlot source;         ///< the scene, or the kernel image (rowsScene, kernelRows)
        SamplerSlot kernelSpectrum; ///< columnsInverse
        ImageSlot spectrumIn;       ///< the spectrum, read in place (the column passes, rowsInverse)
        ImageSlot spectrumOut;      ///< rowsScene, kernelRows, columnsForward, columnsInverse
        ImageSlot kernelOut;        ///< kernelColumns
        ImageSlot glare;            ///< rowsInverse
    };
    const Programs& programs(int rowSize, int columnSize);
    void ensureTargets(Extent glare, Extent padded);
    void ensureKernel(const GlareKernelParameters& p, int radius);
    /// The dispatches, each with its own parameter block (written only when its contents change).
    enum Step { RowsScene, ColumnsForward, ColumnsInverse, RowsInverse, KernelRows, KernelColumns, Steps };
    /// The four passes of the FFT convolution of `scene` into mGlare, timed when `timers`.
    void convolve(const Texture& scene, int divisor, GpuTimers* timers);
    /// One FFT dispatch of `program`, one line a work group, then `after`.
    void transform(Step step, const Program& program, int lines, const GlareFftParameters& parameters,
                   Barrier after = Barrier::ComputeRead);

    int mDivisor = 1;
    Extent mExtent;
    Extent mGlareExtent;
    Extent mPadded;
    std::map<std::pair<int, int>, Programs> mPrograms; ///< by (row FFT size, column FFT size)
    Texture mSpectrum;                                 ///< RGBA32F Nx x Ny: two complex signals per texel
    Texture mKernelSpectrum;                           ///< RG32F Nx x Ny
    Texture mGlare; ///< RGBA16F glare extent: the halo's convolution, its share in alpha
    std::array<ParameterBlock<GlareFftParameters>, Steps> mParameters;
    GlareKernelParameters mKernelKey{};
    Extent mKernelPadded;
    int mKernelRadius = 0;
    float mHaloShare = 0.0f;
    int mKernelBuilds = 0;
};

} // namespace photopic
