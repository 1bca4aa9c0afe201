#include "CameraJson.h"

#include "InputError.h"

#include "core/JsonText.h"
#include "core/ShownText.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
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

/// An array of N numbers; `prefix` ("" or "frames.N.") names the key in errors.
template <int N>
glm::vec<N, float> vectorOf(const fs::path& path, const json& object, const std::string& key,
                            glm::vec<N, float> fallback, const std::string& prefix = "") {
    const auto it = object.find(key);
    if (it == object.end())
        return fallback;
    if (!it->is_array() || it->size() != std::size_t(N) || !std::all_of(it->begin(), it->end(), finiteFloat))
        badKey(path, prefix + key,
               "expected an array of " + std::to_string(N) +
                   " finite numbers of single precision (magnitude up to 3.4e38)");
    glm::vec<N, float> v;
    for (int i = 0; i < N; ++i)
        v[i] = (*it)[std::size_t(i)].get<float>();
    return v;
}

/// The shortest and the longest direction vector (target - position, up) normalised in single precision
/// without its squared length underflowing or overflowing.
constexpr float kMinDirection = 1e-6f;
constexpr float kMaxDirection = 1e18f;

/// The camera at the frame shapes with the extreme aspects (every other shape's matrix entries lie between
/// theirs): a view, projection or view-projection beyond single precision is refused naming the key that
/// puts it there; then the rest (the lens) as invalidCameraReason sees it.
void requireFiniteCamera(const fs::path& path, const CameraJson& c, const std::string& prefix) {
    const std::string position = prefix + (c.cameraToWorld ? "cameraToWorld" : "position");
    const std::string fov = prefix + (c.focalLengthMm ? "focalLengthMm" : "verticalFovDeg");
    for (const auto& [width, height] : {std::pair{kCameraJsonMaxSide, 1}, std::pair{1, kCameraJsonMaxSide}}) {
        const Camera camera = c.camera(width, height);
        if (!allFinite(camera.view))
            badKey(path, position, "too far from the origin: the view matrix overflows single precision");
        const glm::mat4& p = camera.projection;
        if (!std::isfinite(p[0][0]) || !std::isfinite(p[1][1]))
            badKey(path, fov,
                   "too small: the projection overflows single precision for a " + std::to_string(width) +
                       "x" + std::to_string(height) + " frame");
        if (!allFinite(p))
            badKey(path, prefix + "far",
                   "too large for this near plane: the projection overflows single precision");
        if (!allFinite(camera.prevViewProjection))
            badKey(path, position,
                   "too far from the origin for this field of view: the view-projection overflows single "
                   "precision for a " +
                       std::to_string(width) + "x" + std::to_string(height) + " frame");
    }
    if (const char* reason = invalidCameraReason(c.camera(16, 9)))
        badKey(path, prefix + "lens", reason);
}

void rejectUnknownKeys(const fs::path& path, const json& object, const std::set<std::string>& known,
                       const std::string& prefix) {
    for (const auto& [key, value] : object.items()) {
        if (!known.contains(key))
            badKey(path, prefix + key, "unknown key");
    }
}

Lens lensJson(const fs::path& path, const json& root, float verticalFov, const std::string& prefix) {
    Lens lens;
    const auto it = root.find("lens");
    if (it == root.end()) {
        lens.focalLengthMm = lens.sensorHeightMm / (2.0f * std::tan(0.5f * verticalFov));
        return lens;
    }
    const std::string at = prefix + "lens.";
    if (!it->is_object())
        badKey(path, prefix + "lens", "expected an object");
    rejectUnknownKeys(path, *it,
                      {"focalLengthMm", "sensorHeightMm", "fNumber", "focusDistance", "shutterAngleDeg",
                       "exposureTimeS", "iso"},
                      at);
    lens.sensorHeightMm = number(path, *it, "sensorHeightMm", lens.sensorHeightMm, at);
    // Without a focal length, the one that gives the field of view on this sensor.
    lens.focalLengthMm =
        number(path, *it, "focalLengthMm", lens.sensorHeightMm / (2.0f * std::tan(0.5f * verticalFov)), at);
    lens.fNumber = number(path, *it, "fNumber", lens.fNumber, at);
    lens.focusDistance = number(path, *it, "focusDistance", lens.focusDistance, at);
    lens.shutterAngleDeg = number(path, *it, "shutterAngleDeg", lens.shutterAngleDeg, at);
    lens.exposureTimeS = number(path, *it, "exposureTimeS", lens.exposureTimeS, at);
    lens.iso = number(path, *it, "iso", lens.iso, at);
    return lens;
}

} // namespace

