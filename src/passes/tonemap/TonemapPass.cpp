#include "passes/tonemap/TonemapPass.h"

#include "core/ColorGrading.h"
#include "core/Log.h"
#include "gl/Capabilities.h"
#include "passes/Bindings.h"
#include "passes/DisplayProgram.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace photopic {

namespace {
constexpr const char* kCompute = "passes/tonemap/tonemap.comp.glsl";

/// passes/common/noise.h.glsl pcgHash, bit for bit (32-bit unsigned arithmetic wraps the same way).
std::uint32_t pcgHash(std::uint32_t v) {
    const std::uint32_t state = v * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

/// Frame pixels per texel of a bloom image: the least power of two whose texels cover the frame (a chain's
/// level 0 holds ceil(frame / divisor) texels).
int bloomPixels(Extent frame, Extent bloom) {
    int scale = 1;
    while (scale < 64 && (scale * bloom.width < frame.width || scale * bloom.height < frame.height)) {
        scale *= 2;
    }
    return scale;
}
} // namespace

TonemapPass::TonemapPass(const Capabilities& caps)
    : mParameters("tonemap parameters")
    , mCaps(caps)
    , mGroup(pixelGroup())
    , mBloomBlocks(isSoftwareRenderer()) {}

void TonemapPass::setBloomBlocks(bool on) {
    mBloomBlocks = on;
}

bool TonemapPass::bloomBlocks(const Inputs& in, Extent target) const {
    if (!mBloomBlocks || in.bloom == nullptr) {
        return false;
    }
    const Extent b = in.bloom->extent();
    return target.width == 2 * b.width && target.height == 2 * b.height;
}

std::span<const ResourceUse> TonemapPass::uses() const {
    static constexpr ResourceUse kUses[] = {{Resource::SceneColor, Access::Read},
                                            {Resource::ExposureState, Access::Read},
                                            {Resource::Bloom, Access::ReadOptional},
                                            {Resource::DisplayColor, Access::Write}};
    return kUses;
}

const TonemapPass::Variant& TonemapPass::variant(ToneMapper mode, bool bloom, bool glow, bool grade,
                                                 bool scene, bool display16, bool blocks) {
    // The scene-referred output stops before the curve: one program serves every mode and depth.
    const int curve = scene ? 0 : int(mode);
    display16 = display16 && !scene;
    blocks = blocks && bloom;
    const int key = (blocks ? 512 : 0) + (display16 ? 256 : 0) + curve * 16 + (glow ? 8 : 0) +
                    (bloom ? 4 : 0) + (grade ? 2 : 0) + (scene ? 1 : 0);
    auto it = mPrograms.find(key);
    if (it == mPrograms.end()) {
        ShaderDefines defines =
            withDisplayStore({{"TONEMAP_MODE", std::to_string(curve)}}, display16 ? 16 : 8);
        if (bloom) {
            defines.emplace_back("BLOOM", "1");
        }
        if (blocks) {
            defines.emplace_back("BLOOM_BLOCKS", "1");
        }
        if (glow) {
            defines.emplace_back("GLOW", "1");
        }
        if (grade) {
            defines.emplace_back("GRADE", "1");
        }
        if (scene) {
            defines.emplace_back("OUTPUT_SCENE", "1");
        }
        defines = withPixelGroup(std::move(defines), mGroup);
        it = mPrograms.emplace(key, Variant(makeComputeProgram(kCompute, bindingDefines(defines)))).first;
    }
    return it->second;
}

void TonemapPass::configure(const Settings& settings) {
    const ToneMappingSettings& tonemapping = settings.tonemapping;
    const ColorGradingSettings& grading = settings.colorGrading;
    const bool display16 = settings.output.bitDepth == 16;
    if (legacyGlow(effectiveTier(mCaps, settings.quality), settings)) {
        variant(tonemapping.mode, false, true, grading.enabled, false, display16);
        return;
    }
    for (const bool bloom : {false, true}) {
        variant(tonemapping.mode, bloom, false, grading.enabled, false, display16, bloom && mBloomBlocks);
    }
}

void TonemapPass::run(const Variant& variant, const Inputs& in, const Texture& target, bool blocks) {
    const Extent extent = target.extent();
    // The dither hides 8-bit steps (1/255 apart). At 16 bits a step is 1/257 of that, far below what a
    // display or an eye resolves, so there is no banding to hide; noise scaled to that step would only make
    // the file compress worse, and without it a 16-bit image is the same from frame to frame.
    const bool dither = in.output->dither && in.output->bitDepth == 8;
    TonemapParameters parameters{.whitePoint = in.tonemapping->whitePoint,
                                 .agxLook = int(in.tonemapping->agxLook),
                                 .dither = dither ? 1 : 0,
                                 .frame = std::uint32_t(in.frameIndex)};
    // The dither's two seeds for this frame: its pattern changes with every frame index.
    parameters.ditherSeeds[0] = pcgHash(parameters.frame * 2u);
    parameters.ditherSeeds[1] = pcgHash(parameters.frame * 2u + 1u);
    if (in.bloom) {
        // Glare mixes as energy-conserving bloom does: its image is the halo's share of the glare, alpha
        // that share (passes/glare/GlarePass.h).
        parameters.bloomAdditive = in.bloomSettings->mode == BloomMode::Threshold ? 1 : 0;
        parameters.bloomIntensity = in.bloomSettings->intensity;
        parameters.bloomPixels = float(bloomPixels(extent, in.bloom->extent()));
        bind(variant.bloom, *in.bloom);
    }
    if (in.glow) {
        const BloomSettings& b = *in.bloomSettings;
        parameters.glowThreshold = b.mode == BloomMode::Threshold ? b.threshold : 1.0f;
        parameters.glowIntensity = b.intensity;
        // ~2% of the frame height, as wide as a mid level of the full chain; at least a few pixels.
        parameters.glowRadius = std::max(4.0f, 0.02f * float(extent.height));
    }
    if (in.grading && in.grading->enabled) {
        const ColorGradingSettings& g = *in.grading;
        const glm::mat3 wb = whiteBalanceMatrix(g.temperature, g.tint);
        for (int c = 0; c < 3; ++c) {
            for (int r = 0; r < 3; ++r) {
                parameters.whiteBalance[c][r] = wb[c][r];
            }
        }
        parameters.contrast = g.contrast;
        parameters.saturation = g.saturation;
        parameters.lift[0] = g.lift.x;
        parameters.lift[1] = g.lift.y;
        parameters.lift[2] = g.lift.z;
        parameters.invGamma[0] = 1.0f / g.gamma.x;
        parameters.invGamma[1] = 1.0f / g.gamma.y;
        parameters.invGamma[2] = 1.0f / g.gamma.z;
        parameters.gain[0] = g.gain.x;
        parameters.gain[1] = g.gain.y;
        parameters.gain[2] = g.gain.z;
    }
    mParameters.update(parameters);
    mParameters.bind(kBindingParameters);
    variant.program.use();
    bind(variant.scene, *in.scene);
    bindExposureStateForReading(*in.exposureState);
    bind(variant.output, target, ImageAccess::Write);
    dispatch(variant.program, blocks ? Extent{(extent.width + 3) / 4, (extent.height + 3) / 4} : extent,
             Barrier::ImageWrite, mGroup);
}

void TonemapPass::execute(FrameContext& ctx, FrameResources& resources) {
    const BloomSettings& bloom = ctx.settings.bloom;
    if (bloom.enabled && bloom.mode == BloomMode::Glare && (!ctx.hdr || !ctx.tier.bloom)) {
        // The glare's FFT runs on the HDR path's scene only; the LDR path's cheap glow stands in, if any.
        warnOnce("bloom-glare-unavailable",
                 fmt::format("bloom.mode = glare needs the HDR path and a quality tier with bloom ({}); {}",
                             ctx.hdr ? "this tier has no bloom" : "this frame runs the LDR path",
                             !ctx.hdr && legacyGlow(ctx.tier, ctx.settings)
                                 ? "the LDR path's single cheap glow stands in"
                                 : "no glare is drawn"));
    }
    const Inputs in{.scene = resources.texture(Resource::SceneColor),
                    .exposureState = resources.buffer(Resource::ExposureState),
                    .tonemapping = &ctx.settings.tonemapping,
                    .output = &ctx.settings.output,
                    .bloom = resources.texture(Resource::Bloom),
                    .bloomSettings = &ctx.settings.bloom,
                    .glow = !ctx.hdr && legacyGlow(ctx.tier, ctx.settings),
                    .grading = &ctx.settings.colorGrading,
                    .frameIndex = ctx.time.frameIndex,
                    .timers = ctx.timers};
    const int bitDepth = ctx.settings.output.bitDepth;
    PooledTexture& out = resources.pool().acquire(
        {.extent = ctx.extent, .format = displayFormat(bitDepth), .debugName = "display"});
    const Extent e = ctx.extent;
    double bytes = double(e.width) * e.height *
                   (bytesPerTexel(in.scene->format()) + bytesPerTexel(out.texture().format()));
    if (in.bloom) {
        bytes +=
            double(in.bloom->extent().width) * in.bloom->extent().height * bytesPerTexel(in.bloom->format());
    }
    ScopedGpuTimer timer(in.timers, "composite + grade + tonemap", bytes);
    const bool grade = in.grading && in.grading->enabled;
    const bool blocks = bloomBlocks(in, out.texture().extent());
    run(variant(in.tonemapping->mode, in.bloom != nullptr, in.glow, grade, false, bitDepth == 16, blocks), in,
        out.texture(), blocks);
    resources.bind(Resource::DisplayColor, out.texture());
}

const Texture& TonemapPass::renderScene(const Inputs& in) {
    const Extent e = in.scene->extent();
    if (!mScene.valid() || mScene.extent() != e) {
        mScene = Texture({.extent = e, .format = GL_RGBA32F, .debugName = "scene-referred output"});
    }
    DebugGroup group("scene-referred output");
    const bool grade = in.grading && in.grading->enabled;
    const bool blocks = bloomBlocks(in, e);
    run(variant(in.tonemapping->mode, in.bloom != nullptr, in.glow, grade, true, false, blocks), in, mScene,
        blocks);
    return mScene;
}

} // namespace photopic
