#pragma once
// The pipeline a host drives: it owns the passes (pipeline/FrameOrder.h, the frame order written once) and
// the frame's resources, validates the host's inputs, and runs the two stages through the sequencer. It
// contains no pass logic: that lives in src/passes/<name>/. docs/architecture.md draws the frame.
//
// Per frame a 3D host calls beginFrame (jitter for its projection), renderLighting (ambient occlusion and
// contact shadows to shade with), then execute (the post chain). A host with a finished colour image calls
// execute alone.

#include "core/Image.h"
#include "core/OutdoorsMask.h"
#include "core/Settings.h"
#include "core/Subjects.h"
#include "gl/Capabilities.h"
#include "gl/GpuTimers.h"
#include "gl/Objects.h"
#include "gl/ReadbackRing.h"
#include "passes/FrameInputs.h"
#include "passes/exposure/ExposurePass.h"
#include "passes/ssaa/SsaaAccumulator.h"
#include "pipeline/FrameOrder.h"
#include "pipeline/Sequencer.h"

#include <array>
#include <bitset>
#include <cstdint>
#include <deque>
#include <functional>
#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace photopic {

class GlStateScope;

/// What the pipeline is doing, for hosts, logs and the CLI: degradations are never silent.
struct PipelineStatus {
    ColorPath path = ColorPath::Hdr; ///< the path frames take now (quality=legacy forces LDR)
    std::string pathReason;          ///< why
    Quality quality = Quality::High;
    int bloomLevels = 0;              ///< levels the last frame's bloom chain ran (0: no bloom)
    std::vector<PassTiming> passes;   ///< the most recent frame with GPU timings available
    std::vector<std::string> ran;     ///< the passes the last frame ran, in order (both stages)
    std::vector<SkippedPass> skipped; ///< passes the last frame needed but could not run, and why
    /// Problems with the last frame's inputs (a null colour, an input of another size or an unusable format,
    /// a camera with NaN): each names the input; the input was ignored for the frame.
    std::vector<std::string> inputErrors;
};

struct PipelineCreateInfo {
    Settings settings;
    bool forceLdr = false; ///< take the LDR path whatever the GPU can do
    /// Keep every frame's telemetry until drainTelemetry() (offline sequences: one CSV row per frame). Off
    /// for interactive hosts, which read only the newest through telemetry().
    bool keepTelemetryHistory = false;
};

/// What the lighting stage hands the host for shading. Each is null when its pass did not run this frame.
struct LightingOutputs {
    /// R8/R16F visibility in [0, 1] for indirect (ambient, IBL) light only: the raw visibility, before
    /// ssao.power.
    const Texture* ambientOcclusion = nullptr;
    /// ssao.power: the host multiplies its indirect light by pow(visibility, ambientOcclusionPower).
    float ambientOcclusionPower = 1.0f;
    /// R8/R16F visibility in [0, 1] for the sun's direct light only.
    const Texture* contactShadows = nullptr;
};

class Pipeline {
public:
    /// Needs a current GL 4.5 context (the host's or a HeadlessContext). Throws GlError on set-up failure,
    /// SettingsError for settings outside their ranges, IoError for an unreadable metering mask.
    explicit Pipeline(const PipelineCreateInfo& info = PipelineCreateInfo{});
    ~Pipeline();
    Pipeline(const Pipeline&) = delete;
    Pipeline& operator=(const Pipeline&) = delete;

    /// Throws SettingsError (every issue, by JSON path) for what `photopic settings --check` rejects; the
    /// pipeline keeps its settings then.
    void setSettings(const Settings& settings);
    [[nodiscard]] const Settings& settings() const { return mSettings; }
    [[nodiscard]] const Capabilities& capabilities() const { return mCaps; }

    /// Starts a frame (two-stage use by 3D hosts): returns the sub-pixel jitter, in pixels (x right, y up),
    /// that the host adds to its projection for this frame (jitteredProjection in core/Camera.h): Halton(2,
    /// 3) over temporal.jitterCycle frames while jitter is on (temporal.jitter), zero otherwise. A camera
    /// with `cut` set invalidates the histories like reset().
    glm::vec2 beginFrame(const FrameTime& time, const Camera* camera = nullptr);
    /// The jitter beginFrame returned for this frame.
    [[nodiscard]] glm::vec2 jitter() const { return mJitter; }

