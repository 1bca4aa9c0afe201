#pragma once
// Screen-space reflections (docs/architecture.md, "Screen-space reflections"), in the post stage's HDR
// domain after AO and before TAA. Three passes:
//   - DepthPyramidPass: linearDepth -> depthPyramid, the min-max depth chain the march climbs (its levels side
//     by side in one single-level texture: ssr_pyramid.h.glsl);
//   - SsrPass: the hierarchical-Z trace (full resolution; or half, each pixel then finding its own hit near
//     those of the 2 x 2 blocks around it), then the resolve, which reads the
//     reflected radiance from last frame's image and adds it, weighted by the material's specular weight and
//     the confidence, to sceneColor; it also writes `reflections` (radiance, confidence) for the debug view;
//   - SsrHistoryPass: after TAA, keeps the frame's finished HDR image (with mips) and publishes it as
//     `ssrHistory` for the next frame's resolve.
// Tests: tests/gl/test_ssr.cpp, tests/e2e/ssr.sh.

#include "gl/ShaderLibrary.h"
#include "passes/FramePass.h"
#include "passes/ProgramVariants.h"

#include <array>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace photopic {

/// std140 mirror of ssr_common.h.glsl's parameter block (the trace and the resolve).
struct SsrParameters {
    glm::mat4 projection{1.0f};
    glm::mat4 reprojection{1.0f}; ///< this frame's view space -> last frame's clip space
    /// The view-space ray through NDC (x, y): its point at NDC z = -1 is rayNear[0] + x rayNear[1] + y
    /// rayNear[2], at NDC z = 0 the same with rayFar.
    glm::vec4 rayNear[3] = {};
    glm::vec4 rayFar[3] = {};
    glm::vec2 fullSize{1.0f};  ///< pixels
    glm::vec2 traceSize{1.0f}; ///< pixels of the trace target
    float thickness = 0.25f;   ///< world units
    float maxDistance = 50.0f; ///< world units
    float roughnessCutoff = 0.6f;
    float edgeFade = 1.0f; ///< pixels
    float intensity = 1.0f;
    std::int32_t maxSteps = 200;
    std::int32_t levels = 1;
    std::int32_t normals = 0; ///< 0: none (reconstructed from depth), 1: view xyz, 2: octahedral
    std::int32_t hasMaterial = 0;
    std::int32_t hasHistory = 0;
    std::int32_t hasMotion = 0;
    std::int32_t half = 0;
    glm::ivec2 pyramidSize{1}; ///< level 0 of the depth pyramid (depthPyramidExtent)
    std::int32_t padding[2] = {};
};
static_assert(sizeof(SsrParameters) == 304);
static_assert(offsetof(SsrParameters, rayNear) == 128);
static_assert(offsetof(SsrParameters, fullSize) == 224);
static_assert(offsetof(SsrParameters, thickness) == 240);
static_assert(offsetof(SsrParameters, intensity) == 256);
static_assert(offsetof(SsrParameters, half) == 284);
static_assert(offsetof(SsrParameters, pyramidSize) == 288);

/// Levels of the depth pyramid for an image (at most 7: cells of up to 64 pixels).
[[nodiscard]] int depthPyramidLevels(Extent e) noexcept;
/// Level 0's extent: the image's, padded up to a whole number of the coarsest cells (the padding is sky).
[[nodiscard]] Extent depthPyramidExtent(Extent e) noexcept;
/// The pyramid texture's extent: one level holding every level of the chain (ssr_pyramid.h.glsl), level 0
/// with the others in a column to its right.
[[nodiscard]] Extent depthPyramidAtlasExtent(Extent e) noexcept;

class DepthPyramidPass final : public FramePass {
public:
    DepthPyramidPass();
    [[nodiscard]] std::string_view name() const override { return "ssr depth pyramid"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        return ctx.settings.ssr.enabled && ctx.hdr;
    }
    void execute(FrameContext& ctx, FrameResources& resources) override;

private:
    /// Every level in one dispatch through shared memory (sharedMemoryTiles(): a GPU), else a dispatch a
    /// level; for the pass's life.
    bool mOneDispatch = sharedMemoryTiles();
    Program mProgram;
    ImageSlot mLinearDepth = mProgram.image("uLinearDepth");
    ImageSlot mPyramid = mProgram.image("uPyramid");
};

/// Keeps the frame's HDR image after TAA for the next frame's reflections.
class SsrHistoryPass final : public FramePass {
public:
    SsrHistoryPass();
    [[nodiscard]] std::string_view name() const override { return "ssr history"; }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        return ctx.settings.ssr.enabled && ctx.hdr;
    }
    /// Nothing in this frame reads it: the next frame's SsrPass does.
    [[nodiscard]] bool hasSideEffects() const override { return true; }
    void invalidateHistory() override { mValid = false; }
    void execute(FrameContext& ctx, FrameResources& resources) override;

    /// Last frame's image, or nullptr when there is none to reuse (first frame, resize, cut, reset).
    [[nodiscard]] const Texture* previous() const { return mValid ? &mHistory : nullptr; }
    /// `ssrHistory`: last frame's image, while there is one to reuse.
    void publishState(FrameResources& resources) const override;

