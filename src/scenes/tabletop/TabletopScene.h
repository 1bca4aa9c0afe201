#pragma once

#include "core/OutdoorsMask.h"
#include "core/Subjects.h"
#include "scenes/Scene.h"

#include <glm/vec2.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace photopic {

/// The tabletop, the eye-adaptation demo's host: a procedural battle map with a sunlit field, a roofed
/// building with three torch-lit rooms, tokens, and a player token that walks out of the building and back
/// in. Deterministic per frame index (time = frameIndex * dt). Its outdoors mask is the roof of the building.
struct TabletopSceneSettings {
    float sunIlluminance = 5.0f;
    float darkness = 0.0f;
    float torchIntensity = 1.5f;
    float flicker = 0.05f;
    float viewHeight = 900.0f;
    float loopSeconds = 24.0f;

    template <class V>
    void visit(V& v) {
        v.field("sunIlluminance", sunIlluminance, Range{0, 1000},
                "scene-linear irradiance: the field at noon; a token outdoors reads ~25x what it reads by "
                "the torch inside the door");
        v.field("darkness", darkness, Range{0, 1},
                "Foundry's darkness level; scales the outdoor light down to 3% (a moonlit night) at 1");
        v.field("torchIntensity", torchIntensity, Range{0, 100},
                "scene-linear irradiance at a torch's core radius");
        v.field("flicker", flicker, Range{0, 0.5}, "torch flicker amplitude (a fraction of the light)");
        v.field("viewHeight", viewHeight, Range{100, 2000}, "world units: height of the camera's window");
        v.field("loopSeconds", loopSeconds, Range{20, 600}, "s: the player's walk repeats with this period");
    }
};

class TabletopScene final : public Scene {
public:
    static constexpr std::uint32_t kPlayerId = 1;
    /// The map: 32 x 20 grid squares of 100 world units; the outdoors mask covers it.
    static constexpr SceneRect kMapRect{0.0f, 0.0f, 3200.0f, 2000.0f};

    /// Needs a current GL 4.5 context (compiles the scene's shader).
    TabletopScene();

    [[nodiscard]] std::string_view name() const override { return "tabletop"; }
    [[nodiscard]] Settings defaultSettings() const override;
    std::vector<SettingsIssue> applyOverride(std::string_view assignment) override;
    [[nodiscard]] std::string settingsJson() const override;
    void resize(Extent extent) override;
    /// subject,world_x,world_y,screen_u,screen_v,outdoors: the subject of the view (controlled, else own
    /// character).
    [[nodiscard]] std::vector<std::string> telemetryColumns() const override;
    FrameInputs render(const FrameTime& time, Pipeline& pipeline, std::vector<double>& telemetry) override;

    [[nodiscard]] const TabletopSceneSettings& settings() const { return mSettings; }
    /// The subjects of the last rendered frame: every token, the player controlled and the user's character.
    [[nodiscard]] const std::vector<Subject>& subjects() const { return mSubjects; }
    /// The roof mask (8-bit; coordinates as core/OutdoorsMask.h states them).
    [[nodiscard]] const OutdoorsMask& outdoorsMask() const { return mMask; }
    /// World position of the player at `seconds` of frame time: inside until ~3.9 s, outside until ~11.7 s,
    /// inside again (standing by the door until 15 s, then by the fire), looping every loopSeconds.
    [[nodiscard]] static glm::vec2 playerWorldAt(double seconds, double loopSeconds = 24.0);
    /// Flicker multiplier of torch `index` at `seconds`: 1 +- amplitude, smooth, deterministic.
    [[nodiscard]] static float torchFlicker(int index, double seconds, float amplitude);

private:
    TabletopSceneSettings mSettings;
    Program mProgram;
    Texture mColor;
    Texture mMaskTexture;
    OutdoorsMask mMask;
    std::vector<Subject> mSubjects;
};

std::unique_ptr<Scene> makeTabletopScene();

} // namespace photopic
