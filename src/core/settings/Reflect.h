#pragma once
// Settings reflection: every settings struct lists its fields once, in a `visit(V&)` member template, and the
// JSON reader, the JSON writer, the `--set` override, the viewer's editor and the settings reference
// (SettingsDescriber.h, `photopic settings --markdown`, docs/settings.md) are visitors over that one list (so
// a new field cannot be forgotten by one of them). A field states its JSON key, its range or, for enums, the
// allowed names, and last its meaning: the one description of the field, which the reference prints and
// the viewer shows as a tooltip. The default is the member's initialiser; the description leaves range and
// default to the reflection and names the unit first where there is one ("s: time constant ...").
//
//     template <class V> void visit(V& v) {
//         v.field("exposure", exposure, Range{-20, 20}, "EV: manual exposure");
//         v.field("mode", mode, toneMapperNames(), "curve applied once, after every HDR effect");
//         v.require(tauDarken > 0, "tauDarken", "must be positive");
//     }
//
// `v.alias("speed", Range{...}, [&](float s) { ... }, "older key: ...")` keeps an older key readable
// without writing it.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace photopic {

/// Closed numeric range [min, max] a field must lie in; also printed in error messages.
struct Range {
    double min;
    double max;
};

/// Every settings issue code, in one list (X-macro): tests assert on the code, users read the message.
#define PHOTOPIC_SETTINGS_ISSUES(X)                                                                          \
    X(ParseError, "the text is not valid JSON")                                                              \
    X(BadVersion, "unsupported settings version")                                                            \
    X(UnknownKey, "unknown key")                                                                             \
    X(WrongType, "wrong value type")                                                                         \
    X(OutOfRange, "value out of range")                                                                      \
    X(BadEnum, "value not among the allowed names")                                                          \
    X(Constraint, "values break a rule between fields")                                                      \
    X(BadOverride, "a --set override is not of the form path=value")                                         \
    X(InvalidUtf8, "the text is not valid UTF-8")                                                            \
    X(MissingFile, "the file does not exist")                                                                \
    X(UnreadableFile, "the file cannot be read")

enum class SettingsIssueCode {
#define PHOTOPIC_X(name, text) name,
    PHOTOPIC_SETTINGS_ISSUES(PHOTOPIC_X)
#undef PHOTOPIC_X
};

std::string_view settingsIssueCodeName(SettingsIssueCode);

/// One problem found while reading settings: what, where (JSON path such as "postEffects.bloom.intensity"),
/// why.
struct SettingsIssue {
    SettingsIssueCode code;
    std::string path;
    std::string message;
};

using CurvePoints = std::vector<glm::vec2>;
/// A list of object ids (each within the field's Range), e.g. the objects an effect is limited to.
using IdList = std::vector<std::uint32_t>;

} // namespace photopic
