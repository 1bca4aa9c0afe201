#include "passes/bloom/BloomPass.h"

#include "core/Bloom.h"
#include "core/Environment.h"
#include "core/Log.h"
#include "gl/Capabilities.h"
#include "passes/Bindings.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace photopic {

namespace {
constexpr const char* kDown = "passes/bloom/bloom_downsample.comp.glsl";
constexpr const char* kUp = "passes/bloom/bloom_upsample.comp.glsl";
constexpr GLenum kFormat = GL_RGBA16F;
constexpr int kTile = 16; // target texels per side of a tiled prefilter's group (TILES, SHARED_TAPS)

double texelBytes(Extent e, GLenum format) {
    return double(e.width) * double(e.height) * bytesPerTexel(format);
}

/// The binding #defines and `defines` for a program of the invocation shape `group`.
ShaderDefines programDefines(ShaderDefines defines, PixelGroup group) {
    return bindingDefines(withPixelGroup(std::move(defines), group));
}

/// Each prefilter kernel: its name (PHOTOPIC_BLOOM_PREFILTER, the bench), what it reads (the override's
/// report) and the #defines that pick it in bloom_downsample.comp.glsl (besides PREFILTER and KARIS).
struct PrefilterKernelInfo {
    BloomPrefilterKernel kernel;
    const char* name;
    const char* reads;
    ShaderDefines defines; ///< none for Taps, whose programs setBlockSide makes
};

const std::vector<PrefilterKernelInfo>& prefilterKernels() {
    static const std::vector<PrefilterKernelInfo> kernels = [] {
        const std::string tile = std::to_string(kTile);
        return std::vector<PrefilterKernelInfo>{
            {BloomPrefilterKernel::Taps, "taps", "filtered taps", {}},
            {BloomPrefilterKernel::Tiles, "tiles", "tiles of unfiltered scene texels", {{"TILES", tile}}},
            {BloomPrefilterKernel::SharedTaps,
             "shared",
             "filtered taps shared in a group",
             {{"SHARED_TAPS", tile}}},
            {BloomPrefilterKernel::SharedTexels,
             "shared-texels",
             "unfiltered taps shared in a group",
             {{"SHARED_TAPS", tile}, {"SHARED_TEXELS", "1"}}},
        };
    }();
    return kernels;
}

const PrefilterKernelInfo& prefilterKernelInfo(BloomPrefilterKernel kernel) {
    const auto& kernels = prefilterKernels();
    return *std::ranges::find(kernels, kernel, &PrefilterKernelInfo::kernel);
}

} // namespace

const char* bloomPrefilterKernelName(BloomPrefilterKernel kernel) {
    return prefilterKernelInfo(kernel).name;
}

BloomPass::BloomPass()
    : mGroup(pixelGroup())
    , mPrefilter(makeComputeProgram(kDown, programDefines({{"PREFILTER", "1"}, {"KARIS", "1"}}, mGroup)))
    , mDownsample(makeComputeProgram(kDown, programDefines({}, mGroup)))
    , mUpsample(makeComputeProgram(kUp, programDefines({}, mGroup)))
    , mSceneSampler(Sampler::linear("bloom scene sampler")) {
    setBlockSide(isSoftwareRenderer() ? 4 : 2);
    applyEnvironmentOverrides();
}

void BloomPass::applyEnvironmentOverrides() {
    if (const auto side = environmentValue("PHOTOPIC_BLOOM_BLOCK_SIDE")) {
        if (*side == "1" || *side == "2" || *side == "4") {
            setBlockSide(std::stoi(std::string(*side)));
            warnOnce("bloom-block-side", fmt::format("PHOTOPIC_BLOOM_BLOCK_SIDE={}: the bloom downsample "
                                                     "filters blocks of {} x {} target texels",
                                                     *side, *side, *side));
        } else {
            warnOnce("bloom-block-side-bad",
                     fmt::format("PHOTOPIC_BLOOM_BLOCK_SIDE={}: not 1, 2 or 4; ignored", *side));
        }
    }
    if (const auto value = environmentValue("PHOTOPIC_BLOOM_PREFILTER")) {
        const auto& kernels = prefilterKernels();
        const auto kernel =
            std::ranges::find_if(kernels, [&](const PrefilterKernelInfo& k) { return *value == k.name; });
        if (kernel != kernels.end()) {
            setPrefilterKernel(kernel->kernel);
            warnOnce("bloom-prefilter",
                     fmt::format("PHOTOPIC_BLOOM_PREFILTER={}: the bloom prefilter reads {}", *value,
                                 kernel->reads));
        } else {
            std::string names;
            for (const PrefilterKernelInfo& k : kernels) {
                names += fmt::format("{}'{}'", names.empty() ? "" : ", ", k.name);
            }
            warnOnce("bloom-prefilter-bad",
                     fmt::format("PHOTOPIC_BLOOM_PREFILTER={}: not one of {}; ignored", *value, names));
        }
    }
}