Camera CameraJson::camera(int width, int height) const {
    Camera c;
    c.view = cameraToWorld ? glm::inverse(*cameraToWorld) : glm::lookAt(position, target, up);
    c.nearPlane = nearPlane;
    c.farPlane = farPlane;
    c.lens = lens;
    if (focalLengthMm) {
        // The sensor side the fit names spans that side of the frame; shift moves the window by fractions of
        // it.
        const float w = float(width);
        const float h = float(height);
        float side = std::max(w, h);
        float pixels = *focalLengthMm / sensor.widthMm * side; // the focal length in pixels
        if (sensor.fit == Sensor::Fit::Horizontal) {
            side = w;
            pixels = *focalLengthMm / sensor.widthMm * w;
        } else if (sensor.fit == Sensor::Fit::Vertical) {
            side = h;
            pixels = *focalLengthMm / sensor.heightMm * h;
        }
        c.verticalFov = 2.0f * std::atan(0.5f * h / pixels);
        c.projection = perspectiveProjection(c.verticalFov, w / h, nearPlane, farPlane);
        // x_ndc = P00 x / -z - P20: the window moved right by shift.x * side pixels moves the image left.
        c.projection[2][0] = 2.0f * shift.x * side / w;
        c.projection[2][1] = 2.0f * shift.y * side / h;
        c.lens.focalLengthMm = *focalLengthMm;
        c.lens.sensorHeightMm = *focalLengthMm * h / pixels; // the sensor's extent over the frame's height
    } else {
        c.verticalFov = glm::radians(verticalFovDeg);
        c.projection =
            perspectiveProjection(c.verticalFov, float(width) / float(height), nearPlane, farPlane);
    }
    c.prevViewProjection = c.viewProjection();
    return c;
}

namespace {

/// cameraToWorld: 4 rows of 4 finite numbers, a rotation (orthonormal within 1e-3) and a translation, last
/// row (0, 0, 0, 1).
glm::mat4 rigidMatrix(const fs::path& path, const json& value, const std::string& key) {
    const auto isRow = [](const json& row) {
        return row.is_array() && row.size() == 4 && std::all_of(row.begin(), row.end(), finiteFloat);
    };
    if (!value.is_array() || value.size() != 4 || !std::all_of(value.begin(), value.end(), isRow))
        badKey(path, key, "expected 4 rows of 4 finite numbers (row-major, translation in the last column)");
    glm::mat4 m(0.0f);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            m[c][r] = value[std::size_t(r)][std::size_t(c)].get<float>();
    if (std::abs(m[0][3]) > 1e-6f || std::abs(m[1][3]) > 1e-6f || std::abs(m[2][3]) > 1e-6f ||
        std::abs(m[3][3] - 1.0f) > 1e-6f)
        badKey(path, key, "the last row must be (0, 0, 0, 1)");
    const glm::mat3 rotation(m);
    const glm::mat3 gram = glm::transpose(rotation) * rotation;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            if (std::abs(gram[i][j] - (i == j ? 1.0f : 0.0f)) > 1e-3f)
                badKey(path, key,
                       "the upper 3x3 must be a rotation (orthonormal columns, no scale or shear)");
        }
    if (glm::determinant(rotation) < 0.0f)
        badKey(path, key, "the upper 3x3 is a reflection (determinant -1), not a rotation");
    if (glm::length(glm::vec3(m[3])) > kMaxDirection)
        badKey(path, key, "the camera is too far from the origin");
    return m;
}

CameraJson::Sensor sensorJson(const fs::path& path, const json& value, const std::string& prefix) {
    if (!value.is_object())
        badKey(path, prefix + "sensor", "expected an object");
    rejectUnknownKeys(path, value, {"widthMm", "heightMm", "fit"}, prefix + "sensor.");
    CameraJson::Sensor sensor;
    sensor.widthMm = number(path, value, "widthMm", sensor.widthMm, prefix + "sensor.");
    sensor.heightMm = number(path, value, "heightMm", sensor.heightMm, prefix + "sensor.");
    for (const auto& [key, mm] :
         {std::pair{"widthMm", sensor.widthMm}, std::pair{"heightMm", sensor.heightMm}}) {
        if (!(mm > 0.0f && mm <= 1000.0f))
            badKey(path, prefix + "sensor." + key, "must be in (0, 1000] mm");
    }
    if (const auto fit = value.find("fit"); fit != value.end()) {
        const std::string name = fit->is_string() ? fit->get<std::string>() : "";
        if (name == "auto")
            sensor.fit = CameraJson::Sensor::Fit::Auto;
        else if (name == "horizontal")
            sensor.fit = CameraJson::Sensor::Fit::Horizontal;
        else if (name == "vertical")
            sensor.fit = CameraJson::Sensor::Fit::Vertical;
        else
            badKey(path, prefix + "sensor.fit", "expected \"auto\", \"horizontal\" or \"vertical\"");
    }
    return sensor;
}

