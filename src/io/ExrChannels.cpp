#include "io/ExrChannels.h"

#include <algorithm>
#include <initializer_list>
#include <utility>

namespace photopic {

namespace {

constexpr std::array<const char*, kAovCount> kAovNames{"color",  "depth", "normals",
                                                       "motion", "ao",    "objectid"};

std::string joined(const std::vector<std::string>& names, std::size_t limit = 64) {
    std::string out;
    for (std::size_t i = 0; i < names.size() && i < limit; ++i)
        out += (i == 0 ? "" : ", ") + names[i];
    if (names.size() > limit)
        out += ", ... (" + std::to_string(names.size()) + " in all)";
    return out;
}

std::vector<std::string> split(std::string_view text, char separator) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = text.find(separator, start);
        parts.emplace_back(text.substr(start, end == std::string_view::npos ? text.npos : end - start));
        if (end == std::string_view::npos)
            return parts;
        start = end + 1;
    }
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

/// A convention word: the kind it belongs to and what it sets.
struct Convention {
    const char* word;
    Aov kind;
    void (*apply)(AovConventions&);
};

const std::vector<Convention>& conventions() {
    using C = AovConventions;
    static const std::vector<Convention> table{
        {"planar", Aov::Depth, [](C& v) { v.depth = C::Depth::Planar; }},
        {"radial", Aov::Depth, [](C& v) { v.depth = C::Depth::Radial; }},
        {"world", Aov::Normals, [](C& v) { v.normals = C::Normals::World; }},
        {"world-zup", Aov::Normals, [](C& v) { v.normals = C::Normals::WorldZUp; }},
        {"camera", Aov::Normals, [](C& v) { v.normals = C::Normals::Camera; }},
        {"pixels", Aov::Motion, [](C& v) { v.motionUnits = C::MotionUnits::Pixels; }},
        {"ndc", Aov::Motion, [](C& v) { v.motionUnits = C::MotionUnits::Ndc; }},
        {"uv", Aov::Motion, [](C& v) { v.motionUnits = C::MotionUnits::Uv; }},
        {"current-minus-previous", Aov::Motion,
         [](C& v) { v.motionSense = C::MotionSense::CurrentMinusPrevious; }},
        {"previous-minus-current", Aov::Motion,
         [](C& v) { v.motionSense = C::MotionSense::PreviousMinusCurrent; }},
        {"next-minus-current", Aov::Motion, [](C& v) { v.motionSense = C::MotionSense::NextMinusCurrent; }},
        {"current-minus-next", Aov::Motion, [](C& v) { v.motionSense = C::MotionSense::CurrentMinusNext; }},
        {"y-up", Aov::Motion, [](C& v) { v.motionYUp = true; }},
        {"y-down", Aov::Motion, [](C& v) { v.motionYUp = false; }},
        {"jittered", Aov::Motion, [](C& v) { v.motionJittered = true; }},
        {"unjittered", Aov::Motion, [](C& v) { v.motionJittered = false; }},
        {"pair=1", Aov::Motion, [](C& v) { v.motionPair = 1; }},
        {"pair=2", Aov::Motion, [](C& v) { v.motionPair = 2; }},
    };
    return table;
}

/// The convention words a kind takes, in the table's order.
std::vector<std::string> conventionWords(Aov kind) {
    std::vector<std::string> words;
    for (const Convention& c : conventions()) {
        if (c.kind == kind)
            words.emplace_back(c.word);
    }
    return words;
}

void applyConvention(AovConventions& c, const std::string& word) {
    for (const Convention& convention : conventions()) {
        if (word == convention.word) {
            convention.apply(c);
            return;
        }
    }
}

/// The component sets a prefix given for a kind is completed with, in order of preference; the names after
/// the kind's required count are optional (colour's alpha).
struct Components {
    std::vector<const char*> names;
    std::size_t required;
};

const std::vector<Components>& componentSets(Aov kind) {
    static const std::vector<Components> color{
        {{"R", "G", "B", "A"}, 3}, {{"r", "g", "b", "a"}, 3}, {{"Y"}, 1}};
    static const std::vector<Components> single{{{"Z"}, 1}, {{"z"}, 1}, {{"V"}, 1}, {{"X"}, 1},
                                                {{"R"}, 1}, {{"Y"}, 1}, {{"x"}, 1}, {{"r"}, 1}};
    static const std::vector<Components> normals{
        {{"X", "Y", "Z"}, 3}, {{"x", "y", "z"}, 3}, {{"R", "G", "B"}, 3}, {{"r", "g", "b"}, 3}};
    static const std::vector<Components> motion{
        {{"X", "Y", "Z", "W"}, 4}, {{"X", "Y"}, 2}, {{"x", "y"}, 2}, {{"U", "V"}, 2},
        {{"u", "v"}, 2},           {{"R", "G"}, 2}, {{"r", "g"}, 2}};
    switch (kind) {
    case Aov::Color:
        return color;
    case Aov::Normals:
        return normals;
    case Aov::Motion:
        return motion;
    default:
        return single;
    }
}

bool countFits(Aov kind, std::size_t count) {
    switch (kind) {
    case Aov::Color:
        return count == 1 || count == 3 || count == 4;
    case Aov::Normals:
        return count == 3;
    case Aov::Motion:
        return count == 2 || count == 4;
    default:
        return count == 1;
    }
}

const char* expectedCount(Aov kind) {
    switch (kind) {
    case Aov::Color:
        return "1 (Y), 3 (R, G, B) or 4 (R, G, B, A)";
    case Aov::Normals:
        return "3 (x, y, z)";
    case Aov::Motion:
        return "2 (x, y) or 4 (two pairs, pair=1 or pair=2 picks one)";
    default:
        return "1";
    }
}

/// `name` as the file has it: the name itself, else within the layer.
std::optional<std::string> findChannel(const std::vector<std::string>& channels, const std::string& layer,
                                       const std::string& name) {
    if (contains(channels, name))
        return name;
    if (!layer.empty() && contains(channels, layer + "." + name))
        return layer + "." + name;
    return std::nullopt;
}

/// A prefix completed with the first of the kind's component sets whose required names are all there.
std::vector<std::string> completePrefix(const std::vector<std::string>& channels, const std::string& prefix,
                                        Aov kind) {
    for (const Components& set : componentSets(kind)) {
        std::vector<std::string> names;
        for (std::size_t i = 0; i < set.names.size(); ++i) {
            const std::string name = prefix + "." + set.names[i];
            if (contains(channels, name))
                names.push_back(name);
            else if (i < set.required)
                break;
        }
        if (names.size() >= set.required)
            return names;
    }
    return {};
}

/// An --aov's channel list as the file names them.
std::vector<std::string> overrideChannels(const std::vector<std::string>& channels, const std::string& layer,
                                          const AovOverride& o) {
    const std::string kind = aovName(o.kind);
    if (o.channels.size() == 1 && !findChannel(channels, layer, o.channels[0])) {
        // One name that is no channel: a prefix the kind's components complete.
        for (const std::string& prefix :
             {layer.empty() ? o.channels[0] : layer + "." + o.channels[0], o.channels[0]}) {
            std::vector<std::string> names = completePrefix(channels, prefix, o.kind);
            if (!names.empty())
                return names;
        }
        throw AovError("--aov " + kind + "=" + o.channels[0] + ": the file has no channel " + o.channels[0] +
                       (layer.empty() ? "" : " (nor " + layer + "." + o.channels[0] + ")") +
                       " and no channels " + o.channels[0] + ".<component> for " + kind +
                       " (channels: " + joined(channels) + ")");
    }
    std::vector<std::string> names;
    for (const std::string& name : o.channels) {
        const std::optional<std::string> found = findChannel(channels, layer, name);
        if (!found)
            throw AovError("--aov " + kind + ": the file has no channel " + name +
                           (layer.empty() ? "" : " (nor " + layer + "." + name + ")") +
                           " (channels: " + joined(channels) + ")");
        names.push_back(*found);
    }
    if (!countFits(o.kind, names.size()))
        throw AovError("--aov " + kind + ": " + std::to_string(names.size()) + " channels given (" +
                       joined(names) + "), expected " + expectedCount(o.kind));
    return names;
}

/// The first of `prefixes` with any of `components` present; then it must have all of them (but the
/// optional ones, from index `required` on).
std::vector<std::string> presetLayer(const std::vector<std::string>& channels,
                                     std::initializer_list<std::string> prefixes,
                                     std::initializer_list<const char*> components, std::size_t required) {
    for (const std::string& prefix : prefixes) {
        std::vector<std::string> present;
        std::vector<std::string> missing;
        std::size_t i = 0;
        for (const char* component : components) {
            const std::string name = prefix + component;
            if (contains(channels, name))
                present.push_back(name);
            else if (i < required)
                missing.push_back(name);
            ++i;
        }
        if (present.empty())
            continue;
        if (!missing.empty())
            throw AovError("incomplete layer: has " + joined(present) + " but not " + joined(missing));
        return present;
    }
    return {};
}

void photopicPreset(const std::vector<std::string>& channels, const std::string& layer, AovChannels& out) {
    const std::string l = layer.empty() ? "" : layer + ".";
    auto& c = out.channels;
    c[std::size_t(Aov::Color)] = presetLayer(channels, {l}, {"R", "G", "B", "A"}, 3);
    if (c[std::size_t(Aov::Color)].empty())
        c[std::size_t(Aov::Color)] = presetLayer(channels, {l}, {"Y", "A"}, 1);
    // Depth, normals and motion of a layer, else the file's unprefixed ones.
    const std::string none;
    c[std::size_t(Aov::Depth)] = presetLayer(channels, {l, l + "depth.", none, "depth."}, {"Z"}, 1);
    // Upper-case components, else lower-case ones (N.x, as some writers name them).
    c[std::size_t(Aov::Normals)] =
        presetLayer(channels, {l + "N.", l + "normal.", "N.", "normal."}, {"X", "Y", "Z"}, 3);
    if (c[std::size_t(Aov::Normals)].empty())
        c[std::size_t(Aov::Normals)] =
            presetLayer(channels, {l + "N.", l + "normal.", "N.", "normal."}, {"x", "y", "z"}, 3);
    c[std::size_t(Aov::Motion)] = presetLayer(channels, {l + "motion.", "motion."}, {"X", "Y"}, 2);
    if (c[std::size_t(Aov::Motion)].empty())
        c[std::size_t(Aov::Motion)] = presetLayer(channels, {l + "motion.", "motion."}, {"x", "y"}, 2);
}

void blenderPreset(const std::vector<std::string>& channels, const std::string& layer, AovChannels& out) {
    const std::string l = layer.empty() ? "" : layer + ".";
    auto& c = out.channels;
    c[std::size_t(Aov::Color)] = presetLayer(channels, {l + "Combined."}, {"R", "G", "B", "A"}, 3);
    c[std::size_t(Aov::Depth)] = presetLayer(channels, {l + "Depth."}, {"Z"}, 1);
    c[std::size_t(Aov::Normals)] = presetLayer(channels, {l + "Normal."}, {"X", "Y", "Z"}, 3);
    c[std::size_t(Aov::Motion)] = presetLayer(channels, {l + "Vector."}, {"X", "Y", "Z", "W"}, 4);
    c[std::size_t(Aov::Ao)] = presetLayer(channels, {l + "AO."}, {"R"}, 1);
    c[std::size_t(Aov::ObjectId)] = presetLayer(channels, {l + "IndexOB."}, {"X"}, 1);
    AovConventions& v = out.conventions;
    v.depth = AovConventions::Depth::Planar;
    v.normals = AovConventions::Normals::WorldZUp;
    v.motionUnits = AovConventions::MotionUnits::Pixels;
    v.motionSense = AovConventions::MotionSense::PreviousMinusCurrent;
    v.motionYUp = true;
    v.motionJittered = false;
    v.motionPair = 1;
}

/// "; Blender's names: try --aovs blender" for a file of Blender's names read under another preset.
std::string blenderHint(const std::vector<std::string>& channels, AovPreset preset) {
    const bool looksBlender = std::any_of(channels.begin(), channels.end(), [](const std::string& name) {
        return name.find(".Combined.") != std::string::npos;
    });
    return looksBlender && preset != AovPreset::Blender ? "; Blender's names: try --aovs blender" : "";
}

std::string chooseLayer(const std::vector<std::string>& channels, const std::vector<std::string>& layers,
                        AovPreset preset, const std::string& asked) {
    const std::string listed = layers.empty() ? "none" : joined(layers);
    if (!asked.empty()) {
        if (!contains(layers, asked))
            throw AovError("--layer " + asked + ": the file has no such " + aovPresetName(preset) +
                           " layer (layers: " + listed + "; channels: " + joined(channels) + ")");
        return asked;
    }
    if (contains(layers, ""))
        return "";
    if (layers.size() == 1)
        return layers[0];
    if (layers.size() > 1)
        throw AovError("the file has " + std::to_string(layers.size()) + " layers (" + listed +
                       "): choose one with --layer NAME" + blenderHint(channels, preset));
    return "";
}

} // namespace

