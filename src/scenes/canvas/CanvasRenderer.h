#pragma once
// The canvas's shading on the GPU, usable without the Scene wrapper (the benchmark and tests drive it
// directly): uploads a canvas, builds the tile occupancy (which tiles hold material) and tile lists on the
// GPU, and shades a frame into an RGBA16F scene-linear target either tile by tile or full screen.

#include "gl/GpuTimers.h"
#include "gl/Objects.h"
#include "gl/ReadbackRing.h"
#include "scenes/canvas/CanvasImages.h"
#include "scenes/canvas/CanvasMaterial.h"
#include "scenes/canvas/CanvasPathTrial.h"

#include <array>
#include <optional>
#include <span>
#include <string_view>

namespace photopic {

enum class CanvasShading {
    Tiled, ///< specular + sparkle only on tiles with material (indirect dispatch), diffuse-only elsewhere
    Fullscreen, ///< one dispatch, full shading on every pixel (the reference the tiled path must match)
    Auto,       ///< whichever of the two the first frames measure faster here (CanvasPathTrial.h)
};
std::span<const std::string_view> canvasShadingNames(); ///< "tiled", "fullscreen", "auto"

/// std430 mirror of the TileLists block in canvas_tiles.comp.glsl / canvas_shade.comp.glsl (followed by
/// 2 x tiles uints: occupied list, then empty list).
struct GpuTileListsHeader {
    std::array<std::uint32_t, 3> occupiedArgs; ///< glDispatchComputeIndirect args at byte 0
    std::array<std::uint32_t, 3> emptyArgs;    ///< at byte 12
    std::uint32_t pad0 = 0;
    std::uint32_t pad1 = 0;
};
static_assert(sizeof(GpuTileListsHeader) == 32);
static_assert(offsetof(GpuTileListsHeader, emptyArgs) == 12);

class CanvasRenderer {
public:
    /// Needs a current GL 4.5 context; compiles the programs (throws GlError with the log).
    CanvasRenderer();

    /// Uploads `images` (their size becomes the output size) and rebuilds the tile lists on the GPU; reads
    /// the occupied-tile count back once (a set-up stall, not a per-frame one). `tileSize`: a multiple of 16
    /// in [16, 1024]; throws std::invalid_argument otherwise or when the grid has more than 65535 tiles.
    void setCanvas(const CanvasImages& images, int tileSize);

    /// Shades one frame. `timers` (optional) brackets the shading as one pass. `Auto` times the first frames
    /// of each canvas on both paths (timestamp queries read back when ready, never waited for) and then runs
    /// the faster; every path writes the same bits.
    const Texture& execute(const CanvasLighting& lighting, CanvasShading shading,
                           GpuTimers* timers = nullptr);
    /// The path `Auto` runs from now on; nullopt while it is still timing them.
    [[nodiscard]] std::optional<CanvasShading> autoChoice() const { return mTrial.chosen(); }

    [[nodiscard]] const Texture& output() const { return mOutput; }
    [[nodiscard]] const TileGrid& grid() const { return mGrid; }
    /// Tiles with material, as the GPU's tile pass counted them.
    [[nodiscard]] int occupiedTiles() const { return mOccupiedTiles; }
    /// Tiles that get the specular/sparkle shading under `shading`; under `Auto` the tiles with material
    /// (whichever path runs, they are the ones whose pixels take that shading), so telemetry does not
    /// depend on the timing.
    [[nodiscard]] int tilesShaded(CanvasShading shading) const {
        return shading == CanvasShading::Fullscreen ? mGrid.count() : mOccupiedTiles;
    }

private:
    void setLightingUniforms(const Program& program, const CanvasLighting& lighting) const;
    const Texture& shade(const CanvasLighting& lighting, CanvasShading path, GpuTimers* timers);
    const Texture& shadeTimed(const CanvasLighting& lighting, GpuTimers* timers);
    void collectTrialTimes();

    Program mTilesProgram;
    Program mFullscreenProgram;
    Program mTiledSpecularProgram;
    Program mTiledDiffuseProgram;
    Texture mColor;
    Texture mMaterial;
    Texture mOutput;
    Buffer mTileLists;
    ReadbackRing mTileCountReadback; ///< the header with the occupied count, read once per canvas
    TileGrid mGrid;
    int mOccupiedTiles = 0;
    CanvasPathTrial mTrial;
    GpuTimers mTrialTimers; ///< `Auto`'s trial frames, one timing each, named by the path it ran
};

} // namespace photopic
