#include "SettingsEditor.h"

#include "core/settings/SettingsJson.h"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cstring>
#include <string_view>

namespace photopic::viewer {
namespace {

/// A range spanning two decades or more gets a logarithmic slider: a linear one leaves the small values
/// (tau 0.001..30 s, bloom radii) on the first few pixels.
bool spansDecades(Range r) {
    if (r.min > 0.0) {
        return r.max / r.min >= 100.0;
    }
    return r.min == 0.0 && r.max >= 100.0;
}

/// Labels are the JSON keys (what --set and the saved file use), IDs are unique per object through PushID.
class ImGuiEditor {
public:
    bool changed = false;

    void field(std::string_view key, bool& value, std::string_view doc = {}) {
        changed |= ImGui::Checkbox(label(key), &value);
        tooltip(doc);
    }
    void field(std::string_view key, float& value, Range range, std::string_view doc = {}) {
        ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp;
        if (spansDecades(range)) {
            flags |= ImGuiSliderFlags_Logarithmic;
        }
        changed |= ImGui::SliderFloat(label(key), &value, float(range.min), float(range.max), "%.4g", flags);
        tooltip(doc);
    }
    void field(std::string_view key, int& value, Range range, std::string_view doc = {}) {
        const int lo = int(std::max(range.min, double(INT_MIN / 2)));
        const int hi = int(std::min(range.max, double(INT_MAX / 2)));
        ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp;
        if (spansDecades(range)) {
            flags |= ImGuiSliderFlags_Logarithmic;
        }
        changed |= ImGui::SliderInt(label(key), &value, lo, hi, "%d", flags);
        tooltip(doc);
    }
    void field(std::string_view key, std::string& value, std::string_view doc = {}) {
        // Applied on Enter only: a path field (e.g. subjects.outdoors mask) would otherwise be reloaded, and
        // fail, on every keystroke.
        std::array<char, 1024> buffer{};
        std::strncpy(buffer.data(), value.c_str(), buffer.size() - 1);
        if (ImGui::InputText(label(key), buffer.data(), buffer.size(),
                             ImGuiInputTextFlags_EnterReturnsTrue)) {
            value = buffer.data();
            changed = true;
        }
        tooltip(doc);
    }
    void field(std::string_view key, glm::vec2& value, Range range, std::string_view doc = {}) {
        changed |= ImGui::SliderFloat2(label(key), &value.x, float(range.min), float(range.max), "%.3g",
                                       ImGuiSliderFlags_AlwaysClamp);
        tooltip(doc);
    }
    void field(std::string_view key, glm::vec3& value, Range range, std::string_view doc = {}) {
        if (range.min == 0.0 && range.max == 1.0) {
            changed |= ImGui::ColorEdit3(label(key), &value.x, ImGuiColorEditFlags_Float);
        } else {
            changed |= ImGui::SliderFloat3(label(key), &value.x, float(range.min), float(range.max), "%.3g",
                                           ImGuiSliderFlags_AlwaysClamp);
        }
        tooltip(doc);
    }
    void field(std::string_view key, CurvePoints& points, Range, std::string_view doc = {}) {
        // Curves are edited in the JSON file; a point editor is not worth its weight here.
        ImGui::TextDisabled("%s: %zu points (edit in the JSON file)", label(key), points.size());
        tooltip(doc);
    }
    void field(std::string_view key, IdList& ids, Range, std::string_view doc = {}) {
        // Id lists are short and edited rarely: in the JSON file or with --set key=[1,2].
        std::string text;
        for (std::size_t i = 0; i < ids.size(); ++i) {
            text += fmt::format("{}{}", i ? ", " : "", ids[i]);
        }
        ImGui::TextDisabled("%s: [%s] (edit in the JSON file)", label(key), text.c_str());
        tooltip(doc);
    }
    template <class E>
    requires std::is_enum_v<E>
    void field(std::string_view key, E& value, std::span<const std::string_view> names,
               std::string_view doc = {}) {
        const auto current = static_cast<std::size_t>(value);
        const std::string preview(current < names.size() ? names[current] : std::string_view("?"));
        if (ImGui::BeginCombo(label(key), preview.c_str())) {
            for (std::size_t i = 0; i < names.size(); ++i) {
                const std::string name(names[i]);
                if (ImGui::Selectable(name.c_str(), i == current) && i != current) {
                    value = static_cast<E>(i);
                    changed = true;
                }
            }
            ImGui::EndCombo();
        }
        tooltip(doc);
    }
    template <class S>
    void object(std::string_view key, S& sub) {
        if (ImGui::TreeNode(label(key))) {
            sub.visit(*this);
            ImGui::TreePop();
        }
    }
    template <class F>
    void alias(std::string_view, Range, F&&, std::string_view = {}) {
    }                                                         // older keys are read from files, never edited
    void require(bool, std::string_view, std::string_view) {} // settingsProblems() reports these

private:
    /// The field's description (the text docs/settings.md prints) when the pointer rests on its widget.
    static void tooltip(std::string_view doc) {
        if (!doc.empty() && ImGui::IsItemHovered()) {
            ImGui::SetTooltip("%.*s", int(doc.size()), doc.data());
        }
    }
    const char* label(std::string_view key) {
        mLabel.assign(key);
        return mLabel.c_str();
    }
    std::string mLabel;
};

} // namespace

bool editSettings(Settings& settings) {
    ImGuiEditor editor;
    settings.visit(editor);
    return editor.changed;
}

std::vector<std::string> settingsProblems(const Settings& settings) {
    Settings copy = settings;
    std::vector<std::string> lines;
    for (const SettingsIssue& issue : readSettingsJson(settingsToJson(settings), copy)) {
        lines.push_back(fmt::format("{}: {}", issue.path, issue.message));
    }
    return lines;
}

} // namespace photopic::viewer
