#pragma once
// The JSON visitors behind SettingsJson.h, usable for any struct with a `visit(V&)` member (scene settings
// too): JsonWriter writes every field; JsonReader reads present keys, validates type and range, and records
// issues by JSON path without touching fields that have issues.

#include "core/ShownText.h"
#include "core/settings/Reflect.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

namespace photopic::settings_json {

using nlohmann::json;

inline std::string joinNames(std::span<const std::string_view> names) {
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        out += (i ? ", " : "");
        out += names[i];
    }
    return out;
}

inline std::string typeName(const json& j) {
    return j.type_name();
}

/// A value as JSON text for a message: bounded in length and depth (shownJson). Never throws: bytes that are
/// not UTF-8 (a `--set` value is raw command-line text) become U+FFFD.
inline std::string shown(const json& j) {
    return shownJson(j);
}

/// `value` as the double whose shortest decimal is the float's own shortest (0.02f is written as 0.02, not
/// 0.019999999552965164): what a person typed reads back as typed, and reading it gives the same float.
inline double shortestDecimal(float value) {
    char text[32];
    const auto [end, error] = std::to_chars(text, text + sizeof(text), value);
    if (error != std::errc()) {
        return double(value);
    }
    *end = '\0';
    return std::strtod(text, nullptr);
}

/// Writes every field of a settings struct to JSON.
class JsonWriter {
public:
    explicit JsonWriter(json& out)
        : mOut(out) {}

    void field(std::string_view key, bool& value, std::string_view = {}) { mOut[std::string(key)] = value; }
    void field(std::string_view key, float& value, Range, std::string_view = {}) {
        mOut[std::string(key)] = shortestDecimal(value);
    }
    void field(std::string_view key, int& value, Range, std::string_view = {}) {
        mOut[std::string(key)] = value;
    }
    void field(std::string_view key, std::string& value, std::string_view = {}) {
        mOut[std::string(key)] = value;
    }
    void field(std::string_view key, glm::vec2& value, Range, std::string_view = {}) {
        mOut[std::string(key)] = {shortestDecimal(value.x), shortestDecimal(value.y)};
    }
    void field(std::string_view key, glm::vec3& value, Range, std::string_view = {}) {
        mOut[std::string(key)] = {shortestDecimal(value.x), shortestDecimal(value.y),
                                  shortestDecimal(value.z)};
    }
    void field(std::string_view key, CurvePoints& points, Range, std::string_view = {}) {
        json arr = json::array();
        for (const auto& p : points) {
            arr.push_back({shortestDecimal(p.x), shortestDecimal(p.y)});
        }
        mOut[std::string(key)] = arr;
    }
    void field(std::string_view key, IdList& ids, Range, std::string_view = {}) {
        mOut[std::string(key)] = ids;
    }
    template <class E>
    requires std::is_enum_v<E>
    void field(std::string_view key, E& value, std::span<const std::string_view> names,
               std::string_view = {}) {
        mOut[std::string(key)] = std::string(names[static_cast<std::size_t>(value)]);
    }
    template <class S>
    void object(std::string_view key, S& sub) {
        json child = json::object();
        JsonWriter writer(child);
        sub.visit(writer);
        mOut[std::string(key)] = std::move(child);
    }
    template <class F>
    void alias(std::string_view, Range, F&&, std::string_view = {}) {} // aliases are read, never written
    void require(bool, std::string_view, std::string_view) {}

private:
    json& mOut;
};

/// Reads present keys over a settings struct, validating type and range; records issues by JSON path.
class JsonReader {
public:
    JsonReader(const json& in, std::string path, std::vector<SettingsIssue>& issues)
        : mIn(in)
        , mPath(std::move(path))
        , mIssues(issues) {}

