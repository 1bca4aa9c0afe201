#pragma once
// The shape every pass of the frame takes, and the frame's named resources (a typed blackboard).
//
// A pass declares what it reads and writes (`uses()`), says whether its settings turn it on this frame
// (`enabled()`), sizes its own persistent targets in `resize()`, and runs in `execute()` against the frame
// context and the resources. The sequencer (pipeline/Sequencer.h) decides from the declarations alone which
// passes run: a pass whose required input is missing is skipped and reported; a pass whose outputs nothing
// needs is not run at all. docs/architecture.md draws the frame order with every pass's reads and writes.

#include "core/Camera.h"
#include "core/Quality.h"
#include "core/Settings.h"
#include "gl/Capabilities.h"
#include "gl/GpuTimers.h"
#include "gl/Objects.h"
#include "gl/TexturePool.h"
#include "passes/FrameInputs.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace photopic {

class SubjectTracker;
struct ExposureTelemetry;

/// The frame's named resources. Host inputs come first; `Camera` is a resource without a GL object, present
/// when the host gave a valid camera.
enum class Resource : std::uint8_t {
    Color,            ///< host: scene-referred colour
    Depth,            ///< host: depth (FrameInputs::depthKind says how it is encoded)
    Normals,          ///< host: view-space normals
    Motion,           ///< host, or reconstructed from depth and the camera: UV motion, current - previous
    Camera,           ///< host: a valid camera (no GL object)
    SunDirection,     ///< host: a finite, non-zero sun direction (no GL object)
    ObjectId,         ///< host: per-pixel object ids (unsigned integer texture)
    MeteringMask,     ///< grey weights for mask metering (autoExposure.mask.path)
    SceneColor,       ///< the HDR image as it stands: sanitised colour, later passes replace it
    LinearDepth,      ///< R32F positive view depth in scene units (+inf: sky)
    Histogram,        ///< SSBO: 256 bins of this frame
    Metering,         ///< SSBO: metering header and partial sums
    ExposureState,    ///< SSBO: GpuExposureState, the exposure every later pass applies
    Bloom,            ///< the bloom chain's result (exposed)
    LensFlare,        ///< the lens flare features (exposed)
    TaaDebug,         ///< RG8: TAA's history weight and disocclusion, when a debug view shows them
    AmbientOcclusion, ///< lighting stage: visibility for indirect light
    ContactShadows,   ///< lighting stage: visibility for the sun
    DebugColor,       ///< a scene-value debug view (replaces the display image)
    DisplayColor,     ///< RGBA8 display-referred image (RGBA16 at output.bitDepth 16)
    /// lighting stage: the contact-shadow march's steps, when the contact-shadows-steps debug view shows them
    ContactShadowSteps,
    DofCoc,       ///< R16F: depth of field's signed circle of confusion in pixels (< 0 near, > 0 far)
    Material,     ///< host: RGB specular weight (Fresnel F0), A roughness, for screen-space reflections
    DepthPyramid, ///< RG32F min-max pyramid of linearDepth (nearest and farthest surface per cell), level 0
                  ///< padded, every level side by side in one single-level atlas (passes/ssr/ssr_pyramid.h.glsl)
    Reflections,  ///< RGBA16F: reflected radiance (RGB) and its confidence (A)
    /// motion blur's neighbourhood maximum velocity per pixel, when the velocity-tiles debug view shows it
    VelocityTiles,
    /// RGBA16F: the light volumetric light added, when the volumetric-light debug view shows it
    VolumetricLight,
    SunShadowMap, ///< host: the sun's shadow map (FrameInputs::sunShadow), valid
    /// RGBA16F with mips: last frame's finished HDR image, the source screen-space reflections sample
    /// (published by the SSR history pass while it holds one)
    SsrHistory,
    Count
};
inline constexpr std::size_t kResourceCount = std::size_t(Resource::Count);

/// "sceneColor", "depth", ... as logs, status and docs name them.
[[nodiscard]] std::string_view resourceName(Resource resource) noexcept;

enum class Access : std::uint8_t {
    Read,         ///< required: the pass is skipped (and reported) without it
    ReadOptional, ///< used when present
    Write,        ///< produced (or replaced) by the pass
};

struct ResourceUse {
    Resource resource;
    Access access;
};

/// The blackboard: what each named resource is bound to this frame. Bindings are pointers to textures and
/// buffers owned by the host (inputs), a pass (persistent state) or the texture pool (transients).
class FrameResources {
public:
    void bind(Resource r, const Texture& texture) noexcept { mTextures[std::size_t(r)] = &texture; }
    void bind(Resource r, const Buffer& buffer) noexcept { mBuffers[std::size_t(r)] = &buffer; }
    /// For resources without a GL object (the camera).
    void markPresent(Resource r) noexcept { mPresent[std::size_t(r)] = true; }
    void unbind(Resource r) noexcept {
        mTextures[std::size_t(r)] = nullptr;
        mBuffers[std::size_t(r)] = nullptr;
        mPresent[std::size_t(r)] = false;
    }
    void clear() noexcept;

