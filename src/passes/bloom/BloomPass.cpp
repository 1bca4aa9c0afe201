#include "passes/bloom/BloomPass.h"

#include "core/Bloom.h"
#include "passes/Bindings.h"

#include <fmt/format.h>

#include <algorithm>
#include <string>

namespace photopic {

namespace {
constexpr const char* kDown = "passes/bloom/bloom_downsample.comp.glsl";
constexpr const char* kRows = "passes/bloom/bloom_blur.comp.glsl";
constexpr const char* kUp = "passes/bloom/bloom_upsample.comp.glsl";
constexpr GLenum kFormat = GL_RGBA16F;

double texelBytes(Extent e, GLenum format) {
    return double(e.width) * double(e.height) * bytesPerTexel(format);
}

Program makeStepProgram(const char* file, ShaderDefines defines, PixelGroup group) {
    return makeComputeProgram(file, bindingDefines(withPixelGroup(std::move(defines), group)));
}

/// The blur's weights as the parameter block holds them: weight k in component k % 4 of vector k / 4.
void setBlurWeights(BloomStepParameters& p) {
    const auto w = bloomBlurWeights();
    for (std::size_t k = 0; k < w.size(); ++k) {
        p.weights[k / 4][int(k % 4)] = w[k];
    }
}

/// Texels a blur invocation computes along its axis (bloom_step.h.glsl kRun).
constexpr int kBlurRun = 4;

/// The blurs' #defines: the run an invocation computes and the Gaussian's reach (bloom_step.h.glsl).
ShaderDefines blurDefines(ShaderDefines defines) {
    defines.emplace_back("BLUR_RUN", std::to_string(kBlurRun));
    defines.emplace_back("BLUR_REACH", std::to_string(kBloomBlurReach));
    return defines;
}

void setSourceTexel(BloomStepParameters& p, Extent source) {
    p.sourceTexel[0] = 1.0f / float(source.width);
    p.sourceTexel[1] = 1.0f / float(source.height);
}

} // namespace

BloomPass::BloomPass()
    : mGroup(pixelGroup())
    , mPrefilter(makeStepProgram(kDown, {{"PREFILTER", "1"}}, mGroup))
    , mPrefilterQuarter(makeStepProgram(kDown, {{"PREFILTER", "1"}, {"QUARTER", "1"}}, mGroup))
    , mDownsample(makeStepProgram(kDown, {}, mGroup))
    , mBlurRows(makeStepProgram(kRows, blurDefines({}), mGroup))
    , mUpsample(makeStepProgram(kUp, blurDefines({}), mGroup))
    , mUpsampleCoarse(makeStepProgram(kUp, blurDefines({{"COARSE", "1"}}), mGroup))
    , mSampler(Sampler::linearTransparentBorder("bloom sampler")) {}

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
    mRows.clear();
    mUp.clear();
}

void BloomPass::ensureChain(int firstDivisor, int levels) {
    if (levels == mLevels && firstDivisor == mDivisor && !mDown.empty()) {
        return;
    }
    mDivisor = firstDivisor;
    mLevels = levels;
    mDown.clear();
    mRows.clear();
    mUp.clear();
    mDownBlocks.clear();
    mRowBlocks.clear();
    mUpBlocks.clear();
    for (int i = 0; i < levels; ++i) {
        const glm::ivec2 frame = bloomLevelFrame({mExtent.width, mExtent.height}, firstDivisor, i);
        const Extent banded{frame.x + 2 * kBloomMargin, frame.y + 2 * kBloomMargin};
        const auto texture = [&](Extent e, std::string name) {
            return Texture(TextureCreateInfo{.extent = e, .format = kFormat, .debugName = name});
        };
        mDown.push_back(texture(banded, fmt::format("bloom down {}", i)));
        mRows.push_back(texture(banded, fmt::format("bloom rows {}", i)));
        mUp.push_back(texture(i == 0 ? Extent{frame.x, frame.y} : banded, fmt::format("bloom up {}", i)));
        mDownBlocks.emplace_back(fmt::format("bloom down {} parameters", i));
        mRowBlocks.emplace_back(fmt::format("bloom rows {} parameters", i));
        mUpBlocks.emplace_back(fmt::format("bloom up {} parameters", i));
    }
}

void BloomPass::bindStep(const Step& step, ParameterBlock<BloomStepParameters>& block,
                         const BloomStepParameters& p, const Texture& source, const Texture& target) {
    block.update(p);
    block.bind(kBindingParameters);
    step.program.use();
    bind(step.source, source, mSampler);
    bind(step.target, target, ImageAccess::Write);
}

