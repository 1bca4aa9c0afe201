#include "passes/glare/GlarePass.h"

#include "core/Log.h"
#include "gl/Capabilities.h"
#include "passes/Bindings.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace photopic {

namespace {
constexpr const char* kFft = "passes/glare/glare_fft.comp.glsl";
// The pass's texture and image units, declared once (the shader gets them as UNIT_* / IMAGE_* #defines; the
// passes bind them through the programs' slots).
constexpr GLuint kUnitSource = 0;         ///< the scene, or the kernel image
constexpr GLuint kUnitKernelSpectrum = 1; ///< the kernel's spectrum (the inverse column pass)
constexpr GLuint kImageSpectrum = 0;      ///< the spectrum, read in place
constexpr GLuint kImageTarget = 1;        ///< what a pass writes
constexpr int kMaxThreads = 256;          ///< invocations of a line's workgroup
constexpr int kMaxDivisor = 4;            ///< the coarsest halo, for frames past the longest FFT line

ShaderDefines fftDefines(int size, ShaderDefines extra) {
    const int threads = std::min(size / 2, kMaxThreads);
    ShaderDefines defines{{"FFT_SIZE", std::to_string(size)},
                          {"LOG2_SIZE", std::to_string(std::countr_zero(unsigned(size)))},
                          {"THREADS", std::to_string(threads)},
                          {"UNIT_SOURCE", std::to_string(kUnitSource)},
                          {"UNIT_KERNEL_SPECTRUM", std::to_string(kUnitKernelSpectrum)},
                          {"IMAGE_SPECTRUM", std::to_string(kImageSpectrum)},
                          {"IMAGE_TARGET", std::to_string(kImageTarget)}};
    defines.insert(defines.end(), extra.begin(), extra.end());
    return bindingDefines(std::move(defines));
}

double texelBytes(Extent e, GLenum format) {
    return double(e.width) * double(e.height) * bytesPerTexel(format);
}

} // namespace

int fftSize(int n) {
    return int(std::bit_ceil(unsigned(std::max(1, n))));
}

GlarePass::GlarePass() {
    for (int i = 0; i < Steps; ++i)
        mParameters[std::size_t(i)] = ParameterBlock<GlareFftParameters>(fmt::format("glare step {}", i));
    setDivisor(1);
}

void GlarePass::setDivisor(int divisor) {
    if (divisor != 1 && divisor != 2)
        throw std::invalid_argument(fmt::format("glare divisor {}: 1 or 2", divisor));
    mDivisor = divisor;
}

std::span<const ResourceUse> GlarePass::uses() const {
    static constexpr ResourceUse kUses[] = {{Resource::SceneColor, Access::Read},
                                            {Resource::ExposureState, Access::Read},
                                            {Resource::Camera, Access::ReadOptional},
                                            {Resource::Bloom, Access::Write}};
    return kUses;
}

bool GlarePass::enabled(const FrameContext& ctx) const {
    const BloomSettings& b = ctx.settings.bloom;
    return ctx.hdr && ctx.tier.bloom && b.enabled && b.mode == BloomMode::Glare;
}

float GlarePass::verticalFovDeg(const FrameContext& ctx, const FrameResources& resources) {
    if (resources.has(Resource::Camera) && ctx.inputs.camera != nullptr)
        return ctx.inputs.camera->verticalFov * 180.0f / 3.14159265f;
    return ctx.settings.bloom.fieldOfViewDeg;
}

void GlarePass::resize(Extent extent) {
    mExtent = extent;
}

void GlarePass::execute(FrameContext& ctx, FrameResources& resources) {
    resources.bind(Resource::Bloom, execute({.scene = resources.texture(Resource::SceneColor),
                                             .exposureState = resources.buffer(Resource::ExposureState),
                                             .settings = &ctx.settings.bloom,
                                             .verticalFovDeg = verticalFovDeg(ctx, resources),
                                             .timers = ctx.timers}));
}

