#include "core/JsonText.h"

#include "core/ShownText.h"

#include <fmt/format.h>

#include <set>
#include <vector>

namespace photopic {

using nlohmann::json;

namespace {

/// One open array or object while parsing: the keys seen so far, or the index of the next element.
struct Level {
    bool object = false;
    std::set<std::string> keys;
    std::string key;
    std::size_t index = 0;
};

/// The JSON pointer of the value being parsed ("/postEffects/bloom"): each key shown escaped and cut, the
/// whole cut to a line ("/0/0/0/...").
std::string pointer(const std::vector<Level>& stack) {
    constexpr std::size_t kKeyBytes = 40;
    std::string out;
    for (const Level& level : stack) {
        if (out.size() > kShownMaxBytes) {
            return out + "/...";
        }
        // Appended in two steps: GCC 12 warns of a false overlap in `"/" + std::string`.
        out += '/';
        out += level.object ? shownText(level.key, kKeyBytes) : std::to_string(level.index);
    }
    return out.empty() ? "/" : out;
}

/// nlohmann's messages open with "[json.exception.parse_error.101] "; the rest reads on its own.
std::string withoutPrefix(std::string message) {
    if (const auto close = message.find("] "); message.starts_with("[json.") && close != std::string::npos) {
        message.erase(0, close + 2);
    }
    return message;
}

} // namespace

json parseJsonText(std::string_view text, const JsonTextLimits& limits) {
    std::vector<Level> stack;
    const auto nextElement = [&] {
        if (!stack.empty() && !stack.back().object) {
            ++stack.back().index;
        }
    };
    // The callback sees every event in document order, so it keeps its own stack of open containers.
    const json::parser_callback_t check = [&](int, json::parse_event_t event, json& parsed) {
        switch (event) {
        case json::parse_event_t::object_start:
        case json::parse_event_t::array_start:
            if (int(stack.size()) >= limits.maxDepth) {
                throw JsonTextError(
                    JsonTextError::Kind::TooDeep,
                    fmt::format("nested deeper than {} levels at {}", limits.maxDepth, pointer(stack)));
            }
            stack.push_back(
                {.object = event == json::parse_event_t::object_start, .keys = {}, .key = {}, .index = 0});
            break;
        case json::parse_event_t::key: {
            Level& level = stack.back();
            level.key = parsed.get<std::string>();
            if (limits.rejectDuplicateKeys && !level.keys.insert(level.key).second) {
                throw JsonTextError(JsonTextError::Kind::DuplicateKey,
                                    fmt::format("duplicate key \"{}\" at {}", shownText(level.key),
                                                pointer({stack.begin(), stack.end() - 1})));
            }
            break;
        }
        case json::parse_event_t::object_end:
        case json::parse_event_t::array_end:
            stack.pop_back();
            nextElement();
            break;
        case json::parse_event_t::value:
            nextElement();
            break;
        }
        return true;
    };
    try {
        return json::parse(text.begin(), text.end(), check);
    } catch (const json::out_of_range& e) {
        // 406: a number literal beyond double range.
        if (e.id == 406) {
            throw JsonTextError(JsonTextError::Kind::NumberOutOfRange,
                                withoutPrefix(e.what()) + " (beyond the range of a double)");
        }
        throw JsonTextError(JsonTextError::Kind::Syntax, withoutPrefix(e.what()));
    } catch (const json::exception& e) {
        throw JsonTextError(JsonTextError::Kind::Syntax, withoutPrefix(e.what()));
    }
}

} // namespace photopic
