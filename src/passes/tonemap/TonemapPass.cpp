#include "passes/tonemap/TonemapPass.h"

#include "core/ColorGrading.h"
#include "passes/Bindings.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace photopic {

namespace {
constexpr const char* kVertex = "passes/common/fullscreen.vert.glsl";
constexpr const char* kFragment = "passes/tonemap/tonemap.frag.glsl";
} // namespace

TonemapPass::TonemapPass(const Capabilities& caps)
    : mCaps(caps)
    , mVao(VertexArray::create("fullscreen")) {}

std::span<const ResourceUse> TonemapPass::uses() const {
    static constexpr ResourceUse kUses[] = {{Resource::SceneColor, Access::Read},
                                            {Resource::ExposureState, Access::Read},
                                            {Resource::Bloom, Access::ReadOptional},
                                            {Resource::DisplayColor, Access::Write}};
    return kUses;
}

const Program& TonemapPass::variant(ToneMapper mode, bool bloom, bool glow, bool grade, bool scene) {
    // The scene-referred output stops before the curve: one program serves every mode.
    const int curve = scene ? 0 : int(mode);
    const int key = curve * 16 + (glow ? 8 : 0) + (bloom ? 4 : 0) + (grade ? 2 : 0) + (scene ? 1 : 0);
    auto it = mPrograms.find(key);
    if (it == mPrograms.end()) {
        ShaderDefines defines{{"TONEMAP_MODE", std::to_string(curve)}};
        if (bloom) {
            defines.emplace_back("BLOOM", "1");
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
        it = mPrograms.emplace(key, makeGraphicsProgram(kVertex, kFragment, bindingDefines(defines))).first;
    }
    return it->second;
}

void TonemapPass::configure(const Settings& settings) {
    const ToneMappingSettings& tonemapping = settings.tonemapping;
    const ColorGradingSettings& grading = settings.colorGrading;
    if (legacyGlow(effectiveTier(mCaps, settings.quality), settings)) {
        variant(tonemapping.mode, false, true, grading.enabled, false);
        return;
    }
    for (const bool bloom : {false, true}) {
        variant(tonemapping.mode, bloom, false, grading.enabled, false);
    }
}

void TonemapPass::draw(const Program& program, const Inputs& in, Extent extent) {
    setUniform(program, "uWhitePoint", in.tonemapping->whitePoint);
    setUniform(program, "uAgxLook", int(in.tonemapping->agxLook));
    setUniform(program, "uDither", in.output->dither ? 1 : 0);
    glProgramUniform1ui(program.id(), glGetUniformLocation(program.id(), "uFrame"), GLuint(in.frameIndex));
    if (in.bloom) {
        setUniform(program, "uBloomAdditive", in.bloomSettings->mode == BloomMode::Threshold ? 1 : 0);
        setUniform(program, "uBloomIntensity", in.bloomSettings->intensity);
        glBindTextureUnit(1, in.bloom->id());
    }
    if (in.glow) {
        const BloomSettings& b = *in.bloomSettings;
        setUniform(program, "uGlowThreshold", b.mode == BloomMode::Threshold ? b.threshold : 1.0f);
        setUniform(program, "uGlowIntensity", b.intensity);
        // ~2% of the frame height, as wide as a mid level of the full chain; at least a few pixels.
        setUniform(program, "uGlowRadius", std::max(4.0f, 0.02f * float(extent.height)));
    }
    if (in.grading && in.grading->enabled) {
        const ColorGradingSettings& g = *in.grading;
        const glm::mat3 wb = whiteBalanceMatrix(g.temperature, g.tint);
        glProgramUniformMatrix3fv(program.id(), glGetUniformLocation(program.id(), "uWhiteBalance"), 1,
                                  GL_FALSE, glm::value_ptr(wb));
        setUniform(program, "uContrast", g.contrast);
        setUniform(program, "uSaturation", g.saturation);
        setUniform(program, "uLift", g.lift.x, g.lift.y, g.lift.z);
        setUniform(program, "uInvGamma", 1.0f / g.gamma.x, 1.0f / g.gamma.y, 1.0f / g.gamma.z);
        setUniform(program, "uGain", g.gain.x, g.gain.y, g.gain.z);
    }
    program.use();
    glBindTextureUnit(0, in.scene->id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingExposureState, in.exposureState->id());
    glBindVertexArray(mVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void TonemapPass::execute(FrameContext& ctx, FrameResources& resources) {
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
    PooledTexture& out =
        resources.pool().acquire({.extent = ctx.extent, .format = GL_RGBA8, .debugName = "display"});
    const Extent e = ctx.extent;
    double bytes = double(e.width) * e.height * (bytesPerTexel(in.scene->format()) + 4);
    if (in.bloom) {
        bytes +=
            double(in.bloom->extent().width) * in.bloom->extent().height * bytesPerTexel(in.bloom->format());
    }
    ScopedGpuTimer timer(in.timers, "composite + grade + tonemap", bytes);
    out.framebuffer().bind();
    const bool grade = in.grading && in.grading->enabled;
    draw(variant(in.tonemapping->mode, in.bloom != nullptr, in.glow, grade, false), in, e);
    resources.bind(Resource::DisplayColor, out.texture());
}

const Texture& TonemapPass::renderScene(const Inputs& in) {
    const Extent e = in.scene->extent();
    if (!mScene.valid() || mScene.extent() != e) {
        mScene = Texture({.extent = e, .format = GL_RGBA32F, .debugName = "scene-referred output"});
        mSceneFbo = Framebuffer(mScene, 0, "scene-referred output");
    }
    DebugGroup group("scene-referred output");
    mSceneFbo.bind();
    const bool grade = in.grading && in.grading->enabled;
    draw(variant(in.tonemapping->mode, in.bloom != nullptr, in.glow, grade, true), in, e);
    return mScene;
}

} // namespace photopic