void BloomPass::setPrefilterKernel(BloomPrefilterKernel kernel) {
    mPrefilterKernel = kernel;
    ShaderDefines defines = prefilterKernelInfo(kernel).defines;
    if (defines.empty()) {
        mPrefilterTiled = Program();
        return;
    }
    defines.insert(defines.begin(), {{"PREFILTER", "1"}, {"KARIS", "1"}});
    mPrefilterTiled = makeComputeProgram(kDown, bindingDefines(std::move(defines)));
}

void BloomPass::setBlockSide(int side) {
    if (side != 1 && side != 2 && side != 4) {
        throw std::invalid_argument(fmt::format("bloom block side {}: 1, 2 or 4", side));
    }
    const char* blocks = side == 4 ? "BLOCKS_4X4" : "BLOCKS";
    mPrefilterBlocks =
        side == 1 ? Program()
                  : makeComputeProgram(
                        kDown, programDefines({{"PREFILTER", "1"}, {"KARIS", "1"}, {blocks, "1"}}, mGroup));
    mDownsampleBlocks =
        side == 1 ? Program() : makeComputeProgram(kDown, programDefines({{blocks, "1"}}, mGroup));
    mUpsampleBlocks =
        side == 4 ? makeComputeProgram(kUp, programDefines({{"BLOCKS_4X4", "1"}}, mGroup)) : Program();
    mBlockSide = side;
}

std::span<const ResourceUse> BloomPass::uses() const {
    static constexpr ResourceUse kUses[] = {{Resource::SceneColor, Access::Read},
                                            {Resource::ExposureState, Access::Read},
                                            {Resource::Bloom, Access::Write}};
    return kUses;
}

void BloomPass::execute(FrameContext& ctx, FrameResources& resources) {
    const BloomSettings& b = ctx.settings.bloom;
    resources.bind(Resource::Bloom, execute({.scene = resources.texture(Resource::SceneColor),
                                             .exposureState = resources.buffer(Resource::ExposureState),
                                             .settings = &b,
                                             .firstDivisor = ctx.tier.bloomFirstDivisor,
                                             .mipCount = b.mipCount > 0 ? b.mipCount : ctx.tier.bloomMips,
                                             .timers = ctx.timers}));
}

void BloomPass::resize(Extent extent) {
    if (extent == mExtent) {
        return;
    }
    mExtent = extent;
    mLevels = 0; // rebuilt on the next execute, at the size and depth that frame asks for
    mDown.clear();
    mUp.clear();
}

void BloomPass::ensureChain(int firstDivisor, int levels) {
    if (levels == mLevels && firstDivisor == mDivisor && !mDown.empty()) {
        return;
    }
    mDivisor = firstDivisor;
    mLevels = levels;
    mDown.clear();
    mUp.clear();
    mDownParameters.clear();
    mUpParameters.clear();
    for (int i = 0; i < levels; ++i) {
        mDownParameters.emplace_back(fmt::format("bloom down {} parameters", i));
        const glm::ivec2 s = bloomMipSize({mExtent.width, mExtent.height}, firstDivisor, i);
        const std::string down = fmt::format("bloom down {}", i);
        mDown.emplace_back(TextureCreateInfo{.extent = {s.x, s.y}, .format = kFormat, .debugName = down});
        if (i + 1 < levels) {
            mUpParameters.emplace_back(fmt::format("bloom up {} parameters", i));
            const std::string up = fmt::format("bloom up {}", i);
            mUp.emplace_back(TextureCreateInfo{.extent = {s.x, s.y}, .format = kFormat, .debugName = up});
        }
    }
}

