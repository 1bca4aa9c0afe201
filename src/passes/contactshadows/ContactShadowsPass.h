#pragma once
// Screen-space contact shadows for the sun, in the lighting stage: per pixel, a short ray march through the
// depth buffer from the surface point towards the sun (contactShadows.distance, in world units), then a
// temporal accumulation of the dithered result. Three dispatches: the surfaces (normal and depth in one
// texel, so that a step reads one texel), the march, the accumulation. The output is the sun's visibility in
// [0, 1] (R16F, 1 for the sky), which the host multiplies into its direct sun term only; ambient and
// image-based light keep their own occlusion (GTAO). docs/architecture.md ("Contact shadows") has the
// algorithm and its measured agreement with the testbed's ray-traced sun visibility.
// Tests: tests/gl/test_contact_shadows.cpp, tests/core/test_contact_shadows_settings.cpp,
// tests/e2e/contact_shadows.sh.

#include "passes/FramePass.h"
#include "passes/HistoryTexture.h"
#include "passes/ProgramVariants.h"

#include <array>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace photopic {

/// std140 mirror of contact_shadows_common.h.glsl's parameter block (the march and the resolve).
struct ContactShadowParameters {
    glm::mat4 projection{1.0f};
    glm::mat4 reprojection{1.0f}; ///< this frame's view space -> last frame's clip space
    /// The view-space ray through NDC (x, y): its point at NDC z = -1 is rayNear[0] + x rayNear[1] + y
    /// rayNear[2], at NDC z = 0 the same with rayFar (affine in x and y for perspective and orthographic
    /// projections alike).
    glm::vec4 rayNear[3] = {};
    glm::vec4 rayFar[3] = {};
    glm::vec4 sunView{0.0f, 0.0f, 1.0f, 0.0f}; ///< xyz: unit, towards the sun, view space
    glm::vec2 fullSize{1.0f};                  ///< pixels
    float distance = 0.18f;                    ///< world units
    float thickness = 0.003f;                  ///< world units
    float strength = 1.1f;
    std::int32_t steps = 22;
    std::uint32_t frame = 0;     ///< moves the dithered start
    std::int32_t maskCount = 0;  ///< ids in `mask`; 0: every object
    std::int32_t writeSteps = 0; ///< the steps debug view is on: write steps taken
    std::int32_t hasHistory = 0;
    std::int32_t hasMotion = 0;
    float edgeFade = 2.0f;      ///< pixels: hits this close to the screen's edge fade out
    float historyWeight = 0.9f; ///< the clamped history's weight in the accumulation
    float padding[3] = {};
    glm::uvec4 mask[4] = {}; ///< up to 16 object ids, four per element
};
static_assert(sizeof(ContactShadowParameters) == 368);
static_assert(offsetof(ContactShadowParameters, rayNear) == 128);
static_assert(offsetof(ContactShadowParameters, sunView) == 224);
static_assert(offsetof(ContactShadowParameters, fullSize) == 240);
static_assert(offsetof(ContactShadowParameters, frame) == 264);
static_assert(offsetof(ContactShadowParameters, historyWeight) == 288);
static_assert(offsetof(ContactShadowParameters, mask) == 304);

class ContactShadowsPass final : public FramePass {
public:
    ContactShadowsPass();
    [[nodiscard]] std::string_view name() const override { return "contact shadows"; }
    /// linearDepth, camera and sunDirection; normals and motion when the host gives them; objectId when
    /// contactShadows.mask lists ids (then required).
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        return ctx.settings.contactShadows.enabled;
    }
    void configure(const Settings& settings) override;
    void invalidateHistory() override;
    void execute(FrameContext& ctx, FrameResources& resources) override;

    /// The history's weight against this frame's march, per frame (about 10 frames of accumulation).
    static constexpr float kHistoryWeight = 0.9f;

private:
    /// The frame's intermediate textures.
    struct Targets {
        const Texture* surface = nullptr; ///< per pixel: view normal and plane constant
        const Texture* raw = nullptr;     ///< this frame's march
        const Texture* steps = nullptr;   ///< the steps debug view, when asked for
    };
    [[nodiscard]] static Targets acquireTargets(const FrameContext& ctx, FrameResources& resources);
    /// This frame's parameter block.
    [[nodiscard]] ContactShadowParameters parameters(const FrameContext& ctx, const FrameResources& resources,
                                                     bool writeSteps, bool hasHistory) const;
    /// The three steps: the surfaces from depth (and normals), the march toward the sun, the resolve with
    /// the history.
    void surfaces(const FrameContext& ctx, const FrameResources& resources, const Targets& t);
    void march(const FrameContext& ctx, const FrameResources& resources, const Targets& t);
    void resolve(const FrameContext& ctx, const FrameResources& resources, const Targets& t);

    /// The surfaces from the host's normals or from depth (CONTACT_SHADOWS_NORMALS: 0 reconstructed, 1 view
    /// xyz, 2 octahedral).
    struct SurfaceProgram : ProgramSlots {
        using ProgramSlots::ProgramSlots;
        ImageSlot depth = program.image("uLinearDepth");
        SamplerSlot normals = program.sampler("uNormalTexture");
        SamplerSlot objectId = program.sampler("uObjectId");
        ImageSlot out = program.image("uSurface");
    };
    /// The march for a perspective projection ([1], CONTACT_SHADOWS_PERSPECTIVE) or any other ([0]).
    struct MarchProgram : ProgramSlots {
        using ProgramSlots::ProgramSlots;
        ImageSlot depth = program.image("uLinearDepth");
        ImageSlot surface = program.image("uSurface");
        ImageSlot raw = program.image("uRaw");
        ImageSlot steps = program.image("uStepsTaken");
    };
    ProgramVariants<SurfaceProgram, 3> mSurface{"passes/contactshadows/contact_shadows_surface.comp.glsl"};
    ProgramVariants<MarchProgram, 2> mMarch{"passes/contactshadows/contact_shadows_march.comp.glsl"};
    /// The resolve with motion vectors ([1], CONTACT_SHADOWS_MOTION) or the camera's reprojection ([0]): a
    /// define, so a SIMD implementation does not run both.
    struct ResolveProgram : ProgramSlots {
        using ProgramSlots::ProgramSlots;
        ImageSlot depth = program.image("uLinearDepth");
        ImageSlot raw = program.image("uRaw");
        SamplerSlot history = program.sampler("uHistory");
        SamplerSlot motion = program.sampler("uMotion");
        ImageSlot out = program.image("uOut");
    };
    std::array<ResolveProgram, 2> mResolve;
    ParameterBlock<ContactShadowParameters> mParameters;
    HistoryTexture mHistory;  ///< the accumulated visibility, also the stage's output
    Texture mNoSteps;         ///< bound to the steps image unit when no debug view asks for them
    Texture mNoObjectIds;     ///< bound to the object-id unit when the frame is not masked
    Sampler mObjectIdSampler; ///< NEAREST, whatever filtering the host's integer texture has
    bool mMasked = false;     ///< contactShadows.mask lists ids
    /// This frame's lighting stage started the history over (a cut, resize or reset): the post stage's
    /// invalidateHistory() for the same event must not drop it again.
    bool mRestarted = false;
};

} // namespace photopic