    void field(std::string_view key, bool& value, std::string_view = {}) {
        if (const json* j = find(key)) {
            if (!j->is_boolean()) {
                wrongType(key, *j, "true or false");
                return;
            }
            value = j->get<bool>();
        }
    }
    void field(std::string_view key, float& value, Range range, std::string_view = {}) {
        if (const json* j = find(key)) {
            double d = 0;
            if (number(key, *j, range, d)) {
                value = static_cast<float>(d);
            }
        }
    }
    void field(std::string_view key, int& value, Range range, std::string_view = {}) {
        if (const json* j = find(key)) {
            if (!j->is_number_integer()) {
                wrongType(key, *j, fmt::format("an integer in [{}, {}]", range.min, range.max));
                return;
            }
            const auto v = j->get<long long>();
            if (double(v) < range.min || double(v) > range.max) {
                add(SettingsIssueCode::OutOfRange, key,
                    fmt::format("{} is outside [{}, {}]", v, range.min, range.max));
                return;
            }
            value = static_cast<int>(v);
        }
    }
    void field(std::string_view key, std::string& value, std::string_view = {}) {
        if (const json* j = find(key)) {
            if (!j->is_string()) {
                wrongType(key, *j, "a string");
                return;
            }
            value = j->get<std::string>();
        }
    }
    void field(std::string_view key, glm::vec2& value, Range range, std::string_view = {}) {
        vector(key, &value.x, 2, range);
    }
    void field(std::string_view key, glm::vec3& value, Range range, std::string_view = {}) {
        vector(key, &value.x, 3, range);
    }
    void field(std::string_view key, CurvePoints& points, Range range, std::string_view = {}) {
        const json* j = find(key);
        if (!j) {
            return;
        }
        if (!j->is_array()) {
            wrongType(key, *j, "an array of [x, y] pairs");
            return;
        }
        CurvePoints parsed;
        for (std::size_t i = 0; i < j->size(); ++i) {
            const json& p = (*j)[i];
            const std::string at = fmt::format("{}[{}]", key, i);
            if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number()) {
                add(SettingsIssueCode::WrongType, at,
                    fmt::format("expected [x, y] numbers, got {}", shown(p)));
                return;
            }
            const double x = p[0].get<double>(), y = p[1].get<double>();
            if (!std::isfinite(x) || !std::isfinite(y) || x < range.min || x > range.max || y < range.min ||
                y > range.max) {
                add(SettingsIssueCode::OutOfRange, at,
                    fmt::format("{} has a value outside [{}, {}]", shown(p), range.min, range.max));
                return;
            }
            parsed.emplace_back(static_cast<float>(x), static_cast<float>(y));
        }
        points = std::move(parsed);
    }
    void field(std::string_view key, IdList& ids, Range range, std::string_view = {}) {
        const json* j = find(key);
        if (!j) {
            return;
        }
        if (!j->is_array()) {
            wrongType(key, *j, fmt::format("an array of integers in [{}, {}]", range.min, range.max));
            return;
        }
        IdList parsed;
        for (std::size_t i = 0; i < j->size(); ++i) {
            const json& e = (*j)[i];
            const std::string at = fmt::format("{}[{}]", key, i);
            if (!e.is_number_integer()) {
                add(SettingsIssueCode::WrongType, at,
                    fmt::format("expected an integer in [{}, {}], got {}", range.min, range.max, shown(e)));
                return;
            }
            // Signed and unsigned JSON integers alike: compare as double (ids fit a double exactly).
            const double v =
                e.is_number_unsigned() ? double(e.get<std::uint64_t>()) : double(e.get<long long>());
            if (v < range.min || v > range.max) {
                add(SettingsIssueCode::OutOfRange, at,
                    fmt::format("{} is outside [{}, {}]", shown(e), range.min, range.max));
                return;
            }
            parsed.push_back(static_cast<std::uint32_t>(v));
        }
        ids = std::move(parsed);
    }
    template <class E>
    requires std::is_enum_v<E>
    void field(std::string_view key, E& value, std::span<const std::string_view> names,
               std::string_view = {}) {
        const json* j = find(key);
        if (!j) {
            return;
        }
        if (!j->is_string()) {
            wrongType(key, *j, "one of: " + joinNames(names));
            return;
        }
        const auto s = j->get<std::string>();
        for (std::size_t i = 0; i < names.size(); ++i) {
            if (names[i] == s) {
                value = static_cast<E>(i);
                return;
            }
        }
        add(SettingsIssueCode::BadEnum, key,
            fmt::format("\"{}\" is not one of: {}", shownText(s), joinNames(names)));
    }
    template <class S>
    void object(std::string_view key, S& sub) {
        const json* j = find(key);
        if (!j) {
            return;
        }
        if (!j->is_object()) {
            wrongType(key, *j, "an object");
            return;
        }
        JsonReader reader(*j, childPath(key), mIssues);
        sub.visit(reader);
        reader.finish();
    }
    /// A key kept for compatibility (older files' names): read, range-checked, handed to `set`, never
    /// written.
    template <class F>
    void alias(std::string_view key, Range range, F&& set, std::string_view = {}) {
        if (const json* j = find(key)) {
            double d = 0;
            if (number(key, *j, range, d)) {
                set(static_cast<float>(d));
            }
        }
    }
    void require(bool ok, std::string_view key, std::string_view message) {
        if (!ok) {
            add(SettingsIssueCode::Constraint, key, std::string(message));
        }
    }

    /// Reports every key in the object that no field claimed.
    void finish() {
        for (const auto& [key, value] : mIn.items()) {
            if (!mSeen.contains(key)) {
                std::string known;
                for (const auto& k : mKnown) {
                    known += (known.empty() ? "" : ", ") + k;
                }
                add(SettingsIssueCode::UnknownKey, shownText(key), fmt::format("known keys: {}", known));
            }
        }
    }

