#include "core/settings/SettingsDescriber.h"

namespace photopic {
namespace {

/// A table cell: `|` would end the cell and a line break the row.
std::string cell(std::string_view text) {
    std::string out;
    for (const char c : text) {
        if (c == '|') {
            out += "\\|";
        } else if (c == '\n') {
            out += ' ';
        } else {
            out += c;
        }
    }
    return out;
}

std::string code(std::string_view text) {
    if (text.empty()) {
        return {};
    }
    std::string out(1, '`');
    out += cell(text);
    out += '`';
    return out;
}

} // namespace

std::string settingsMarkdownTable(const std::vector<SettingDoc>& docs) {
    std::string out = "| Key | Type | Default | Range or values | Meaning |\n|---|---|---|---|---|\n";
    for (const SettingDoc& d : docs) {
        const std::string type = d.alias ? d.type + " (older key, read only)" : d.type;
        out += fmt::format("| {} | {} | {} | {} | {} |\n", code(d.key), cell(type), code(d.defaultJson),
                           cell(d.allowed), cell(d.meaning));
    }
    return out;
}

std::string settingsDifferenceList(const std::vector<SettingDoc>& base,
                                   const std::vector<SettingDoc>& changed) {
    std::string out;
    for (std::size_t i = 0; i < base.size() && i < changed.size(); ++i) {
        if (base[i].key == changed[i].key && base[i].defaultJson != changed[i].defaultJson) {
            out += fmt::format("- {}: {} -> {}\n", code(base[i].key), code(base[i].defaultJson),
                               code(changed[i].defaultJson));
        }
    }
    return out;
}

} // namespace photopic