/// The camera's placement: cameraToWorld, or position, target and up.
void parsePlacement(const fs::path& path, const json& root, const std::string& prefix, CameraJson& c) {
    if (root.contains("cameraToWorld")) {
        for (const char* key : {"position", "target", "up"}) {
            if (root.contains(key))
                badKey(path, prefix + key, "give either cameraToWorld or position/target/up, not both");
        }
        c.cameraToWorld = rigidMatrix(path, root.at("cameraToWorld"), prefix + "cameraToWorld");
    } else {
        for (const char* key : {"position", "target"}) {
            if (!root.contains(key))
                badKey(path, prefix + key, "required (or cameraToWorld)");
        }
        c.position = vectorOf<3>(path, root, "position", c.position, prefix);
        c.target = vectorOf<3>(path, root, "target", c.target, prefix);
        c.up = vectorOf<3>(path, root, "up", c.up, prefix);
    }
}

/// The projection: focalLengthMm with its sensor and shift, or verticalFovDeg; then near and far.
void parseProjection(const fs::path& path, const json& root, const std::string& prefix, CameraJson& c) {
    if (root.contains("focalLengthMm")) {
        if (root.contains("verticalFovDeg"))
            badKey(path, prefix + "verticalFovDeg", "give either verticalFovDeg or focalLengthMm, not both");
        c.focalLengthMm = number(path, root, "focalLengthMm", 50.0f, prefix);
        if (!(*c.focalLengthMm > 0.0f && *c.focalLengthMm <= 10000.0f))
            badKey(path, prefix + "focalLengthMm", "must be in (0, 10000] mm");
        if (const auto sensor = root.find("sensor"); sensor != root.end())
            c.sensor = sensorJson(path, *sensor, prefix);
        if (root.contains("shift")) {
            c.shift = vectorOf<2>(path, root, "shift", c.shift, prefix);
            if (std::abs(c.shift.x) > 10.0f || std::abs(c.shift.y) > 10.0f)
                badKey(path, prefix + "shift", "must be within [-10, 10] (fractions of the fitted side)");
        }
    } else {
        for (const char* key : {"sensor", "shift"}) {
            if (root.contains(key))
                badKey(path, prefix + key,
                       "needs focalLengthMm (a projection from a field of view has none)");
        }
        c.verticalFovDeg = number(path, root, "verticalFovDeg", c.verticalFovDeg, prefix);
        if (!(c.verticalFovDeg > 0.0f && c.verticalFovDeg < 180.0f))
            badKey(path, prefix + "verticalFovDeg", "must be in (0, 180) degrees");
    }
    c.nearPlane = number(path, root, "near", c.nearPlane, prefix);
    const auto far = root.find("far");
    c.farPlane = far == root.end() || far->is_null() ? std::numeric_limits<float>::infinity()
                                                     : number(path, root, "far", c.farPlane, prefix);
    if (!(c.nearPlane > 0.0f))
        badKey(path, prefix + "near", "must be > 0");
    if (!(c.farPlane > c.nearPlane))
        badKey(path, prefix + "far", "must be > near (omit it or use null for an infinite far plane)");
}

/// position, target and up, when they place the camera: apart, and up not along the view.
void checkLookAt(const fs::path& path, const std::string& prefix, const CameraJson& c) {
    const glm::vec3 forward = c.target - c.position;
    const float forwardLength = glm::length(forward);
    if (!(forwardLength >= kMinDirection && forwardLength <= kMaxDirection))
        badKey(path, prefix + "target", "must differ from position by a distance in [1e-6, 1e18]");
    const float upLength = glm::length(c.up);
    if (!(upLength >= kMinDirection && upLength <= kMaxDirection))
        badKey(path, prefix + "up", "must have a length in [1e-6, 1e18]");
    if (glm::length(glm::cross(forward / forwardLength, c.up / upLength)) < 1e-6f)
        badKey(path, prefix + "up", "must not be parallel to target - position");
}

