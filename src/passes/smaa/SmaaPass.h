#pragma once
// SMAA 1x (Jimenez et al. 2012): luma edges with local contrast adaptation, blending weights from orthogonal
// and diagonal pattern searches with corner rounding, and neighbourhood blending. Three compute dispatches;
// the edges and weights are pooled transients, the area and search tables (core/SmaaTextures.h) are uploaded
// once. Two placements:
//  - Display (aa.mode smaa): on the display-referred RGBA8 image after tone mapping, in FXAA's place; edges
//    on the encoded values (silhouettes kept by the frame's linear depth when a 3D host gives one), the blend
//    in linear light.
//  - Hdr (aa.mode taa+smaa): on the scene-referred colour of the current frame, before TAA gathers it, so the
//    temporal resolve starts from anti-aliased edges (SMAA first, then the temporal gather, as engines ship
//    the pair). Edges are judged on a display-like luma of the exposed colour (last frame's exposure, as TAA
//    uses), sqrt(l E / (1 + l E)), so the thresholds mean what they mean after tone mapping; silhouettes are
//    kept by the linear depth as above; the blend mixes scene light, as a supersampled render would.
// Tests: tests/gl/test_smaa.cpp, tests/e2e/smaa.sh.

#include "passes/DisplayProgram.h"
#include "passes/FramePass.h"
#include "passes/ProgramVariants.h"

#include <cstddef>
#include <cstdint>
#include <optional>

namespace photopic {

/// Mirrors passes/smaa/smaa_parameters.h.glsl, std140.
struct SmaaParameters {
    float threshold = 0.1f; ///< luma step that makes an edge
    float contrastFactor =
        2.0f; ///< local contrast adaptation: dropped when a step this many times larger is beside
    float cornerRounding = 1.0f;    ///< fraction kept at a detected corner; 1: no corner detection
    std::int32_t searchSteps = 0;   ///< orthogonal search steps (two pixels each)
    std::int32_t diagonalSteps = 0; ///< 0: no diagonal patterns
    float subpixel = 0.0f;          ///< one-pixel ridges left unblended move this far towards their sides
    std::int32_t tilesX = 0;        ///< 8 x 8 tiles per row of the image
    std::int32_t tileCount = 0;     ///< tiles in the image
    std::int32_t blendAll = 0;      ///< 1: the blend step runs over the whole image, not its tile list
    std::int32_t pad[3] = {};
};
static_assert(sizeof(SmaaParameters) == 48);

/// std430 mirror of the header of passes/smaa/smaa_tiles.h.glsl's buffer: the indirect dispatches of the
/// weights step (one work group per 8 x 8 tile with an edge) and of the blend step (those tiles and their
/// left and lower neighbours). `uint tileData[]` follows: both lists, then both lists' flags, a tile count
/// each.
struct GpuSmaaTiles {
    std::uint32_t weightGroups[3] = {0, 1, 1};
    std::uint32_t pad0 = 0;
    std::uint32_t blendGroups[3] = {0, 1, 1};
    std::uint32_t pad1 = 0;
};
static_assert(sizeof(GpuSmaaTiles) == 32 && offsetof(GpuSmaaTiles, blendGroups) == 16);

class SmaaPass final : public FramePass {
public:
    enum class Domain { Display, Hdr };

    explicit SmaaPass(Domain domain = Domain::Display);
    [[nodiscard]] std::string_view name() const override {
        return mDomain == Domain::Display ? "smaa" : "smaa (hdr)";
    }
    [[nodiscard]] std::span<const ResourceUse> uses() const override;
    [[nodiscard]] bool enabled(const FrameContext& ctx) const override {
        const AntiAliasing aa = ctx.settings.antiAliasing();
        // taa+smaa runs SMAA in the HDR domain before TAA; without the HDR path (no TAA either) it falls back
        // to the display placement.
        if (mDomain == Domain::Hdr) {
            return aa == AntiAliasing::TaaSmaa && ctx.hdr;
        }
        return aa == AntiAliasing::Smaa || (aa == AntiAliasing::TaaSmaa && !ctx.hdr);
    }
    /// Display domain: builds the blend program for output.bitDepth ahead of the first frame; throws GlError.
    void configure(const Settings& settings) override;
    void execute(FrameContext& ctx, FrameResources& resources) override;

    /// The tables as the GPU holds them (tests compare them with the CPU generator).
    [[nodiscard]] const Texture& orthogonalAreaTexture() const { return mAreaOrtho; }
    [[nodiscard]] const Texture& diagonalAreaTexture() const { return mAreaDiag; }
    [[nodiscard]] const Texture& searchTexture() const { return mSearch; }

private:
    /// An edge detection program and its slots (uLinearDepth inactive without SMAA_DEPTH).
    struct EdgesProgram : ProgramSlots {
        using ProgramSlots::ProgramSlots;
        SamplerSlot color = program.sampler("uColor");
        ImageSlot depth = program.image("uLinearDepth");
        ImageSlot edges = program.image("uEdges");
    };
    /// The frame's intermediate textures and output.
    struct Targets {
        const Texture* edges = nullptr;
        const Texture* weights = nullptr;
        const Texture* out = nullptr;
    };
    [[nodiscard]] static Targets acquireTargets(Extent e, GLenum colorFormat, FrameResources& resources);
    void updateParameters(const FrameContext& ctx, bool hdr, bool blendAll);
    /// An empty tile list for this frame's extent, bound at kBindingTileList.
    void resetTiles(Extent e);
    /// The three steps: edges (with the linear depth, when the frame brings one), blending weights, blend.
    void detectEdges(const FrameContext& ctx, const FrameResources& resources, const Texture& color,
                     const Targets& t, const std::string& prefix);
    void blendingWeights(const FrameContext& ctx, const Targets& t, const std::string& prefix);
    void blend(const FrameContext& ctx, const Texture& color, const Targets& t, int bitDepth,
               const std::string& prefix);
    /// The blend step runs over the whole image: its input's format is not its output's, so the pixels it
    /// leaves alone cannot be copied.
    [[nodiscard]] static bool blendsAll(const Texture& color, const Targets& t);

    Domain mDomain;
    EdgesProgram mEdges;
    /// With the frame's linear depth: silhouettes are kept whatever their neighbours. Made on first use.
    std::optional<EdgesProgram> mEdgesDepth;
    Program mWeights;
    SamplerSlot mWeightsEdges = mWeights.sampler("uEdges");
    ImageSlot mWeightsAreaOrtho = mWeights.image("uAreaOrtho");
    ImageSlot mWeightsAreaDiag = mWeights.image("uAreaDiag");
    ImageSlot mWeightsSearch = mWeights.image("uSearch");
    ImageSlot mWeightsOut = mWeights.image("uWeights");
    DisplayProgram mBlend; ///< the HDR domain only ever uses its 8-bit build (which stores RGBA16F)
    SamplerSlot mBlendColor = mBlend.sampler("uColor");
    ImageSlot mBlendWeights = mBlend.image("uWeights");
    ImageSlot mBlendEdges = mBlend.image("uEdges");
    ImageSlot mBlendOutput = mBlend.image("uOutput");
    Texture mAreaOrtho;
    Texture mAreaDiag;
    Texture mSearch;
    ParameterBlock<SmaaParameters> mParameters;
    Buffer mTiles; ///< GpuSmaaTiles, the lists and their flags; grown to the largest extent seen
};

} // namespace photopic