const Texture& BloomPass::execute(const Inputs& in) {
    const int levels =
        bloomMipCount({mExtent.width, mExtent.height}, in.firstDivisor, std::max(1, in.mipCount));
    ensureChain(in.firstDivisor, levels);
    DebugGroup group("bloom");
    bindExposureStateForReading(*in.exposureState);

    // Downsample chain; level 0 reads the scene with the prefilter (exposure, Karis, threshold).
    for (int i = 0; i < levels; ++i) {
        const Texture& source = i == 0 ? *in.scene : mDown[std::size_t(i - 1)];
        const Texture& target = mDown[std::size_t(i)];
        const Extent se = source.extent(), te = target.extent();
        const float step = i == 0 ? float(in.firstDivisor) * 0.5f : 1.0f;
        // Taps step by `step` source texels around each target texel; where the target is exactly half the
        // source in those steps, the next target texel's taps are these moved by two steps, and blocks share
        // them.
        const float span = 2.0f * step;
        const bool half =
            float(se.width) == span * float(te.width) && float(se.height) == span * float(te.height);
        const bool blocks = half && mBlockSide > 1;
        // Tiles read every scene texel of a half-size level 0 (taps one texel apart); shared taps need only
        // the half.
        const bool tiles = i == 0 && half && mPrefilterTiled.valid() &&
                           (mPrefilterKernel != BloomPrefilterKernel::Tiles || step == 1.0f);
        const Program& program = tiles    ? mPrefilterTiled
                                 : i == 0 ? (blocks ? mPrefilterBlocks : mPrefilter)
                                          : (blocks ? mDownsampleBlocks : mDownsample);
        ScopedGpuTimer timer(in.timers, i == 0 ? "bloom prefilter" : fmt::format("bloom down {}", i),
                             texelBytes(se, source.format()) + texelBytes(te, kFormat));
        BloomDownsampleParameters parameters{.targetTexel = {1.0f / float(te.width), 1.0f / float(te.height)},
                                             .sourceStep = {step / float(se.width), step / float(se.height)}};
        if (i == 0) {
            parameters.threshold = in.settings->mode == BloomMode::Threshold ? 1 : 0;
            parameters.knee = bloomKneeConstants(in.settings->threshold, in.settings->knee);
        }
        mDownParameters[std::size_t(i)].update(parameters);
        mDownParameters[std::size_t(i)].bind(kBindingParameters);
        program.use();
        glBindTextureUnit(0, source.id());
        glBindSampler(0, i == 0 ? mSceneSampler.id() : 0);
        glBindImageTexture(0, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kFormat);
        const int side = mBlockSide;
        if (tiles) {
            glDispatchCompute(GLuint((te.width + kTile - 1) / kTile), GLuint((te.height + kTile - 1) / kTile),
                              1);
        } else {
            dispatchPixels(blocks ? Extent{(te.width + side - 1) / side, (te.height + side - 1) / side} : te,
                           mGroup);
        }
        // The next level, or with one level the passes after the chain, read this one.
        if (levels == 1)
            imageWriteBarrier();
        else
            computeReadBarrier();
    }
    glBindSampler(0, 0);

    // Upsample chain, smallest level first: up[i] = mix(down[i], tent(up[i + 1]), radius).
    for (int i = levels - 2; i >= 0; --i) {
        const Texture& coarse = i == levels - 2 ? mDown[std::size_t(levels - 1)] : mUp[std::size_t(i + 1)];
        const Texture& fine = mDown[std::size_t(i)];
        const Extent ce = coarse.extent(), te = fine.extent();
        ScopedGpuTimer timer(in.timers, fmt::format("bloom up {}", i),
                             texelBytes(ce, kFormat) + 2 * texelBytes(te, kFormat));
        ParameterBlock<BloomUpsampleParameters>& block = mUpParameters[std::size_t(i)];
        block.update({.targetTexel = {1.0f / float(te.width), 1.0f / float(te.height)},
                      .coarseTexel = {1.0f / float(ce.width), 1.0f / float(ce.height)},
                      .radius = in.settings->radius});
        block.bind(kBindingParameters);
        // 4x4 blocks where the level is exactly twice the coarser one: their tent weights are constants.
        const bool blocks = mUpsampleBlocks.valid() && te.width == 2 * ce.width && te.height == 2 * ce.height;
        (blocks ? mUpsampleBlocks : mUpsample).use();
        glBindTextureUnit(0, coarse.id());
        glBindTextureUnit(1, fine.id());
        glBindImageTexture(0, mUp[std::size_t(i)].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kFormat);
        dispatchPixels(blocks ? Extent{(te.width + 3) / 4, (te.height + 3) / 4} : te, mGroup);
        if (i == 0)
            imageWriteBarrier(); // the chain's result: whatever reads it next
        else
            computeReadBarrier(); // the next upsample
    }
    return levels == 1 ? mDown[0] : mUp[0];
}

} // namespace photopic
