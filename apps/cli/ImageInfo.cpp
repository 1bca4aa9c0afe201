// `photopic image --info` (ImageInputs.h runImageInfo): each input's channels and attributes, and what
// each feeds.
#include "ImageInputs.h"

#include "Commands.h"
#include "InputSequence.h"

#include "io/ImageIO.h"

#include <fmt/format.h>

#include <algorithm>
#include <bitset>
#include <cstdio>

namespace photopic::cli {

namespace fs = std::filesystem;

namespace {

std::string motionUse(const AovConventions& c) {
    using C = AovConventions;
    const char* units = c.motionUnits == C::MotionUnits::Pixels ? "pixels"
                        : c.motionUnits == C::MotionUnits::Ndc  ? "NDC units"
                                                                : "UV units";
    const char* sense = c.motionSense == C::MotionSense::CurrentMinusPrevious   ? "current minus previous"
                        : c.motionSense == C::MotionSense::PreviousMinusCurrent ? "previous minus current"
                        : c.motionSense == C::MotionSense::NextMinusCurrent
                            ? "next minus current, read as constant velocity"
                            : "current minus next, read as constant velocity";
    return fmt::format("motion ({}, {}, y {}, {}; turned into UV, y up, current minus previous{})", units,
                       sense, c.motionYUp ? "up" : "down",
                       c.motionJittered ? "between jittered samples" : "unjittered",
                       c.motionJittered ? ", jitter removed" : "");
}

/// What `name` feeds under `aovs`, in words.
std::string channelUse(const std::string& name, const AovChannels& aovs) {
    const std::optional<Aov> aov = aovs.feeds(name);
    if (!aov) {
        if (name == "RY" || name == "BY")
            return aovs.has(Aov::Color) && aovs.of(Aov::Color)[0] == "Y" ? "colour (chroma)" : "not used";
        const std::vector<std::string>& other = aovs.otherMotionPair;
        if (std::find(other.begin(), other.end(), name) != other.end())
            return "not used (motion's other pair: --aov motion=:pair=" +
                   std::string(aovs.conventions.motionPair == 2 ? "1" : "2") + " reads it)";
        return "not used";
    }
    const AovConventions& c = aovs.conventions;
    switch (*aov) {
    case Aov::Color:
        return "colour";
    case Aov::Depth:
        return c.depth == AovConventions::Depth::Planar
                   ? "depth (linear view depth, planar)"
                   : "depth (linear view depth, radial: made planar with the camera)";
    case Aov::Normals:
        return c.normals == AovConventions::Normals::Camera ? "normals (camera space)"
               : c.normals == AovConventions::Normals::WorldZUp
                   ? "normals (world space, Z up: turned Y up, then into view space with the camera)"
                   : "normals (world space, turned into view space with the camera)";
    case Aov::Motion:
        return motionUse(c);
    case Aov::Ao:
        return "ambient occlusion: not read (Photopic computes its own; --debug ao writes it)";
    case Aov::ObjectId:
        return "object ids (contactShadows.mask)";
    }
    return "not used";
}

std::string attributeUse(const std::string& name) {
    static const std::vector<std::pair<std::string, std::string>> uses{
        {"BlenderMultiChannel", "the blender preset, unless --aovs says otherwise"},
        {"worldToCamera", "camera view"},
        {"worldToNDC", "camera projection"},
        {"nearClipPlane", "camera near plane"},
        {"farClipPlane", "camera far plane"},
        {"focus", "lens focus distance"},
        {"aperture", "lens f-number"},
        {"expTime", "lens exposure time"},
        {"isoSpeed", "lens ISO"},
        {"pinholeFocalLength", "lens focal length"},
        {"sensorOverallDimensions", "lens sensor height"},
        {"shutterAngle", "lens shutter angle"},
        {"jitter", "sample jitter (TAA; the motion unjitter with --aov motion=:jittered)"},
        {"sunDirection", "sun direction (contact shadows, volumetric light)"},
        {"dataWindow", "pixels read"},
        {"displayWindow", "NDC frame of the camera"},
        {"channels", "the channels above"},
        {"compression", "file structure"},
        {"lineOrder", "file structure"},
    };
    for (const auto& [attribute, use] : uses) {
        if (name == attribute)
            return use;
    }
    return "not used";
}

void printInfo(const fs::path& path, const std::optional<CameraTrack>& cameras,
               std::optional<std::int64_t> number, const AovRequest& request) {
    const ExrFrame frame = readExrFrame(path, {}, request);
    std::printf("%s: %dx%d", path.string().c_str(), frame.color.width, frame.color.height);
    if (frame.displaySize != glm::ivec2(frame.color.width, frame.color.height) ||
        frame.dataOrigin != glm::ivec2(0))
        std::printf(" (data window at %d,%d of a %dx%d display window)", frame.dataOrigin.x,
                    frame.dataOrigin.y, frame.displaySize.x, frame.displaySize.y);
    const AovChannels& aovs = frame.aovs;
    std::string layers;
    for (const std::string& layer : aovLayers(frame.channels, aovs.preset))
        layers += (layers.empty() ? "" : ", ") + (layer.empty() ? std::string("(unprefixed)") : layer);
    std::printf("\nchannels: the %s preset%s, layer %s (layers: %s)\n", aovPresetName(aovs.preset),
                request.preset ? " (--aovs)" : " (the file's)",
                aovs.layer.empty() ? "(unprefixed)" : aovs.layer.c_str(),
                layers.empty() ? "none" : layers.c_str());
    if (!frame.parts.empty()) {
        std::string parts;
        for (const std::string& part : frame.parts)
            parts += (parts.empty() ? "" : ", ") + part;
        std::printf("parts: %zu (%s); another part's channels are named PART.CHANNEL\n", frame.parts.size(),
                    parts.c_str());
    }
    std::vector<std::string> unused;
    for (const auto& name : frame.channels) {
        const std::string use = channelUse(name, aovs);
        std::printf("  %s -> %s\n", name.c_str(), use.c_str());
        if (use.starts_with("not used"))
            unused.push_back(name);
    }
    std::string unusedList;
    for (const std::string& name : unused)
        unusedList += (unusedList.empty() ? "" : ", ") + name;
    std::printf("unused channels: %s\n", unused.empty() ? "none" : unusedList.c_str());
    std::printf("attributes:\n");
    for (const auto& attribute : frame.attributes) {
        const std::string name = attribute.substr(0, attribute.find(' '));
        std::printf("  %s -> %s\n", attribute.c_str(), attributeUse(name).c_str());
    }
    std::optional<Camera> camera;
    try {
        camera = frameCamera(frame);
    } catch (const std::invalid_argument& e) {
        throw InputError(fmt::format("\"{}\": bad camera attributes: {}", path.string(), e.what()));
    }
    const char* source = camera ? "file attributes" : "--camera";
    if (!camera && cameras)
        camera = cameras->at(number, path).camera(frame.color.width, frame.color.height);
    if (!camera) {
        std::printf("camera: none (no worldToCamera/worldToNDC; normals will be skipped)\n");
        return;
    }
    std::printf(
        "camera (%s): near %g, far %g, vertical fov %.3g deg, focal length %.4g mm, sensor height %.4g mm, "
        "f/%.3g, focus %g\n",
        source, double(camera->nearPlane), double(camera->farPlane),
        double(glm::degrees(camera->verticalFov)), double(camera->lens.focalLengthMm),
        double(camera->lens.sensorHeightMm), double(camera->lens.fNumber),
        double(camera->lens.focusDistance));
}

} // namespace

int runImageInfo(const std::vector<fs::path>& inputs, const fs::path& cameraJsonPath, const AovRequest& aovs,
                 const std::map<fs::path, std::int64_t>& numbers) {
    const std::optional<CameraTrack> cameras =
        cameraJsonPath.empty() ? std::nullopt : std::optional<CameraTrack>(loadCameraTrack(cameraJsonPath));
    for (const auto& path : inputs) {
        if (!isExr(path)) {
            try {
                const ImageF image = readImage(path);
                std::printf("%s: %dx%d, colour only (not an OpenEXR file)\n", path.string().c_str(),
                            image.width, image.height);
            } catch (const IoError& e) {
                throw InputError(e.what());
            }
            continue;
        }
        try {
            printInfo(path, cameras, frameNumberOf(numbers, path), aovs);
        } catch (const IoError& e) {
            throw InputError(e.what());
        }
    }
    return kOk;
}

} // namespace photopic::cli
