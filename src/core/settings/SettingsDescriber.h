#pragma once
// The settings reference: a visitor over the settings reflection that lists every field with its full key,
// type, default, range or allowed names and meaning (the description argument of field()), and the
// Markdown table that docs/settings.md and `photopic settings --markdown` print.

#include "core/settings/JsonVisitors.h"

#include <string>
#include <string_view>
#include <vector>

namespace photopic {

/// One row of the settings reference.
struct SettingDoc {
    std::string key;         ///< full path below the document's root, e.g. "bloom.intensity"
    std::string type;        ///< bool, number, integer, string, enum, number[2], number[3], points, id list
    std::string defaultJson; ///< the default as JSON text, e.g. 0.04, true, "aces-fitted"
    std::string allowed;     ///< "[min, max]", the enum names, or empty
    std::string meaning;     ///< the field's description; empty when visit() gave none
    bool alias = false;      ///< an older key that is read but never written
};

namespace settings_json {

/// Collects a SettingDoc per field of a settings struct, keys prefixed with `root` ("" for none).
class SettingsDescriber {
public:
    SettingsDescriber(std::string root, std::vector<SettingDoc>& out)
        : mRoot(std::move(root))
        , mOut(out) {}

    void field(std::string_view key, bool& value, std::string_view doc = {}) {
        add(key, "bool", value, doc, "true, false", [&](JsonWriter& w) { w.field(key, value); });
    }
    void field(std::string_view key, float& value, Range range, std::string_view doc = {}) {
        add(key, "number", value, doc, interval(range), [&](JsonWriter& w) { w.field(key, value, range); });
    }
    void field(std::string_view key, int& value, Range range, std::string_view doc = {}) {
        add(key, "integer", value, doc, interval(range), [&](JsonWriter& w) { w.field(key, value, range); });
    }
    void field(std::string_view key, std::string& value, std::string_view doc = {}) {
        add(key, "string", value, doc, "", [&](JsonWriter& w) { w.field(key, value); });
    }
    void field(std::string_view key, glm::vec2& value, Range range, std::string_view doc = {}) {
        add(key, "number[2]", value, doc, "each in " + interval(range),
            [&](JsonWriter& w) { w.field(key, value, range); });
    }
    void field(std::string_view key, glm::vec3& value, Range range, std::string_view doc = {}) {
        add(key, "number[3]", value, doc, "each in " + interval(range),
            [&](JsonWriter& w) { w.field(key, value, range); });
    }
    void field(std::string_view key, CurvePoints& points, Range range, std::string_view doc = {}) {
        add(key, "[x, y] points", points, doc, "x, y each in " + interval(range),
            [&](JsonWriter& w) { w.field(key, points, range); });
    }
    void field(std::string_view key, IdList& ids, Range range, std::string_view doc = {}) {
        add(key, "id list", ids, doc, "each in " + interval(range),
            [&](JsonWriter& w) { w.field(key, ids, range); });
    }
    template <class E>
    requires std::is_enum_v<E>
    void field(std::string_view key, E& value, std::span<const std::string_view> names,
               std::string_view doc = {}) {
        add(key, "enum", value, doc, joinNames(names), [&](JsonWriter& w) { w.field(key, value, names); });
    }
    template <class S>
    void object(std::string_view key, S& sub) {
        SettingsDescriber child(path(key), mOut);
        sub.visit(child);
    }
    template <class F>
    void alias(std::string_view key, Range range, F&&, std::string_view doc = {}) {
        mOut.push_back({path(key), "number", "", interval(range), std::string(doc), true});
    }
    void require(bool, std::string_view, std::string_view) {}

private:
    static std::string interval(Range r) { return fmt::format("[{}, {}]", r.min, r.max); }
    std::string path(std::string_view key) const {
        return mRoot.empty() ? std::string(key) : mRoot + "." + std::string(key);
    }
    template <class T, class Write>
    void add(std::string_view key, std::string type, const T&, std::string_view doc, std::string allowed,
             Write&& write) {
        json value = json::object();
        JsonWriter writer(value);
        write(writer);
        mOut.push_back({path(key), std::move(type), shown(value[std::string(key)]), std::move(allowed),
                        std::string(doc), false});
    }

    std::string mRoot;
    std::vector<SettingDoc>& mOut;
};

} // namespace settings_json

/// Every field of `settings` (its values as the defaults), keys below `root` ("" for none).
template <class S>
std::vector<SettingDoc> describeSettings(S settings, std::string_view root = {}) {
    std::vector<SettingDoc> docs;
    settings_json::SettingsDescriber describer{std::string(root), docs};
    settings.visit(describer);
    return docs;
}

/// A Markdown table (key, type, default, allowed, meaning) of `docs`; `|` in any cell is escaped.
std::string settingsMarkdownTable(const std::vector<SettingDoc>& docs);

/// The rows whose default differs between `base` and `changed` (same keys in the same order), as
/// "key: base -> changed" lines of a Markdown list.
std::string settingsDifferenceList(const std::vector<SettingDoc>& base,
                                   const std::vector<SettingDoc>& changed);

} // namespace photopic