const GlarePass::Programs& GlarePass::programs(int rowSize, int columnSize) {
    const auto key = std::pair{rowSize, columnSize};
    if (const auto found = mPrograms.find(key); found != mPrograms.end())
        return found->second;
    Programs p;
    p.rowsScene = makeComputeProgram(kFft, fftDefines(rowSize, {{"ROWS", "1"}, {"LOAD_SCENE", "1"}}));
    p.columnsForward = makeComputeProgram(kFft, fftDefines(columnSize, {}));
    p.columnsInverse =
        makeComputeProgram(kFft, fftDefines(columnSize, {{"INVERSE", "1"}, {"MULTIPLY", "1"}}));
    p.rowsInverse = makeComputeProgram(
        kFft, fftDefines(rowSize, {{"ROWS", "1"}, {"INVERSE", "1"}, {"STORE_GLARE", "1"}}));
    p.kernelRows = makeComputeProgram(kFft, fftDefines(rowSize, {{"ROWS", "1"}, {"LOAD_KERNEL", "1"}}));
    p.kernelColumns = makeComputeProgram(kFft, fftDefines(columnSize, {{"STORE_SPECTRUM", "1"}}));
    p.source = p.rowsScene.sampler("uSource");
    p.kernelSpectrum = p.columnsInverse.sampler("uKernelSpectrum");
    p.spectrumIn = p.columnsForward.image("uSpectrumIn");
    p.spectrumOut = p.rowsScene.image("uSpectrumOut");
    p.kernelOut = p.kernelColumns.image("uKernelOut");
    p.glare = p.rowsInverse.image("uGlare");
    return mPrograms.emplace(key, std::move(p)).first->second;
}

void GlarePass::ensureTargets(Extent glare, Extent padded) {
    if (glare != mGlareExtent || !mGlare.valid()) {
        mGlareExtent = glare;
        mGlare = Texture({.extent = glare, .format = GL_RGBA16F, .debugName = "glare"});
    }
    if (padded != mPadded || !mSpectrum.valid()) {
        mPadded = padded;
        mSpectrum = Texture({.extent = padded, .format = GL_RGBA32F, .debugName = "glare spectrum"});
    }
}

void GlarePass::transform(Step step, const Program& program, int lines, const GlareFftParameters& parameters,
                          Barrier after) {
    ParameterBlock<GlareFftParameters>& block = mParameters[std::size_t(step)];
    block.update(parameters);
    block.bind(kBindingParameters);
    program.use();
    dispatch(program, Groups{GLuint(lines), 1, 1}, after);
}

void GlarePass::ensureKernel(const GlareKernelParameters& p, int radius) {
    if (p == mKernelKey && mPadded == mKernelPadded && radius == mKernelRadius && mKernelSpectrum.valid())
        return;
    DebugGroup group("glare kernel");
    const GlareKernelImage kernel = sampleGlareKernel(p, radius);
    const GlareKernelImage halo = glareHalo(kernel);
    // The halo wrapped about texel (0, 0). The kernel is in image coordinates (y down) and textures keep rows
    // bottom-up (gl/TextureIo.h): offset (dx, dy) goes to texel ((dx + Nx) % Nx, (Ny - dy) % Ny).
    const int nx = mPadded.width, ny = mPadded.height;
    std::vector<float> wrapped(std::size_t(nx) * std::size_t(ny), 0.0f);
    for (int dy = -halo.radius; dy <= halo.radius; ++dy)
        for (int dx = -halo.radius; dx <= halo.radius; ++dx)
            wrapped[std::size_t((ny - dy) % ny) * std::size_t(nx) + std::size_t((dx + nx) % nx)] =
                halo.at(dx, dy);
    // Only its spectrum is kept.
    const Texture image({.extent = mPadded, .format = GL_R32F, .debugName = "glare kernel"});
    glTextureSubImage2D(image.id(), 0, 0, 0, nx, ny, GL_RED, GL_FLOAT, wrapped.data());
    mKernelSpectrum = Texture({.extent = mPadded, .format = GL_RG32F, .debugName = "glare kernel spectrum"});
    const Programs& programs = this->programs(nx, ny);
    bind(programs.source, image);
    bind(programs.spectrumOut, mSpectrum, ImageAccess::Write);
    transform(KernelRows, programs.kernelRows, ny, {.columns = nx, .loadRows = ny, .storeRows = ny});
    bind(programs.spectrumIn, mSpectrum, ImageAccess::Read);
    bind(programs.kernelOut, mKernelSpectrum, ImageAccess::Write);
    transform(KernelColumns, programs.kernelColumns, nx, {.columns = nx, .loadRows = ny, .storeRows = ny});
    mHaloShare = 1.0f - kernel.core();
    mKernelKey = p;
    mKernelPadded = mPadded;
    mKernelRadius = radius;
    ++mKernelBuilds;
}