const char* aovName(Aov aov) {
    return kAovNames[std::size_t(aov)];
}

const char* aovPresetName(AovPreset preset) {
    return preset == AovPreset::Blender ? "blender" : "photopic";
}

std::optional<Aov> AovChannels::feeds(std::string_view channel) const {
    for (std::size_t k = 0; k < kAovCount; ++k) {
        if (std::find(channels[k].begin(), channels[k].end(), channel) != channels[k].end())
            return Aov(k);
    }
    return std::nullopt;
}

AovPreset parseAovPreset(std::string_view name) {
    if (name == "photopic")
        return AovPreset::Photopic;
    if (name == "blender")
        return AovPreset::Blender;
    throw AovError("--aovs " + std::string(name) +
                   ": unknown preset (presets: photopic, blender; other "
                   "renderers' recipes are in docs/interop.md)");
}

AovOverride parseAovOverride(std::string_view text) {
    const std::string shown(text);
    const std::size_t equals = text.find('=');
    if (equals == std::string_view::npos)
        throw AovError("--aov " + shown + ": expected KIND=CHANNELS[:CONVENTIONS] (kinds: " +
                       joined({kAovNames.begin(), kAovNames.end()}) + ")");
    const std::string kindName(text.substr(0, equals));
    const auto kind = std::find(kAovNames.begin(), kAovNames.end(), kindName);
    if (kind == kAovNames.end())
        throw AovError("--aov " + shown + ": unknown kind \"" + kindName +
                       "\" (kinds: " + joined({kAovNames.begin(), kAovNames.end()}) + ")");
    AovOverride o;
    o.kind = Aov(kind - kAovNames.begin());
    const std::string_view rest = text.substr(equals + 1);
    const std::size_t colon = rest.find(':');
    const std::string_view list = rest.substr(0, colon);
    if (list == "none") {
        o.none = true;
    } else if (!list.empty()) {
        o.channels = split(list, ',');
        for (const std::string& name : o.channels) {
            if (name.empty())
                throw AovError("--aov " + shown + ": an empty channel name");
        }
        if (!countFits(o.kind, o.channels.size()) && o.channels.size() != 1)
            throw AovError("--aov " + shown + ": " + std::to_string(o.channels.size()) +
                           " channels given, expected " + expectedCount(o.kind) +
                           " (or one prefix their components complete)");
    }
    if (colon != std::string_view::npos) {
        const std::vector<std::string> allowed = conventionWords(o.kind);
        for (const std::string& word : split(rest.substr(colon + 1), ',')) {
            if (!contains(allowed, word))
                throw AovError(
                    "--aov " + shown + ": \"" + word + "\" is no convention of " + kindName +
                    (allowed.empty() ? " (it takes none)" : " (conventions: " + joined(allowed) + ")"));
            o.convention.push_back(word);
        }
    }
    if (list.empty() && o.convention.empty())
        throw AovError("--aov " + shown + ": no channels and no conventions given");
    return o;
}