void BloomPass::downsample(const Inputs& in, int level) {
    const Texture& source = level == 0 ? *in.scene : mDown[std::size_t(level - 1)];
    const Texture& target = mDown[std::size_t(level)];
    ScopedGpuTimer timer(in.timers, level == 0 ? "bloom prefilter" : fmt::format("bloom down {}", level),
                         texelBytes(source.extent(), source.format()) + texelBytes(target.extent(), kFormat));
    BloomStepParameters p;
    setSourceTexel(p, source.extent());
    // Target texel t's centre in the source's texel-centre coordinates: the frame's region of the target
    // starts kBloomMargin texels in, and the source's too (but for the frame itself).
    const float scale = level == 0 ? float(in.firstDivisor) : 2.0f;
    const float origin =
        level == 0 ? 0.5f * (scale - 1.0f) - scale * float(kBloomMargin) : 0.5f - float(kBloomMargin);
    p.sourceScale[0] = p.sourceScale[1] = scale;
    p.sourceOrigin[0] = p.sourceOrigin[1] = origin;
    if (level == 0) {
        p.frameSize[0] = source.extent().width;
        p.frameSize[1] = source.extent().height;
        p.threshold = in.settings->mode == BloomMode::Threshold ? 1 : 0;
        p.knee = bloomKneeConstants(in.settings->threshold, in.settings->knee);
    }
    const Step& step = level > 0 ? mDownsample : in.firstDivisor == 4 ? mPrefilterQuarter : mPrefilter;
    bindStep(step, mDownBlocks[std::size_t(level)], p, source, target);
    const Extent e = target.extent();
    // The prefilter computes 2x2 blocks of targets an invocation; the row blur and the next level read it.
    dispatch(step.program, level == 0 ? Extent{(e.width + 1) / 2, (e.height + 1) / 2} : e,
             Barrier::ComputeRead, mGroup);
}

void BloomPass::blurRows(const Inputs& in, int level) {
    const Texture& source = mDown[std::size_t(level)];
    const Texture& target = mRows[std::size_t(level)];
    ScopedGpuTimer timer(in.timers, fmt::format("bloom rows {}", level),
                         2 * texelBytes(target.extent(), kFormat));
    BloomStepParameters p;
    setSourceTexel(p, source.extent());
    setBlurWeights(p);
    bindStep(mBlurRows, mRowBlocks[std::size_t(level)], p, source, target);
    // The upsample reads it.
    dispatch(mBlurRows.program, {(target.extent().width + kBlurRun - 1) / kBlurRun, target.extent().height},
             Barrier::ComputeRead, mGroup);
}

void BloomPass::upsample(const Inputs& in, int level) {
    const Texture& source = mRows[std::size_t(level)];
    const Texture& target = mUp[std::size_t(level)];
    const bool coarse = level + 1 < mLevels;
    ScopedGpuTimer timer(in.timers, fmt::format("bloom up {}", level),
                         texelBytes(source.extent(), kFormat) + texelBytes(target.extent(), kFormat) +
                             (coarse ? texelBytes(mUp[std::size_t(level + 1)].extent(), kFormat) : 0.0));
    BloomStepParameters p;
    setSourceTexel(p, source.extent());
    setBlurWeights(p);
    // The result (level 0) holds the frame's region alone; the other levels keep their bands.
    p.targetOffset[0] = p.targetOffset[1] = level == 0 ? kBloomMargin : 0;
    if (coarse) {
        const Extent ce = mUp[std::size_t(level + 1)].extent();
        p.coarseTexel[0] = 1.0f / float(ce.width);
        p.coarseTexel[1] = 1.0f / float(ce.height);
        // Level texel q lies at frame position (q - margin + 1/2) * scale; the coarser level's texel Q at
        // (Q - margin + 1/2) * 2 scale.
        p.coarseOrigin[0] = p.coarseOrigin[1] = 0.5f * float(kBloomMargin) - 0.25f;
        p.radius = in.settings->radius;
    }
    const Step& step = coarse ? mUpsampleCoarse : mUpsample;
    bindStep(step, mUpBlocks[std::size_t(level)], p, source, target);
    if (coarse) {
        bind(mCoarse, mUp[std::size_t(level + 1)], mSampler);
    }
    // Level 0 is the chain's result, whatever reads it next; the others, the next upsample.
    dispatch(step.program, {target.extent().width, (target.extent().height + kBlurRun - 1) / kBlurRun},
             level == 0 ? Barrier::ImageWrite : Barrier::ComputeRead, mGroup);
}

const Texture& BloomPass::execute(const Inputs& in) {
    const int levels =
        bloomMipCount({mExtent.width, mExtent.height}, in.firstDivisor, std::max(1, in.mipCount));
    ensureChain(in.firstDivisor, levels);
    DebugGroup group("bloom");
    bindExposureStateForReading(*in.exposureState);
    for (int i = 0; i < levels; ++i) {
        downsample(in, i);
    }
    for (int i = levels - 1; i >= 0; --i) {
        blurRows(in, i);
        upsample(in, i);
    }
    bindSampler(mDownsample.source, nullptr);
    bindSampler(mCoarse, nullptr);
    return mUp[0];
}

} // namespace photopic
