// The public API (include/photopic/photopic.h) over the pipeline: converts the host's plain types (GL names,
// column-major arrays) into the pipeline's, adopts the host's textures for one call, and delivers the output
// where the host asks for it. No pass logic lives here.

#include "photopic/photopic.h"

#include "core/Log.h"
#include "core/settings/SettingsJson.h"
#include "gl/Context.h"
#include "gl/StateScope.h"
#include "pipeline/Pipeline.h"

#include <fmt/format.h>
#include <glm/gtc/type_ptr.hpp>

#include <bitset>
#include <cstring>
#include <utility>

namespace photopic {
namespace {

glm::mat4 toGlm(const Matrix4& m) {
    return glm::make_mat4(m.data());
}

Matrix4 toArray(const glm::mat4& m) {
    Matrix4 out{};
    std::memcpy(out.data(), glm::value_ptr(m), sizeof(out));
    return out;
}

Camera toCamera(const HostCamera& c) {
    Camera camera;
    camera.view = toGlm(c.view);
    camera.projection = toGlm(c.projection);
    camera.prevViewProjection = toGlm(c.prevViewProjection);
    camera.nearPlane = c.nearPlane;
    camera.farPlane = c.farPlane;
    camera.verticalFov = c.verticalFov;
    camera.lens = {.focalLengthMm = c.lens.focalLengthMm,
                   .sensorHeightMm = c.lens.sensorHeightMm,
                   .fNumber = c.lens.fNumber,
                   .focusDistance = c.lens.focusDistance,
                   .shutterAngleDeg = c.lens.shutterAngleDeg,
                   .exposureTimeS = c.lens.exposureTimeS,
                   .iso = c.lens.iso};
    camera.cut = c.cut;
    return camera;
}

/// Settings from JSON over the defaults; throws Error naming every issue.
Settings parseSettings(std::string_view json) {
    Settings settings;
    if (json.empty()) {
        return settings;
    }
    const std::vector<SettingsIssue> issues = readSettingsJson(json, settings);
    if (!issues.empty()) {
        throw Error("invalid settings JSON:\n" + formatSettingsIssues(issues));
    }
    return settings;
}

/// Runs `body`, turning the library's own exceptions into Error at the API boundary.
template <class F>
decltype(auto) guarded(F&& body) {
    try {
        return body();
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(e.what());
    }
}

SubjectLight toLight(const SubjectContext& c) {
    return {.id = c.id,
            .outdoors = c.outdoors,
            .measuredLuma = c.measuredLuma,
            .targetLog2 = c.targetLog2,
            .appliedLog2 = c.appliedLog2,
            .moving = c.moving};
}

} // namespace

const char* versionString() noexcept {
    return PHOTOPIC_VERSION;
}

void setLogCallback(LogCallback callback, void* user, LogSeverity minimum) {
    setLogLevel(LogLevel(int(minimum)));
    if (callback == nullptr) {
        setLogSink(nullptr);
        return;
    }
    setLogSink([callback, user](LogLevel level, std::string_view message) {
        const std::string text(message);
        callback(LogSeverity(int(level)), text.c_str(), user);
    });
}

struct PostProcessor::Impl {
    explicit Impl(const CreateInfo& info)
        : pipeline({.settings = parseSettings(info.settingsJson), .forceLdr = info.forceLdr}) {}

