// photopic-view's panels (ViewerPanels.h).
#include "ViewerPanels.h"

#include "SettingsEditor.h"
#include "ViewerKeys.h"

#include "core/settings/SettingsJson.h"
#include "io/ImageIO.h"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace photopic::viewer {

namespace {

void row(const char* name, const std::string& value) {
    ImGui::TextUnformatted(name);
    // Long names (the fused composite pass) push their value right rather than overlap it.
    ImGui::SameLine(std::max(150.0f, ImGui::CalcTextSize(name).x + 16.0f));
    ImGui::TextUnformatted(value.c_str());
}

bool evSlider(const char* label, float& ev) {
    // Shown as EV with the multiplier beside it: users think of the bounds as multipliers (0.25 .. 4).
    const std::string format = fmt::format("%.2f EV (x{:.3g})", std::exp2(ev));
    return ImGui::SliderFloat(label, &ev, -8.0f, 8.0f, format.c_str(), ImGuiSliderFlags_AlwaysClamp);
}

/// The "Dynamic Exposure" folder: the adaptation bounds and timing.
bool dynamicExposurePanel(Settings& s) {
    bool changed = false;
    AutoExposureSettings& ae = s.autoExposure;
    changed |= ImGui::Checkbox("enabled", &ae.enabled);
    if (evSlider("minExposure", ae.minEV)) {
        ae.maxEV = std::max(ae.maxEV, ae.minEV); // keep minEV <= maxEV while dragging, as the settings demand
        changed = true;
    }
    if (evSlider("maxExposure", ae.maxEV)) {
        ae.minEV = std::min(ae.minEV, ae.maxEV);
        changed = true;
    }
    changed |= ImGui::SliderFloat("probeHz", &s.subjects.probe.hz, 0.1f, 240.0f, "%.3g Hz",
                                  ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::SliderFloat("tauBrighten", &ae.tauBrighten, 0.001f, 30.0f, "%.3g s",
                                  ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::SliderFloat("tauDarken", &ae.tauDarken, 0.001f, 30.0f, "%.3g s",
                                  ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    return changed;
}

const char* sourceName(SubjectSource source) {
    switch (source) {
    case SubjectSource::Controlled:
        return "controlled";
    case SubjectSource::OwnCharacter:
        return "own character";
    case SubjectSource::Center:
        return "screen centre";
    case SubjectSource::None:
        break;
    }
    return "none";
}

/// "Debug (Selected Token)": read from the context API, which never waits on the GPU (probe
/// results are a frame or more old), so drawing it cannot stall the frame.
void debugPanel(const Pipeline& pipeline) {
    const SubjectTracker& tracker = pipeline.subjects();
    const SubjectContext* c = pipeline.subjectContext();
    row("selection", sourceName(tracker.selection().source));
    if (!c) {
        ImGui::TextDisabled("no subject this frame");
        return;
    }
    row("subjectTokenId", fmt::format("{}", c->id));
    row("measuredLuma", fmt::format("{:.4f}", c->measuredLuma));
    row("outdoors", fmt::format("{:.3f}", c->outdoors));
    row("targetExposure", fmt::format("x{:.3f} ({:+.2f} EV)", std::exp2(c->targetLog2), c->targetLog2));
    row("appliedExposure", fmt::format("x{:.3f} ({:+.2f} EV)", std::exp2(c->appliedLog2), c->appliedLog2));
    row("screenUv.u", fmt::format("{:.3f}", c->screenUv.x));
    row("screenUv.v", fmt::format("{:.3f}", c->screenUv.y));
    row("lastProbeAgeSeconds", c->lastProbeAt < 0.0f
                                   ? std::string("never")
                                   : fmt::format("{:.3f}", tracker.time() - c->lastProbeAt));
}

void telemetryPanel(Pipeline& pipeline, float dt) {
    const ExposureTelemetry& t = pipeline.telemetry();
    const PipelineStatus status = pipeline.status();
    row("frame dt", fmt::format("{:.1f} ms", dt * 1000.0f));
    row("path", status.path == ColorPath::Hdr ? "HDR" : "LDR");
    ImGui::TextWrapped("(%s)", status.pathReason.c_str());
    row("quality", std::string(qualityNames()[std::size_t(status.quality)]));
    if (!t.valid) {
        ImGui::TextDisabled("exposure telemetry not back yet");
    } else {
        row("telemetry frame", fmt::format("{}", t.frame));
        row("metered luminance", fmt::format("{:.4f}", t.meteredLuminance));
        row("target / applied", fmt::format("{:+.2f} / {:+.2f} EV", t.targetLog2, t.appliedLog2));
        row("exposure", fmt::format("x{:.3f}{}", t.exposure, t.adapting ? " (adapting)" : ""));
    }
    double total = 0.0;
    for (const PassTiming& p : status.passes) {
        row(p.name.c_str(), fmt::format("{:.3f} ms", p.gpuMs));
        total += p.gpuMs;
    }
    if (!status.passes.empty()) {
        row("total GPU", fmt::format("{:.3f} ms", total));
    }
}

} // namespace

void saveSettings(const Settings& settings, const std::filesystem::path& path, UiState& ui) {
    try {
        writeTextFile(path, settingsToJson(settings));
        ui.message = "saved " + path.string();
    } catch (const std::exception& e) {
        ui.message = e.what();
    }
}

/// Applies `ui.edited` to the pipeline when it has no problems (as an edit in the panels does).
void applyEdited(Pipeline& pipeline, UiState& ui) {
    ui.problems = settingsProblems(ui.edited);
    if (ui.problems.empty()) {
        try {
            pipeline.setSettings(ui.edited);
        } catch (const std::exception& e) {
            ui.problems.emplace_back(e.what());
        }
    }
}

void drawPanels(Pipeline& pipeline, const ViewerOptions& options, UiState& ui) {
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(300, ImGui::GetIO().DisplaySize.y - 16), ImGuiCond_FirstUseEver);
    ImGui::Begin("Photopic");
    ImGui::PushItemWidth(150.0f);
    bool changed = false;
    ImGui::SetNextItemOpen(true, ImGuiCond_FirstUseEver);
    if (ImGui::CollapsingHeader("Dynamic Exposure")) {
        changed |= dynamicExposurePanel(ui.edited);
    }
    ImGui::SetNextItemOpen(true, ImGuiCond_FirstUseEver);
    if (ImGui::CollapsingHeader("Debug (Selected Token)")) {
        debugPanel(pipeline);
    }
    if (ImGui::CollapsingHeader("Exposure telemetry and status")) {
        telemetryPanel(pipeline, ui.dt);
    }
    if (ImGui::CollapsingHeader("All settings")) {
        changed |= editSettings(ui.edited);
    }
    if (ImGui::Button("Save JSON")) {
        saveSettings(pipeline.settings(), options.save, ui);
    }
    ImGui::SameLine();
    if (ImGui::Button("Reset exposure")) {
        pipeline.resetExposure();
        ui.message = "exposure reset";
    }
    if (!ui.message.empty()) {
        ImGui::TextWrapped("%s", ui.message.c_str());
    }
    if (ImGui::CollapsingHeader("Keys")) {
        for (const KeyBinding& k : viewerKeys()) {
            row(std::string(k.key).c_str(), std::string(k.action));
        }
    }
    if (changed) {
        applyEdited(pipeline, ui); // a set-up boundary: e.g. an unreadable mask file
    }
    for (const std::string& p : ui.problems) {
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "not applied: %s", p.c_str());
    }
    ImGui::PopItemWidth();
    ImGui::End();
}

} // namespace photopic::viewer
