#include "scenes/gradient/GradientScene.h"

#include "gl/ShaderLibrary.h"
#include "scenes/SceneSettings.h"

#include <cmath>
#include <numbers>

namespace photopic {

namespace {

class GradientScene final : public Scene {
public:
    GradientScene()
        : mProgram(makeComputeProgram("scenes/gradient/gradient.comp.glsl")) {}

    [[nodiscard]] std::string_view name() const override { return "gradient"; }

    std::vector<SettingsIssue> applyOverride(std::string_view assignment) override {
        return applySceneOverride(mSettings, name(), assignment);
    }
    [[nodiscard]] std::string settingsJson() const override { return sceneSettingsJson(mSettings); }

    void resize(Extent extent) override {
        if (mColor.valid() && mColor.extent() == extent) {
            return;
        }
        mColor = Texture({.extent = extent, .format = GL_RGBA16F, .debugName = "gradient scene colour"});
    }

    [[nodiscard]] std::vector<std::string> telemetryColumns() const override { return {"sun_height"}; }

    FrameInputs render(const FrameTime& time, Pipeline&, std::vector<double>& telemetry) override {
        // Time is frameIndex * dt, never a clock: frame N is identical on every run.
        const double t = double(time.frameIndex) * double(time.dt);
        const double phase = 2.0 * std::numbers::pi * t / double(mSettings.period);
        const float height = float(0.4 + 0.45 * std::sin(phase)); // UV height of the sun centre, y up
        const Extent e = mColor.extent();
        DebugGroup group("gradient scene");
        setUniform(mProgram, "uSun", 0.5f, height);
        setUniform(mProgram, "uSunRadius", 0.05f);
        setUniform(mProgram, "uSunLuminance", mSettings.sunLuminance);
        setUniform(mProgram, "uSkyLuminance", mSettings.skyLuminance);
        mProgram.use();
        glBindImageTexture(0, mColor.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        glDispatchCompute(GLuint((e.width + 7) / 8), GLuint((e.height + 7) / 8), 1);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        telemetry = {double(height)};
        return {.color = &mColor};
    }

private:
    GradientSceneSettings mSettings;
    Program mProgram;
    Texture mColor;
};

} // namespace

std::unique_ptr<Scene> makeGradientScene() {
    return std::make_unique<GradientScene>();
}

} // namespace photopic