/// One camera object; `prefix` ("" or "frames.N.") names its keys in errors.
CameraJson parseCameraObject(const fs::path& path, const json& root, const std::string& prefix) {
    if (!root.is_object())
        badKey(path, prefix.empty() ? "camera" : prefix.substr(0, prefix.size() - 1), "expected an object");
    rejectUnknownKeys(path, root,
                      {"position", "target", "up", "cameraToWorld", "verticalFovDeg", "focalLengthMm",
                       "sensor", "shift", "near", "far", "lens", "sunDirection"},
                      prefix);
    CameraJson c;
    parsePlacement(path, root, prefix, c);
    parseProjection(path, root, prefix, c);
    if (!c.cameraToWorld) {
        checkLookAt(path, prefix, c);
    }
    if (root.contains("sunDirection")) {
        const glm::vec3 sun = vectorOf<3>(path, root, "sunDirection", glm::vec3(0.0f), prefix);
        const float length = glm::length(sun);
        if (!(length >= kMinDirection && length <= kMaxDirection))
            badKey(path, prefix + "sunDirection", "must have a length in [1e-6, 1e18]");
        c.sunDirection = sun / length;
    }
    const float verticalFov = c.focalLengthMm ? 2.0f * std::atan(0.5f * c.sensor.heightMm / *c.focalLengthMm)
                                              : glm::radians(c.verticalFovDeg);
    c.lens = lensJson(path, root, verticalFov, prefix);
    if (c.focalLengthMm) {
        const auto lens = root.find("lens");
        for (const char* key : {"focalLengthMm", "sensorHeightMm"}) {
            if (lens != root.end() && lens->contains(key))
                badKey(path, prefix + "lens." + key, "the camera's focalLengthMm and sensor give it");
        }
    }
    requireFiniteCamera(path, c, prefix);
    return c;
}

std::int64_t frameNumber(const fs::path& path, const std::string& key) {
    std::int64_t n = 0;
    const char* end = key.data() + key.size();
    const auto [ptr, ec] = std::from_chars(key.data(), end, n);
    if (key.empty() || ec != std::errc() || ptr != end)
        badKey(path, "frames." + key, "a frame's key is its frame number (an integer)");
    return n;
}

json parseRoot(std::string_view text, const fs::path& path) {
    json root;
    try {
        root = parseJsonText(text);
    } catch (const JsonTextError& e) {
        throw InputError(fmt::format("{}: not valid JSON: {}", path.string(), e.what()));
    }
    if (!root.is_object())
        throw InputError(fmt::format("{}: a camera file holds one JSON object", path.string()));
    return root;
}

std::string readCameraFile(const fs::path& path) {
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
    return std::move(text).str();
}

} // namespace

CameraJson parseCameraJson(std::string_view text, const fs::path& path) {
    return parseCameraObject(path, parseRoot(text, path), "");
}

CameraTrack parseCameraTrack(std::string_view text, const fs::path& path) {
    const json root = parseRoot(text, path);
    CameraTrack track;
    track.path = path;
    if (!root.contains("frames")) {
        track.single = parseCameraObject(path, root, "");
        return track;
    }
    rejectUnknownKeys(path, root, {"frames", "fps", "source"}, "");
    if (root.contains("fps")) {
        const float fps = number(path, root, "fps", 0.0f);
        if (!(fps > 0.0f && fps <= 10000.0f))
            badKey(path, "fps", "must be in (0, 10000]");
        track.fps = fps;
    }
    if (const auto source = root.find("source"); source != root.end() && !source->is_string())
        badKey(path, "source", "expected a string (where the track came from)");
    const json& frames = root.at("frames");
    if (!frames.is_object() || frames.empty())
        badKey(path, "frames", "expected an object of cameras keyed by frame number, at least one");
    for (const auto& [key, value] : frames.items())
        track.frames.emplace(frameNumber(path, key), parseCameraObject(path, value, "frames." + key + "."));
    return track;
}

const CameraJson& CameraTrack::at(std::optional<std::int64_t> number, const fs::path& input) const {
    if (single)
        return *single;
    if (!number)
        throw InputError(fmt::format("{}: {} carries no frame number, and the camera track is keyed by frame "
                                     "number",
                                     path.string(), input.string()));
    const auto it = frames.find(*number);
    if (it == frames.end())
        throw InputError(fmt::format(
            "{}: no camera for frame {} ({}); the track holds frames {} to {} ({} in all)", path.string(),
            *number, input.string(), frames.begin()->first, frames.rbegin()->first, frames.size()));
    return it->second;
}

CameraTrack loadCameraTrack(const fs::path& path) {
    return parseCameraTrack(readCameraFile(path), path);
}

CameraJson loadCameraJson(const fs::path& path) {
    return parseCameraJson(readCameraFile(path), path);
}

} // namespace photopic::cli