std::vector<std::string> aovLayers(const std::vector<std::string>& channels, AovPreset preset) {
    std::vector<std::string> layers;
    const auto add = [&](std::string layer) {
        if (!contains(layers, layer))
            layers.push_back(std::move(layer));
    };
    for (const std::string& name : channels) {
        const std::size_t last = name.rfind('.');
        if (preset == AovPreset::Blender) {
            // <layer>.<pass>.<channel>: the layer is all before the pass.
            const std::size_t pass =
                last == std::string::npos || last == 0 ? std::string::npos : name.rfind('.', last - 1);
            if (pass != std::string::npos)
                add(name.substr(0, pass));
            continue;
        }
        const std::string component = last == std::string::npos ? name : name.substr(last + 1);
        const std::string prefix = last == std::string::npos ? "" : name.substr(0, last);
        const std::string dot = prefix.empty() ? "" : prefix + ".";
        // P.R, P.G and P.B; or P.Y that is no vector's y (no P.X or P.Z beside it).
        const bool rgb = component == "R" && contains(channels, dot + "G") && contains(channels, dot + "B");
        const bool luminance =
            component == "Y" && !contains(channels, dot + "X") && !contains(channels, dot + "Z");
        if (!rgb && !luminance)
            continue;
        add(prefix);
    }
    return layers;
}