    /// Supersampling (aa.mode = ssaa): the sub-frames a host renders per frame, 2^aa.level; 1 otherwise.
    [[nodiscard]] int subframeCount() const noexcept;
    /// The jitter of sub-frame `index` in [0, subframeCount()), in pixels (x right, y up): an N-rooks lattice
    /// over the pixel. Sub-frame 0's is what beginFrame returns.
    [[nodiscard]] glm::vec2 subframeJitter(int index) const noexcept;
    /// Folds the host's HDR colour of sub-frame `index` (rendered with subframeJitter(index)) into the
    /// frame's weighted mean in linear light; the first call of a frame starts the mean.
    void accumulateSubframe(const Texture& color, int index);
    /// The weighted mean of this frame's sub-frames (RGBA32F), the colour to hand to execute(); valid
    /// until the next frame's first accumulateSubframe().
    [[nodiscard]] const Texture& subframeMean() const;
    /// The three calls above for a host that renders a frame with one call: with subframeCount() > 1, folds
    /// `color` (sub-frame 0, already drawn with beginFrame's jitter) into the mean, then for each further
    /// sub-frame calls `draw` with its jitter (it renders into `color` again) and folds that in; returns the
    /// mean. With one sub-frame it returns `color` and calls nothing.
    [[nodiscard]] const Texture& supersample(const Texture& color,
                                             const std::function<void(glm::vec2)>& draw);

    /// Lighting stage (3D hosts, after beginFrame, before the host shades): runs the passes whose outputs the
    /// host consumes while lighting and hands back their textures (null when that pass is off or lacks its
    /// inputs). Valid until the next call.
    const LightingOutputs& renderLighting(const FrameInputs& inputs, const FrameTime& time);

    /// Runs one frame's post stage; returns the display image (sRGB-encoded values in RGBA8, or RGBA16 at
    /// output.bitDepth 16), valid until the next call. Bad inputs never crash it: a null or empty colour
    /// returns a black 1x1 image and other bad inputs are ignored for the frame; both are reported in
    /// status().inputErrors and logged once.
    const Texture& execute(const FrameInputs& inputs, const FrameTime& time);
    /// The last frame's exposed scene-referred image just before tone mapping (RGBA32F), rendered on demand;
    /// when the frame showed a debug view of data (contact-shadows, contact-shadows-steps), its raw values.
    const Texture& sceneReferred();

    /// Per-pass GPU timings, collected without stalling.
    [[nodiscard]] GpuTimers& timers() { return mTimers; }
    /// The path, tier, latest pass timings, and what the last frame ran and skipped.
    [[nodiscard]] PipelineStatus status() const;
    /// The resources the passes the last execute() needed (those that ran, and those skipped for want of an
    /// input whose output a later pass reads) read, required or optional; with the lighting stage's when
    /// renderLighting() ran for that frame.
    /// Of the host's inputs (Resource::Depth, Normals, Motion, ...), those the frame used: a host whose
    /// settings stay the same may leave the others out of its later frames. No pass reads them, and an input
    /// that no needed pass reads decides no pass's place in the plan.
    [[nodiscard]] const std::bitset<kResourceCount>& resourcesRead() const { return mResourcesRead; }
    /// What resourcesRead() will hold after a frame whose inputs besides colour are `inputs` (of
    /// Resource::Depth, Normals, Motion, Camera, SunDirection, ObjectId, Material and SunShadowMap, each
    /// taken as valid), at the current settings; with the lighting stage's reads when `lighting` (the host
    /// calls renderLighting() for that frame). Planned as execute() plans, before the frame is made: a host
    /// can leave out of its first frame too the inputs no pass will read. Runs nothing and changes nothing
    /// later frames do.
    [[nodiscard]] std::bitset<kResourceCount> plannedReads(std::bitset<kResourceCount> inputs,
                                                           bool lighting = false);

    /// Camera cut, teleport: the next frame's exposure snaps to its target (resize does the same).
    void resetExposure() { mResetExposure = true; }
    /// A new shot: exposure snaps and every temporal history is dropped on the next frame.
    void reset();
    /// The auto exposure (EV, without the manual EV) to apply from the next frame on in place of the adapted
    /// value, until cleared with nullopt: a plan made on the CPU for the whole sequence
    /// (core/ExposurePlan.h), so a chunk of it renders as the single run would. Frames are still metered and
    /// their targets reported in the telemetry.
    void setExposureOverride(std::optional<float> appliedLog2) { mExposureOverride = appliedLog2; }

    /// The newest exposure telemetry that has arrived, without blocking. When nothing new has finished, the
    /// last result is returned again (a continuity cache); `valid` is false before the first.
    const ExposureTelemetry& telemetry();
    /// Blocks until every frame in flight has reported; returns every frame's record not yet drained, oldest
    /// first (with keepTelemetryHistory, one per frame since the last drain; else only those still in
    /// flight).
    std::vector<ExposureTelemetry> drainTelemetry();
    /// Frames whose telemetry was dropped because every ring slot was in flight.
    [[nodiscard]] std::uint64_t droppedTelemetry() const;
    /// Test hook: while `ready` returns false, finished readbacks stay in flight.
    void setTelemetryReadyOverride(std::function<bool()> ready);