private:
    /// Every level in one dispatch through shared memory (sharedMemoryTiles(): a GPU), else a dispatch a
    /// level; for the pass's life.
    bool mOneDispatch = sharedMemoryTiles();
    Program mProgram;
    ImageSlot mScene = mProgram.image("uScene");
    /// One dispatch: the levels.
    std::array<ImageSlot, 6> mLevelSlots{mProgram.image("uLevel0"), mProgram.image("uLevel1"),
                                         mProgram.image("uLevel2"), mProgram.image("uLevel3"),
                                         mProgram.image("uLevel4"), mProgram.image("uLevel5")};
    /// A dispatch a level: the level below and the level written.
    ImageSlot mBelow = mProgram.image("uBelow");
    ImageSlot mTarget = mProgram.image("uTarget");
    Texture mHistory;
    bool mValid = false;
};

class SsrPass final : public FramePass {
public:
    SsrPass();
    [[nodiscard]] std::string_view name() const override { return "ssr"; }
    /// sceneColor, depthPyramid, linearDepth and the camera; normals (else reconstructed from depth),
    /// material (else a dielectric mirror) and motion (else the camera's reprojection) when present.
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        return ctx.settings.ssr.enabled && ctx.hdr;
    }
    void execute(FrameContext& ctx, FrameResources& resources) override;

private:
    /// A trace program (ssr_trace.comp.glsl, with or without REFINE) and its slots.
    struct TraceProgram : ProgramSlots {
        using ProgramSlots::ProgramSlots;
        ImageSlot depth = program.image("uLinearDepth");
        SamplerSlot normals = program.sampler("uNormalTexture");
        SamplerSlot material = program.sampler("uMaterial");
        ImageSlot pyramid = program.image("uPyramid");
        ImageSlot blockHits = program.image("uBlockHits"); ///< REFINE only
        ImageSlot hits = program.image("uHits");
    };
    /// The frame's intermediate textures and outputs.
    struct Targets {
        const Texture* hits = nullptr;      ///< one per pixel
        const Texture* blockHits = nullptr; ///< half resolution: the blocks' hits
        const Texture* sceneOut = nullptr;
        const Texture* reflections = nullptr;
    };
    /// `reflections`: the SSR debug view shows them this frame (else no reflections image).
    [[nodiscard]] static Targets acquireTargets(Extent e, bool half, bool reflections,
                                                FrameResources& resources);
    /// Last frame's image when this frame can reuse it, else nullptr.
    [[nodiscard]] static const Texture* history(const FrameContext& ctx, const FrameResources& resources);
    [[nodiscard]] SsrParameters parameters(const FrameContext& ctx, const FrameResources& resources,
                                           Extent traceExtent) const;
    /// Binds the inputs a trace program reads, and its output.
    static void bindTrace(const TraceProgram& trace, const FrameResources& resources, const Texture& hits);
    /// The resolve program for the inputs present (SSR_MOTION, SSR_HISTORY, SSR_MATERIAL), and its slots.
    struct ResolveProgram : ProgramSlots {
        using ProgramSlots::ProgramSlots;
        ImageSlot depth = program.image("uLinearDepth");
        ImageSlot scene = program.image("uScene");
        SamplerSlot history = program.sampler("uHistory");
        ImageSlot hits = program.image("uHits");
        SamplerSlot motion = program.sampler("uMotion");
        SamplerSlot material = program.sampler("uMaterial");
        ImageSlot outScene = program.image("uOutScene");
        ImageSlot outReflections = program.image("uOutReflections");
    };
    /// Built on first use.
    const ResolveProgram& resolveProgram(bool motion, bool history, bool material, bool reflections);
    /// The trace program (REFINE or not) for the normals' source (SsrParameters::normals), built on first
    /// use.
    const TraceProgram& traceProgram(int normals, bool refine);
    /// The trace, and at half resolution the refinement of the blocks' hits to each pixel's.
    void trace(const FrameContext& ctx, const FrameResources& resources, const Targets& t,
               Extent traceExtent);
    void resolve(const FrameContext& ctx, const FrameResources& resources, const Targets& t);

    /// By the normals' source (0: reconstructed, 1: view xyz, 2: octahedral); [1] the REFINE build (half
    /// resolution: each pixel's hit from the blocks' hits).
    ProgramVariants<TraceProgram, 6> mTraces{"passes/ssr/ssr_trace.comp.glsl"};
    /// By the inputs present (bit 0 motion, bit 1 history, bit 2 material) and the outputs (bit 3: the
    /// reflections for the debug view).
    ProgramVariants<ResolveProgram, 16> mResolves{"passes/ssr/ssr_resolve.comp.glsl"};
    ParameterBlock<SsrParameters> mParameters;
};

} // namespace photopic
