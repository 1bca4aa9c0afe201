#include "CameraJson.h"

#include "InputError.h"

#include "core/JsonText.h"
#include "core/ShownText.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>

namespace photopic::cli {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

[[noreturn]] void badKey(const fs::path& path, const std::string& key, const std::string& problem) {
    throw InputError(fmt::format("{}: camera key \"{}\": {}", path.string(), shownText(key), problem));
}

/// A JSON number that a float holds as a finite value.
bool finiteFloat(const json& value) {
    return value.is_number() && std::abs(value.get<double>()) <= double(std::numeric_limits<float>::max());
}

float number(const fs::path& path, const json& object, const std::string& key, float fallback,
             const std::string& prefix = "") {
    const auto it = object.find(key);
    if (it == object.end())
        return fallback;
    if (!finiteFloat(*it))
        badKey(path, prefix + key, "expected a finite number of single precision (magnitude up to 3.4e38)");
    return it->get<float>();
}

glm::vec3 vector3(const fs::path& path, const json& object, const std::string& key, glm::vec3 fallback) {
    const auto it = object.find(key);
    if (it == object.end())
        return fallback;
    if (!it->is_array() || it->size() != 3 || !std::all_of(it->begin(), it->end(), finiteFloat))
        badKey(path, key,
               "expected an array of 3 finite numbers of single precision (magnitude up to 3.4e38)");
    return {(*it)[0].get<float>(), (*it)[1].get<float>(), (*it)[2].get<float>()};
}

/// The shortest and the longest direction vector (target - position, up) normalised in single precision
/// without its squared length underflowing or overflowing.
constexpr float kMinDirection = 1e-6f;
constexpr float kMaxDirection = 1e18f;

/// The camera at the frame shapes with the extreme aspects (every other shape's matrix entries lie between
/// theirs): a view, projection or view-projection beyond single precision is refused naming the key that
/// puts it there; then the rest (the lens) as invalidCameraReason sees it.
void requireFiniteCamera(const fs::path& path, const CameraJson& c) {
    for (const auto& [width, height] : {std::pair{kCameraJsonMaxSide, 1}, std::pair{1, kCameraJsonMaxSide}}) {
        const Camera camera = c.camera(width, height);
        if (!allFinite(camera.view))
            badKey(path, "position", "too far from the origin: the view matrix overflows single precision");
        const glm::mat4& p = camera.projection;
        if (!std::isfinite(p[0][0]) || !std::isfinite(p[1][1]))
            badKey(path, "verticalFovDeg",
                   "too small: the projection overflows single precision for a " + std::to_string(width) +
                       "x" + std::to_string(height) + " frame");
        if (!allFinite(p))
            badKey(path, "far", "too large for this near plane: the projection overflows single precision");
        if (!allFinite(camera.prevViewProjection))
            badKey(path, "position",
                   "too far from the origin for this field of view: the view-projection overflows single "
                   "precision for a " +
                       std::to_string(width) + "x" + std::to_string(height) + " frame");
    }
    if (const char* reason = invalidCameraReason(c.camera(16, 9)))
        badKey(path, "lens", reason);
}

void rejectUnknownKeys(const fs::path& path, const json& object, const std::set<std::string>& known,
                       const std::string& prefix) {
    for (const auto& [key, value] : object.items()) {
        if (!known.contains(key))
            badKey(path, prefix + key, "unknown key");
    }
}

Lens lensJson(const fs::path& path, const json& root, float verticalFov) {
    Lens lens;
    const auto it = root.find("lens");
    if (it == root.end()) {
        lens.focalLengthMm = lens.sensorHeightMm / (2.0f * std::tan(0.5f * verticalFov));
        return lens;
    }
    if (!it->is_object())
        badKey(path, "lens", "expected an object");
    rejectUnknownKeys(path, *it,
                      {"focalLengthMm", "sensorHeightMm", "fNumber", "focusDistance", "shutterAngleDeg",
                       "exposureTimeS", "iso"},
                      "lens.");
    lens.sensorHeightMm = number(path, *it, "sensorHeightMm", lens.sensorHeightMm, "lens.");
    // Without a focal length, the one that gives the field of view on this sensor.
    lens.focalLengthMm = number(path, *it, "focalLengthMm",
                                lens.sensorHeightMm / (2.0f * std::tan(0.5f * verticalFov)), "lens.");
    lens.fNumber = number(path, *it, "fNumber", lens.fNumber, "lens.");
    lens.focusDistance = number(path, *it, "focusDistance", lens.focusDistance, "lens.");
    lens.shutterAngleDeg = number(path, *it, "shutterAngleDeg", lens.shutterAngleDeg, "lens.");
    lens.exposureTimeS = number(path, *it, "exposureTimeS", lens.exposureTimeS, "lens.");
    lens.iso = number(path, *it, "iso", lens.iso, "lens.");
    return lens;
}

} // namespace