    // Subjects: the host's tokens or characters, probed for the light under them. Contexts are this frame's
    // registrations with the newest probe results that have come back through the readback ring (a frame
    // or more old; never waited on). The pointers are valid until the next execute() or setSettings().

    /// Registers this frame's subjects for the next execute() (for hosts that prepare the pipeline before the
    /// caller runs it, like scenes); copied into storage sized at set-up (subjects.maxSubjects), so it does
    /// not allocate. FrameInputs::subjects, when not empty, takes precedence. Cleared by execute().
    void setSubjects(std::span<const Subject> subjects, glm::vec2 viewCentreWorld = glm::vec2(0.0f)) noexcept;
    /// Outdoors values for subjects that bring none (e.g. a roof mask). Not owned; nullptr clears it.
    void setOutdoorsMask(const OutdoorsMask* mask) noexcept;
    /// The context of a subject registered this frame, nullptr when the id was not registered.
    [[nodiscard]] const SubjectContext* contextForSubject(std::uint32_t id) const noexcept;
    /// The subject of the view (controlled, else own character, else the fallback), nullptr when none.
    [[nodiscard]] const SubjectContext* subjectContext() const noexcept;
    /// The outdoors mask at a world position, 0 without a mask.
    [[nodiscard]] float outdoorsAtWorld(float x, float y) const noexcept;
    /// The tracker behind the context API (selection, every context of this frame).
    [[nodiscard]] const SubjectTracker& subjects() const;
    /// Probe results dropped because every probe readback slot was in flight.
    [[nodiscard]] std::uint64_t droppedProbes() const;

    /// The GPU exposure state buffer (GpuExposureState), for passes a host adds after the pipeline's.
    [[nodiscard]] const Buffer& exposureState() const;

private:
    void resize(Extent extent);
    /// Binds the frame's inputs (those that pass validation) to the blackboard.
    bool bindInputs(const FrameInputs& inputs);
    /// bindInputs' steps: an optional host texture checked against the frame's extent and `formats` (a
    /// problem becomes an input error and the resource stays absent), then the inputs by kind.
    void bindOptional(Resource r, const char* name, const Texture* t, Extent extent,
                      std::initializer_list<GLenum> formats);
    void bindOptional(Resource r, const char* name, const Texture* t, Extent extent,
                      std::span<const GLenum> formats);
    void bindGeometry(const FrameInputs& in, Extent extent);
    void bindCamera(const FrameInputs& in);
    void bindSun(const FrameInputs& in);
    /// execute()'s steps: the frame without a colour input, the input problems logged once each, the
    /// lighting stage's outputs bound for the post stage, and the host calls a setting needs but the host
    /// did not make this frame (sub-frames, jitter, the lighting stage) logged once each.
    const Texture& invalidFrame() noexcept;
    void warnInputProblems() noexcept;
    void bindLightingOutputs(const LightingOutputs& lighting, const Texture* contactShadowSteps) noexcept;
    void warnHostCallsMissing(bool lightingRan) noexcept;
    FrameContext makeContext(const FrameInputs& inputs, const FrameTime& time, const QualityTier& tier);
    /// Warns once of each enabled effect that runs only in the lighting stage, for a frame without it.
    void warnLightingStageMissing() const;

    /// The host's GL state while the constructor runs (declared first: restored after everything else).
    std::unique_ptr<GlStateScope> mConstructionScope;
    Settings mSettings;
    Capabilities mCaps;
    std::optional<float> mExposureOverride;
    std::unique_ptr<FrameOrder> mOrder;
    FrameResources mResources;
    Sequencer mLightingSequencer;
    Sequencer mPostSequencer;
    GpuTimers mTimers;
    Extent mExtent;
    bool mResetExposure = true;
    bool mResetHistory = true;
    glm::vec2 mJitter{0.0f};
    bool mLightingTimed = false; ///< renderLighting() opened this frame's GPU timers; execute() closes them
    bool mBeganFrame = false;    ///< the host called beginFrame() for the frame execute() runs
    std::unique_ptr<SsaaAccumulator> mSsaa;
    bool mAccumulating = false; ///< sub-frames were added since the last execute()
    LightingOutputs mLighting;
    const Texture* mContactShadowSteps = nullptr; ///< the lighting stage's, for the post stage's debug view
    std::vector<std::string> mInputErrors;
    std::bitset<kResourceCount> mResourcesRead; ///< resourcesRead()
    Texture mInvalid;                           ///< 1x1 black, returned for a frame without usable colour
    Resource mOutput = Resource::DisplayColor;
};

/// Convenience for offline use (CLI, tests, examples): one image through the pipeline, read back.
Image8 processImage(Pipeline& pipeline, const ImageF& image, const FrameTime& time = {});

} // namespace photopic