private:
    const json* find(std::string_view key) {
        mKnown.emplace_back(key);
        mSeen.emplace(key);
        const auto it = mIn.find(std::string(key));
        return it == mIn.end() ? nullptr : &*it;
    }
    std::string childPath(std::string_view key) const {
        return mPath.empty() ? std::string(key) : mPath + "." + std::string(key);
    }
    void add(SettingsIssueCode code, std::string_view key, std::string message) {
        mIssues.push_back({code, childPath(key), std::move(message)});
    }
    void wrongType(std::string_view key, const json& j, const std::string& expected) {
        add(SettingsIssueCode::WrongType, key,
            fmt::format("expected {}, got {} {}", expected, typeName(j), shown(j)));
    }
    bool number(std::string_view key, const json& j, Range range, double& out) {
        if (!j.is_number()) {
            wrongType(key, j, fmt::format("a number in [{}, {}]", range.min, range.max));
            return false;
        }
        out = j.get<double>();
        if (!std::isfinite(out) || out < range.min || out > range.max) {
            add(SettingsIssueCode::OutOfRange, key,
                fmt::format("{} is outside [{}, {}]", shown(j), range.min, range.max));
            return false;
        }
        return true;
    }
    void vector(std::string_view key, float* dst, int n, Range range) {
        const json* j = find(key);
        if (!j) {
            return;
        }
        if (!j->is_array() || j->size() != std::size_t(n)) {
            wrongType(key, *j, fmt::format("an array of {} numbers in [{}, {}]", n, range.min, range.max));
            return;
        }
        float tmp[3] = {};
        for (int i = 0; i < n; ++i) {
            double d = 0;
            if (!number(fmt::format("{}[{}]", key, i), (*j)[std::size_t(i)], range, d)) {
                return;
            }
            tmp[i] = static_cast<float>(d);
        }
        std::copy(tmp, tmp + n, dst);
    }

    const json& mIn;
    std::string mPath;
    std::vector<SettingsIssue>& mIssues;
    std::set<std::string, std::less<>> mSeen;
    std::vector<std::string> mKnown;
};

/// Reads `object` (the JSON of one struct) into `target`, reporting issues under `path`.
template <class S>
std::vector<SettingsIssue> readObject(const json& object, const std::string& path, S& target) {
    std::vector<SettingsIssue> issues;
    if (!object.is_object()) {
        issues.push_back({SettingsIssueCode::WrongType, path,
                          fmt::format("expected an object, got {}", object.type_name())});
        return issues;
    }
    JsonReader reader(object, path, issues);
    target.visit(reader);
    reader.finish();
    return issues;
}

/// Writes every field of `source` as a JSON object.
template <class S>
json writeObject(const S& source) {
    json out = json::object();
    JsonWriter writer(out);
    S copy = source; // visit() is non-const by design (one list serves readers and writers)
    copy.visit(writer);
    return out;
}

/// Keys of an override have at most this many dot-separated parts (the settings tree is 3 deep).
inline constexpr std::size_t kMaxOverrideParts = 16;

/// Parses "a.b=value" into {"a": {"b": value}} (value as JSON when valid JSON, else a string). Returns false
/// when the text is not of the form path=value; throws JsonTextError when the value is JSON that breaks a
/// limit of parseJsonText (1e400, nesting, a duplicate key), is an array or object that does not parse, or
/// the key has more than kMaxOverrideParts parts.
bool parseAssignment(std::string_view assignment, json& patch);

} // namespace photopic::settings_json