    [[nodiscard]] bool has(Resource r) const noexcept {
        const std::size_t i = std::size_t(r);
        return mTextures[i] != nullptr || mBuffers[i] != nullptr || mPresent[i];
    }
    /// The bound texture, or nullptr.
    [[nodiscard]] const Texture* texture(Resource r) const noexcept { return mTextures[std::size_t(r)]; }
    [[nodiscard]] const Buffer* buffer(Resource r) const noexcept { return mBuffers[std::size_t(r)]; }

    /// Transient textures for this frame.
    [[nodiscard]] TexturePool& pool() noexcept { return mPool; }

private:
    std::array<const Texture*, kResourceCount> mTextures{};
    std::array<const Buffer*, kResourceCount> mBuffers{};
    std::array<bool, kResourceCount> mPresent{};
    TexturePool mPool;
};

/// The tier frames run at: the settings' tier, or the legacy tier's effects when the GPU forces LDR.
[[nodiscard]] QualityTier effectiveTier(const Capabilities& caps, Quality quality) noexcept;
/// The LDR path's single cheap glow runs instead of the bloom chain (legacy tier, bloom.enabled).
[[nodiscard]] bool legacyGlow(const QualityTier& tier, const Settings& settings) noexcept;

/// Everything a pass may look at for this frame besides the resources.
struct FrameContext {
    const Settings& settings;
    const QualityTier& tier; ///< the tier frames run at (the settings' tier, or legacy on an LDR-only GPU)
    const Capabilities& caps;
    const FrameInputs& inputs;
    const FrameTime& time;
    Extent extent;
    bool hdr = true;            ///< the HDR path runs this frame (else the LDR path)
    bool resetExposure = false; ///< snap exposure to its target (first frame, resize, reset, cut)
    bool resetHistory = false;  ///< temporal histories are not reused this frame (resize, reset, cut)
    GpuTimers* timers = nullptr;
    /// This frame's auto exposure settings: the settings' own, or the subject probe pass's outdoors-coupled
    /// copy for the subject of the view.
    const AutoExposureSettings* autoExposure = nullptr;
    /// Some pass this frame reads the scene colour without sanitising each value it reads, so the sanitize
    /// pass makes a clean copy first; else the host's colour stands in for it (Pipeline::execute).
    bool sanitizeScene = true;
    /// EV: the host's planned auto exposure for this frame (Pipeline::setExposureOverride), else none.
    std::optional<float> exposureOverrideLog2{};
    /// The frame's state on the CPU side, which one pass leaves for another as the resources do on the GPU
    /// side (the pipeline wires them; no pass holds another): the subjects the probe pass schedules and
    /// the subject-contexts pass completes, and the exposure pass's newest telemetry.
    SubjectTracker* subjects = nullptr;
    const ExposureTelemetry* exposureTelemetry = nullptr;
};

/// How this frame's normals come (the normal-reading passes build a program per kind): 0 none (a pass
/// reconstructs them from depth or goes without), 1 the host's view-space xyz, 2 its octahedral pair.
[[nodiscard]] int normalsSource(const FrameContext& ctx, const FrameResources& resources) noexcept;

class FramePass {
public:
    FramePass() = default;
    FramePass(const FramePass&) = delete;
    FramePass& operator=(const FramePass&) = delete;
    virtual ~FramePass() = default;

    [[nodiscard]] virtual std::string_view name() const = 0;
    [[nodiscard]] virtual std::span<const ResourceUse> uses() const = 0;
    /// The settings turn the pass on for this frame (inputs are the sequencer's business).
    [[nodiscard]] virtual bool enabled(const FrameContext&) const { return true; }
    /// Binds the state the pass keeps from frame to frame (a history, the exposure state) as resources,
    /// before each stage runs: passes read it from the blackboard, never from the pass that keeps it.
    virtual void publishState(FrameResources&) const {}
    /// Runs even when nothing downstream reads its outputs (readbacks a host polls: telemetry, probes).
    [[nodiscard]] virtual bool hasSideEffects() const { return false; }
    /// Every value it reads of the scene colour goes through sanitize() (passes/common/sanitize.h.glsl) or
    /// an equivalent, so it may read the host's raw colour: when every pass of a frame that reads the scene
    /// colour says so, the frame skips the full-resolution sanitize pass.
    [[nodiscard]] virtual bool sanitizesSceneReads() const { return false; }
    /// New settings (construction and Pipeline::setSettings): a set-up boundary, so it may throw (an
    /// unreadable metering mask throws IoError naming the file; a shader variant that fails to compile,
    /// GlError with its log).
    virtual void configure(const Settings&) {}
    /// Sizes the pass's persistent, size-dependent targets (not the pooled transients).
    virtual void resize(Extent) {}
    /// Forget temporal history (resize, camera cut, Pipeline::reset()).
    virtual void invalidateHistory() {}
    virtual void execute(FrameContext& ctx, FrameResources& resources) = 0;
};

} // namespace photopic