AovChannels resolveAovs(const std::vector<std::string>& channels, bool blenderMultiChannel,
                        const AovRequest& request) {
    AovChannels out;
    // Blender leaves its attribute out of a file with no pass but Combined.
    const bool combinedOnly =
        !contains(channels, "R") && !contains(channels, "Y") &&
        std::any_of(channels.begin(), channels.end(), [](const std::string& name) {
            return name.size() > 11 && name.compare(name.size() - 11, 11, ".Combined.R") == 0;
        });
    out.preset = request.preset.value_or(blenderMultiChannel || combinedOnly ? AovPreset::Blender
                                                                             : AovPreset::Photopic);
    const std::vector<std::string> layers = aovLayers(channels, out.preset);
    out.layer = chooseLayer(channels, layers, out.preset, request.layer);
    if (out.preset == AovPreset::Blender)
        blenderPreset(channels, out.layer, out);
    else
        photopicPreset(channels, out.layer, out);
    const std::string presetOrigin = std::string(aovPresetName(out.preset)) + " preset";
    for (std::size_t k = 0; k < kAovCount; ++k) {
        if (!out.channels[k].empty())
            out.origin[k] = presetOrigin;
    }
    for (const AovOverride& o : request.overrides) {
        auto& names = out.channels[std::size_t(o.kind)];
        if (o.none) {
            names.clear();
            out.origin[std::size_t(o.kind)].clear();
        } else if (!o.channels.empty()) {
            names = overrideChannels(channels, out.layer, o);
            out.origin[std::size_t(o.kind)] = "--aov";
        }
        for (const std::string& word : o.convention)
            applyConvention(out.conventions, word);
    }
    // Blender's second pair is the way back from the next frame's position, unless the user said otherwise.
    const bool senseGiven =
        std::any_of(request.overrides.begin(), request.overrides.end(), [](const AovOverride& o) {
            return std::any_of(o.convention.begin(), o.convention.end(),
                               [](const std::string& w) { return w.find("-minus-") != std::string::npos; });
        });
    if (out.preset == AovPreset::Blender && out.conventions.motionPair == 2 && !senseGiven)
        out.conventions.motionSense = AovConventions::MotionSense::CurrentMinusNext;
    // Of two motion pairs, the one the conventions name.
    auto& motion = out.channels[std::size_t(Aov::Motion)];
    if (motion.size() == 4) {
        const std::size_t first = out.conventions.motionPair == 2 ? 2 : 0;
        out.otherMotionPair = {motion[2 - first], motion[3 - first]};
        motion = {motion[first], motion[first + 1]};
    }
    if (out.channels[std::size_t(Aov::Color)].empty()) {
        throw AovError(std::string("no colour channels under the ") + aovPresetName(out.preset) + " preset" +
                       (out.layer.empty() ? "" : " in layer " + out.layer) +
                       " (channels: " + joined(channels) + ")" + blenderHint(channels, out.preset) +
                       "; --aov color=CHANNELS picks others");
    }
    return out;
}

} // namespace photopic