void GlarePass::convolve(const Texture& scene, int divisor, GpuTimers* timers) {
    const Extent glare = mGlareExtent, padded = mPadded;
    const Programs& programs = this->programs(padded.width, padded.height);
    const double spectrumBytes = texelBytes(padded, GL_RGBA32F);
    bind(programs.source, scene);
    {
        ScopedGpuTimer timer(timers, "glare rows", texelBytes(mExtent, GL_RGBA16F) + spectrumBytes);
        bind(programs.spectrumOut, mSpectrum, ImageAccess::Write);
        transform(RowsScene, programs.rowsScene, glare.height,
                  {.columns = glare.width,
                   .loadRows = glare.height,
                   .storeRows = glare.height,
                   .divisor = divisor});
    }
    bind(programs.spectrumIn, mSpectrum, ImageAccess::Read);
    {
        ScopedGpuTimer timer(timers, "glare columns", 3.0 * spectrumBytes);
        transform(ColumnsForward, programs.columnsForward, padded.width,
                  {.columns = padded.width, .loadRows = glare.height, .storeRows = padded.height});
        bind(programs.kernelSpectrum, mKernelSpectrum);
        transform(ColumnsInverse, programs.columnsInverse, padded.width,
                  {.columns = padded.width, .loadRows = padded.height, .storeRows = glare.height});
    }
    {
        ScopedGpuTimer timer(timers, "glare inverse rows", spectrumBytes + texelBytes(glare, GL_RGBA16F));
        bind(programs.glare, mGlare, ImageAccess::Write);
        transform(RowsInverse, programs.rowsInverse, glare.height,
                  {.columns = glare.width,
                   .loadRows = glare.height,
                   .storeRows = glare.height,
                   .scale = 1.0f / (float(padded.width) * float(padded.height)),
                   .haloShare = mHaloShare},
                  Barrier::ImageWrite); // the tone-map pass samples it
    }
}

const Texture& GlarePass::execute(const Inputs& in) {
    const BloomSettings& b = *in.settings;
    // The first divisor from the pass's own whose image and kernel fit the longest FFT line; past 4, the
    // kernel is clipped instead.
    int divisor = mDivisor;
    Extent glare;
    GlareKernelParameters p;
    int wanted = 0;
    for (;; ++divisor) {
        glare = {(mExtent.width + divisor - 1) / divisor, (mExtent.height + divisor - 1) / divisor};
        p = {.kernel = b.glareKernel,
             .radiusDeg = b.glareRadiusDeg,
             .degreesPerPixel = in.verticalFovDeg * float(divisor) / float(mExtent.height),
             .blades = b.glareBlades,
             .bladeRotationDeg = b.glareBladeRotationDeg};
        wanted = glareKernelRadius(p);
        if (std::max(glare.width, glare.height) + wanted <= kMaxFftSize || divisor == kMaxDivisor)
            break;
    }
    if (divisor != mDivisor) {
        warnOnce(
            "glare-divisor-size",
            fmt::format("glare: a {}x{} frame with a {}-degree kernel does not fit {}-texel FFT lines at "
                        "1/{} of its size; the halo is convolved at 1/{}",
                        mExtent.width, mExtent.height, b.glareRadiusDeg, kMaxFftSize, mDivisor, divisor));
    }
    const int radius = std::max(1, std::min(wanted, kMaxFftSize - std::max(glare.width, glare.height)));
    if (radius < wanted) {
        warnOnce(
            "glare-kernel-clipped",
            fmt::format("bloom.glareRadiusDeg {}: the glare kernel reaches {} pixels, clipped to {} (the "
                        "FFT's {}-texel lines)",
                        b.glareRadiusDeg, wanted, radius, kMaxFftSize));
    }
    const Extent padded{fftSize(glare.width + radius), fftSize(glare.height + radius)};
    ensureTargets(glare, padded);
    DebugGroup group("glare");
    ensureKernel(p, radius);
    bindExposureStateForReading(*in.exposureState);
    convolve(*in.scene, divisor, in.timers);
    return mGlare;
}

} // namespace photopic