Camera CameraJson::camera(int width, int height) const {
    Camera c;
    c.view = glm::lookAt(position, target, up);
    c.verticalFov = glm::radians(verticalFovDeg);
    c.nearPlane = nearPlane;
    c.farPlane = farPlane;
    c.projection = perspectiveProjection(c.verticalFov, float(width) / float(height), nearPlane, farPlane);
    c.prevViewProjection = c.viewProjection();
    c.lens = lens;
    return c;
}

CameraJson parseCameraJson(std::string_view text, const fs::path& path) {
    json root;
    try {
        root = parseJsonText(text);
    } catch (const JsonTextError& e) {
        throw InputError(fmt::format("{}: not valid JSON: {}", path.string(), e.what()));
    }
    if (!root.is_object())
        throw InputError(fmt::format("{}: a camera file holds one JSON object", path.string()));
    rejectUnknownKeys(path, root, {"position", "target", "up", "verticalFovDeg", "near", "far", "lens"}, "");
    for (const char* key : {"position", "target"}) {
        if (!root.contains(key))
            badKey(path, key, "required");
    }
    CameraJson c;
    c.position = vector3(path, root, "position", c.position);
    c.target = vector3(path, root, "target", c.target);
    c.up = vector3(path, root, "up", c.up);
    c.verticalFovDeg = number(path, root, "verticalFovDeg", c.verticalFovDeg);
    c.nearPlane = number(path, root, "near", c.nearPlane);
    const auto far = root.find("far");
    c.farPlane = far == root.end() || far->is_null() ? std::numeric_limits<float>::infinity()
                                                     : number(path, root, "far", c.farPlane);
    if (!(c.verticalFovDeg > 0.0f && c.verticalFovDeg < 180.0f))
        badKey(path, "verticalFovDeg", "must be in (0, 180) degrees");
    if (!(c.nearPlane > 0.0f))
        badKey(path, "near", "must be > 0");
    if (!(c.farPlane > c.nearPlane))
        badKey(path, "far", "must be > near (omit it or use null for an infinite far plane)");
    const glm::vec3 forward = c.target - c.position;
    const float forwardLength = glm::length(forward);
    if (!(forwardLength >= kMinDirection && forwardLength <= kMaxDirection))
        badKey(path, "target", "must differ from position by a distance in [1e-6, 1e18]");
    const float upLength = glm::length(c.up);
    if (!(upLength >= kMinDirection && upLength <= kMaxDirection))
        badKey(path, "up", "must have a length in [1e-6, 1e18]");
    if (glm::length(glm::cross(forward / forwardLength, c.up / upLength)) < 1e-6f)
        badKey(path, "up", "must not be parallel to target - position");
    c.lens = lensJson(path, root, glm::radians(c.verticalFovDeg));
    requireFiniteCamera(path, c);
    return c;
}

CameraJson loadCameraJson(const fs::path& path) {
    // Checked before opening: opening a named pipe for reading waits for a writer, possibly forever.
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (fs::exists(status) && !fs::is_regular_file(status))
        throw InputError(fmt::format("{}: the camera file is not a regular file", path.string()));
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(fmt::format("{}: cannot open the camera file", path.string()));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad())
        throw InputError(fmt::format("{}: cannot read the camera file", path.string()));
    return parseCameraJson(text.view(), path);
}

} // namespace photopic::cli