    /// The host's texture `name`, borrowed for this call; an invalid Texture (and a line in `errors`) when
    /// the name is not a 2D texture.
    Texture adopt(GlName name, const char* input) {
        if (name == 0) {
            return {};
        }
        if (glIsTexture(name) == GL_FALSE) {
            errors.push_back(fmt::format("{}: {} is not a texture name", input, name));
            return {};
        }
        GLint target = 0, width = 0, height = 0, format = 0;
        glGetTextureParameteriv(name, GL_TEXTURE_TARGET, &target);
        if (target != GL_TEXTURE_2D) {
            errors.push_back(fmt::format("{}: texture {} is not a 2D texture", input, name));
            return {};
        }
        glGetTextureLevelParameteriv(name, 0, GL_TEXTURE_WIDTH, &width);
        glGetTextureLevelParameteriv(name, 0, GL_TEXTURE_HEIGHT, &height);
        glGetTextureLevelParameteriv(name, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
        return Texture::adopt(name, {width, height}, GLenum(format));
    }

    /// The frame's inputs as the pipeline takes them; the adopted textures live in this object.
    FrameInputs inputs(const Frame& frame) {
        errors.clear();
        color = adopt(frame.color, "color");
        depth = adopt(frame.depth, "depth");
        normals = adopt(frame.normals, "normals");
        motion = adopt(frame.motion, "motion");
        material = adopt(frame.material, "material");
        objectId = adopt(frame.objectId, "objectId");
        sunShadow = adopt(frame.sunShadow.depth, "sunShadow.depth");
        subjects.clear();
        for (const HostSubject& s : frame.subjects) {
            subjects.push_back({.id = s.id,
                                .world = {s.world[0], s.world[1]},
                                .screenUv = {s.screenUv[0], s.screenUv[1]},
                                .outdoors = s.outdoors,
                                .controlled = s.controlled,
                                .ownCharacter = s.ownCharacter});
        }
        FrameInputs in;
        const auto ifValid = [](const Texture& t) { return t.valid() ? &t : nullptr; };
        in.color = ifValid(color);
        in.depth = ifValid(depth);
        in.depthKind = DepthKind(int(frame.depthEncoding));
        in.normals = ifValid(normals);
        in.normalEncoding = NormalEncoding(int(frame.normalsEncoding));
        in.motion = ifValid(motion);
        in.material = ifValid(material);
        in.objectId = ifValid(objectId);
        if (frame.camera != nullptr) {
            camera = toCamera(*frame.camera);
            in.camera = &camera;
        }
        if (frame.sunDirection) {
            const auto& d = *frame.sunDirection;
            in.sunDirection = glm::vec3(d[0], d[1], d[2]);
        }
        if (sunShadow.valid()) {
            const auto& e = frame.sunShadow.illuminance;
            in.sunShadow = {.depth = &sunShadow,
                            .worldToClip = toGlm(frame.sunShadow.worldToClip),
                            .illuminance = glm::vec3(e[0], e[1], e[2])};
        }
        in.subjects = subjects;
        return in;
    }

    /// Runs the post stage and returns the texture holding `output`.
    const Texture& run(const Frame& frame, Output output) {
        const FrameInputs in = inputs(frame);
        const Texture& display = pipeline.execute(in, {.dt = frame.dt, .frameIndex = frame.frameIndex});
        if (output == Output::Display || in.color == nullptr) {
            return display;
        }
        try {
            return pipeline.sceneReferred();
        } catch (const GlError& e) {
            errors.push_back(
                fmt::format("output: no linear HDR image ({}); the display image was delivered", e.what()));
            return display;
        }
    }

    /// Copies `source` into the rectangle of `framebuffer` (0: the default one), scaled to it.
    void blit(const Texture& source, GLuint framebuffer, int x, int y, int width, int height) {
        const GlStateScope hostState; // restores the host's framebuffers; scissor and sRGB writes off
        if (framebuffer != 0 && glIsFramebuffer(framebuffer) == GL_FALSE) {
            errors.push_back(fmt::format("target: {} is not a framebuffer name", framebuffer));
            return;
        }
        if (glCheckNamedFramebufferStatus(framebuffer, GL_DRAW_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            errors.push_back(fmt::format("target: framebuffer {} is not complete", framebuffer));
            return;
        }
        GLint samples = 0;
        glGetNamedFramebufferParameteriv(framebuffer, GL_SAMPLE_BUFFERS, &samples);
        if (samples > 0) {
            errors.push_back(
                fmt::format("target: framebuffer {} is multisampled; deliver into a single-sample "
                            "framebuffer or texture (GL cannot blit into multisample buffers)",
                            framebuffer));
            return;
        }
        // One framebuffer, re-pointed every call: the output texture changes from frame to frame (pooled),
        // and a framebuffer cached by texture name would outlive a texture whose name GL then reuses.
        if (readFramebuffer.id() == 0) {
            readFramebuffer = Framebuffer(source, 0, "photopic output (read)");
        } else {
            readFramebuffer.attach(source, 0, "photopic output (read)");
        }
        const Extent e = source.extent();
        const int w = width > 0 ? width : e.width;
        const int h = height > 0 ? height : e.height;
        glBlitNamedFramebuffer(readFramebuffer.id(), framebuffer, 0, 0, e.width, e.height, x, y, x + w, y + h,
                               GL_COLOR_BUFFER_BIT, (w == e.width && h == e.height) ? GL_NEAREST : GL_LINEAR);
    }

    void deliver(const Texture& source, const TextureTarget& target) {
        const GlStateScope hostState;
        const Texture host = adopt(target.texture, "target");
        if (!host.valid()) {
            if (target.texture == 0) {
                errors.push_back("target: texture 0 is not a texture");
            }
            return;
        }
        try {
            if (targetFramebuffer.id() == 0) {
                targetFramebuffer = Framebuffer(host, 0, "photopic output (host texture)");
            } else {
                targetFramebuffer.attach(host, 0, "photopic output (host texture)");
            }
        } catch (const GlError& e) {
            errors.push_back(
                fmt::format("target: texture {} cannot be rendered to ({})", host.id(), e.what()));
            return;
        }
        const Extent e = host.extent();
        blit(source, targetFramebuffer.id(), 0, 0, e.width, e.height);
        // Let go of the host's texture: attached, it would live on after the host deletes it.
        glNamedFramebufferTexture(targetFramebuffer.id(), GL_COLOR_ATTACHMENT0, 0, 0);
    }

    Pipeline pipeline;
    Texture color, depth, normals, motion, material, objectId, sunShadow;
    Camera camera;
    std::vector<Subject> subjects;
    std::vector<std::string> errors;                ///< the facade's own input errors for the last call
    Framebuffer readFramebuffer, targetFramebuffer; ///< made on first use, re-pointed every call
};

PostProcessor::PostProcessor(const CreateInfo& info)
    : mImpl(guarded([&] { return std::make_unique<Impl>(info); })) {}

PostProcessor::~PostProcessor() = default;
PostProcessor::PostProcessor(PostProcessor&&) noexcept = default;
PostProcessor& PostProcessor::operator=(PostProcessor&&) noexcept = default;

void PostProcessor::setSettingsJson(std::string_view json) {
    guarded([&] { mImpl->pipeline.setSettings(parseSettings(json)); });
}

void PostProcessor::setSetting(std::string_view assignment) {
    guarded([&] {
        Settings settings = mImpl->pipeline.settings();
        applySettingsOverride(settings, assignment);
        mImpl->pipeline.setSettings(settings);
    });
}

std::string PostProcessor::settingsJson() const {
    return settingsToJson(mImpl->pipeline.settings());
}

std::array<float, 2> PostProcessor::beginFrame(std::uint64_t frameIndex, float dt, const HostCamera* camera) {
    Camera converted;
    if (camera != nullptr) {
        converted = toCamera(*camera);
    }
    const glm::vec2 j =
        mImpl->pipeline.beginFrame({.dt = dt, .frameIndex = frameIndex}, camera ? &converted : nullptr);
    return {j.x, j.y};
}

Matrix4 PostProcessor::jitteredProjection(const Matrix4& projection, std::array<float, 2> jitter, int width,
                                          int height) noexcept {
    return toArray(photopic::jitteredProjection(toGlm(projection), {jitter[0], jitter[1]}, width, height));
}

Lighting PostProcessor::renderLighting(const Frame& frame) {
    return guarded([&] {
        const FrameInputs in = mImpl->inputs(frame);
        const LightingOutputs& out =
            mImpl->pipeline.renderLighting(in, {.dt = frame.dt, .frameIndex = frame.frameIndex});
        return Lighting{.ambientOcclusion = out.ambientOcclusion ? out.ambientOcclusion->id() : 0,
                        .ambientOcclusionPower = out.ambientOcclusionPower,
                        .contactShadows = out.contactShadows ? out.contactShadows->id() : 0};
    });
}

GlName PostProcessor::execute(const Frame& frame, Output output) {
    return guarded([&] { return mImpl->run(frame, output).id(); });
}

void PostProcessor::execute(const Frame& frame, const FramebufferTarget& target, Output output) {
    guarded([&] {
        const Texture& source = mImpl->run(frame, output);
        mImpl->blit(source, target.framebuffer, target.x, target.y, target.width, target.height);
    });
}

void PostProcessor::execute(const Frame& frame, const TextureTarget& target, Output output) {
    guarded([&] { mImpl->deliver(mImpl->run(frame, output), target); });
}

void PostProcessor::resetExposure() noexcept {
    mImpl->pipeline.resetExposure();
}

void PostProcessor::reset() noexcept {
    mImpl->pipeline.reset();
}

Telemetry PostProcessor::telemetry() {
    const ExposureTelemetry& t = mImpl->pipeline.telemetry();
    return {.valid = t.valid,
            .frame = t.frame,
            .meteredLuminance = t.meteredLuminance,
            .targetLog2 = t.targetLog2,
            .appliedLog2 = t.appliedLog2,
            .exposure = t.exposure,
            .adapting = t.adapting};
}

FrameInputSet PostProcessor::inputsRead(const FrameInputSet& offered, bool lighting) {
    return guarded([&] {
        const std::pair<bool FrameInputSet::*, Resource> kInputs[] = {
            {&FrameInputSet::depth, Resource::Depth},
            {&FrameInputSet::normals, Resource::Normals},
            {&FrameInputSet::motion, Resource::Motion},
            {&FrameInputSet::material, Resource::Material},
            {&FrameInputSet::objectId, Resource::ObjectId},
            {&FrameInputSet::camera, Resource::Camera},
            {&FrameInputSet::sunDirection, Resource::SunDirection},
            {&FrameInputSet::sunShadow, Resource::SunShadowMap}};
        std::bitset<kResourceCount> inputs;
        for (const auto& [member, resource] : kInputs) {
            inputs.set(std::size_t(resource), offered.*member);
        }
        const std::bitset<kResourceCount> read = mImpl->pipeline.plannedReads(inputs, lighting) & inputs;
        FrameInputSet out;
        for (const auto& [member, resource] : kInputs) {
            out.*member = read.test(std::size_t(resource));
        }
        return out;
    });
}

Status PostProcessor::status() const {
    PipelineStatus s = mImpl->pipeline.status();
    Status out;
    out.hdrPath = s.path == ColorPath::Hdr;
    out.pathReason = std::move(s.pathReason);
    out.ran = std::move(s.ran);
    for (const SkippedPass& skipped : s.skipped) {
        out.skipped.push_back(fmt::format("{}: lacks {}", skipped.pass, fmt::join(skipped.missing, ", ")));
    }
    out.inputErrors = mImpl->errors;
    for (std::string& e : s.inputErrors) {
        out.inputErrors.push_back(std::move(e));
    }
    for (const PassTiming& p : s.passes) {
        out.passTimes.push_back({.name = p.name, .milliseconds = p.gpuMs});
    }
    return out;
}

std::optional<SubjectLight> PostProcessor::subjectContext(std::uint32_t id) const {
    const SubjectContext* c = mImpl->pipeline.contextForSubject(id);
    return c ? std::optional(toLight(*c)) : std::nullopt;
}

std::optional<SubjectLight> PostProcessor::viewSubject() const {
    const SubjectContext* c = mImpl->pipeline.subjectContext();
    return c ? std::optional(toLight(*c)) : std::nullopt;
}

struct HeadlessGlContext::Impl {
    HeadlessContext context{{.debug = false}};
};

HeadlessGlContext::HeadlessGlContext()
    : mImpl(guarded([] { return std::make_unique<Impl>(); })) {}

HeadlessGlContext::~HeadlessGlContext() = default;

void HeadlessGlContext::makeCurrent() const {
    mImpl->context.makeCurrent();
}

std::string HeadlessGlContext::renderer() const {
    return mImpl->context.info().renderer;
}

} // namespace photopic
