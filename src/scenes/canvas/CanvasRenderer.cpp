#include "scenes/canvas/CanvasRenderer.h"

#include "core/Log.h"
#include "gl/ShaderLibrary.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace photopic {

namespace {

constexpr unsigned kTileListBinding = 0; ///< SSBO binding of the TileLists block
constexpr int kGroupSize = 16;           ///< local_size_x/y of both canvas compute shaders

constexpr std::array<std::string_view, 3> kShadingNames{"tiled", "fullscreen", "auto"};

ShaderDefines defines(bool tiled, bool specular) {
    return {{"TILE_LIST_BINDING", std::to_string(kTileListBinding)},
            {"CANVAS_TILED", tiled ? "1" : "0"},
            {"CANVAS_SPECULAR", specular ? "1" : "0"}};
}

void setUniform3(const Program& p, const char* name, glm::vec3 v) {
    setUniform(p, name, v.x, v.y, v.z);
}

} // namespace

std::span<const std::string_view> canvasShadingNames() {
    return kShadingNames;
}

CanvasRenderer::CanvasRenderer()
    : mTilesProgram(makeComputeProgram("scenes/canvas/canvas_tiles.comp.glsl", defines(false, false)))
    , mFullscreenProgram(makeComputeProgram("scenes/canvas/canvas_shade.comp.glsl", defines(false, true)))
    , mTiledSpecularProgram(makeComputeProgram("scenes/canvas/canvas_shade.comp.glsl", defines(true, true)))
    , mTiledDiffuseProgram(makeComputeProgram("scenes/canvas/canvas_shade.comp.glsl", defines(true, false)))
    , mTileCountReadback(sizeof(GpuTileListsHeader), 1, "canvas tile count") {}

namespace {

/// The tile grid of `images`, checked: colour and material of one non-empty size, tiles a multiple of the
/// group size in [16, 1024], no more tiles than an indirect dispatch can list.
TileGrid checkedTileGrid(const CanvasImages& images, int tileSize) {
    if (tileSize < kGroupSize || tileSize > 1024 || tileSize % kGroupSize != 0) {
        throw std::invalid_argument(
            fmt::format("canvas tile size {} is not a multiple of 16 in [16, 1024]", tileSize));
    }
    const int w = images.color.width, h = images.color.height;
    if (images.material.width != w || images.material.height != h || w <= 0 || h <= 0) {
        throw std::invalid_argument("canvas colour and material must have the same, non-empty size");
    }
    const TileGrid grid = makeTileGrid(w, h, tileSize);
    if (grid.count() > 65535) {
        throw std::invalid_argument(
            fmt::format("{} x {} tiles of {} px exceed the 65535 an indirect dispatch can "
                        "list; use a larger tile size",
                        grid.tilesX, grid.tilesY, tileSize));
    }
    return grid;
}

/// Rows flipped on upload: image row y (top-down) is texel row h-1-y (GL's bottom-left origin).
void uploadFlipped(const Texture& texture, const Image8& image) {
    const int w = image.width, h = image.height;
    std::vector<std::uint8_t> flipped(image.rgba.size());
    const std::size_t row = std::size_t(w) * 4;
    for (int y = 0; y < h; ++y) {
        std::copy_n(image.rgba.data() + std::size_t(h - 1 - y) * row, row,
                    flipped.data() + std::size_t(y) * row);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(texture.id(), 0, 0, 0, w, h, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE, flipped.data());
}

} // namespace

void CanvasRenderer::setCanvas(const CanvasImages& images, int tileSize) {
    const TileGrid grid = checkedTileGrid(images, tileSize);
    const int w = images.color.width, h = images.color.height;
    mGrid = grid;
    mTrial.restart();
    mTrialTimers = {}; // the old canvas's trial frames still in flight are not this one's
    DebugGroup group("canvas upload + tile lists");
    if (!mColor.valid() || mColor.extent() != Extent{w, h}) {
        mColor = Texture({.extent = {w, h}, .format = GL_RGBA16F, .debugName = "canvas colour"});
        mMaterial = Texture({.extent = {w, h},
                             .format = GL_RGBA8UI,
                             .minFilter = GL_NEAREST,
                             .magFilter = GL_NEAREST,
                             .debugName = "canvas material"});
        mOutput = Texture({.extent = {w, h}, .format = GL_RGBA16F, .debugName = "canvas HDR"});
    }
    mColor.uploadRgba32f(images.color.rgba.data());
    uploadFlipped(mMaterial, images.material);

    const auto groupsPerSide = std::uint32_t(tileSize / kGroupSize);
    const GpuTileListsHeader header{.occupiedArgs = {groupsPerSide, groupsPerSide, 0},
                                    .emptyArgs = {groupsPerSide, groupsPerSide, 0}};
    const std::size_t bytes = sizeof(header) + 2 * std::size_t(grid.count()) * sizeof(std::uint32_t);
    if (mTileLists.size() != bytes) {
        mTileLists =
            Buffer({.size = bytes, .flags = GL_DYNAMIC_STORAGE_BIT, .debugName = "canvas tile lists"});
    }
    mTileLists.update(&header, sizeof(header));

    glBindTextureUnit(1, mMaterial.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileListBinding, mTileLists.id());
    setUniform(mTilesProgram, "uTileSize", tileSize);
    setUniform(mTilesProgram, "uTilesX", grid.tilesX);
    setUniform(mTilesProgram, "uTileCount", grid.count());
    mTilesProgram.use();
    glDispatchCompute(GLuint(grid.tilesX), GLuint(grid.tilesY), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);

    // Through a mapped copy, not glGetNamedBufferSubData: reading a GPU-written buffer directly makes a
    // driver move it to host memory (NVIDIA says so in a performance warning), slowing every later dispatch.
    mTileCountReadback.enqueue(mTileLists, 0, 0);
    GpuTileListsHeader counted{};
    for (const ReadbackRing::Result& r : mTileCountReadback.drain()) {
        std::memcpy(&counted, r.bytes.data(), sizeof(counted));
    }
    mOccupiedTiles = int(counted.occupiedArgs[2]);
}

void CanvasRenderer::setLightingUniforms(const Program& p, const CanvasLighting& l) const {
    setUniform3(p, "uLight", l.light);
    setUniform3(p, "uLightColor", l.lightColor);
    setUniform(p, "uAmbient", l.ambient);
    setUniform(p, "uSpecular", l.specular);
    setUniform(p, "uSparkleExposure", l.sparkleExposure);
    setUniform(p, "uSparkleGate", kSparkleGate);
    setUniform(p, "uSparkleExponent", kSparkleExponent);
    setUniform(p, "uMaxShininessLog2", kMaxShininessLog2);
    setUniform(p, "uViewDistance", l.viewDistance);
    setUniform(p, "uTileSize", mGrid.tileSize);
    setUniform(p, "uTilesX", mGrid.tilesX);
}

const Texture& CanvasRenderer::execute(const CanvasLighting& lighting, CanvasShading shading,
                                       GpuTimers* timers) {
    if (shading != CanvasShading::Auto) {
        return shade(lighting, shading, timers);
    }
    if (!mTrial.chosen()) {
        collectTrialTimes(); // logs the choice once, when the trial ends
    }
    if (const std::optional<CanvasShading> chosen = mTrial.chosen()) {
        return shade(lighting, *chosen, timers);
    }
    return shadeTimed(lighting, timers);
}

const Texture& CanvasRenderer::shadeTimed(const CanvasLighting& lighting, GpuTimers* timers) {
    const CanvasShading path = mTrial.take();
    mTrialTimers.beginFrame();
    mTrialTimers.begin(kShadingNames[std::size_t(path)]);
    const Texture& out = shade(lighting, path, timers);
    mTrialTimers.end();
    mTrialTimers.endFrame();
    return out;
}

void CanvasRenderer::collectTrialTimes() {
    for (const std::vector<PassTiming>& frame : mTrialTimers.collect()) {
        for (const PassTiming& t : frame) {
            mTrial.record(t.name == kShadingNames[0] ? CanvasShading::Tiled : CanvasShading::Fullscreen,
                          t.gpuMs);
        }
    }
    if (const std::optional<CanvasShading> chosen = mTrial.chosen()) {
        const std::size_t kept = *chosen == CanvasShading::Tiled ? 0 : 1;
        const std::array<double, 2> ms = mTrial.medians();
        logInfo("canvas shading auto: {} ({:.3f} ms a frame against {:.3f} ms {}, median of {} frames each)",
                kShadingNames[kept], ms[kept], ms[1 - kept], kept == 0 ? "full screen" : "tiled",
                CanvasPathTrial::kSamples);
    }
}

const Texture& CanvasRenderer::shade(const CanvasLighting& lighting, CanvasShading shading,
                                     GpuTimers* timers) {
    const Extent e = mOutput.extent();
    const double bytes = double(e.width) * double(e.height) * (8.0 + 4.0 + 8.0); // colour + material + output
    ScopedGpuTimer timer(
        timers, shading == CanvasShading::Tiled ? "canvas shade (tiled)" : "canvas shade (fullscreen)",
        bytes);
    DebugGroup group(shading == CanvasShading::Tiled ? "canvas shade (tiled)" : "canvas shade (fullscreen)");
    glBindTextureUnit(0, mColor.id());
    glBindTextureUnit(1, mMaterial.id());
    glBindImageTexture(0, mOutput.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    if (shading == CanvasShading::Fullscreen) {
        setLightingUniforms(mFullscreenProgram, lighting);
        mFullscreenProgram.use();
        glDispatchCompute(GLuint((e.width + kGroupSize - 1) / kGroupSize),
                          GLuint((e.height + kGroupSize - 1) / kGroupSize), 1);
    } else {
        // Occupied tiles get the full shading, the rest diffuse only: every pixel is written exactly once.
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileListBinding, mTileLists.id());
        glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, mTileLists.id());
        setLightingUniforms(mTiledSpecularProgram, lighting);
        setUniform(mTiledSpecularProgram, "uListOffset", 0);
        mTiledSpecularProgram.use();
        glDispatchComputeIndirect(GLintptr(offsetof(GpuTileListsHeader, occupiedArgs)));
        setLightingUniforms(mTiledDiffuseProgram, lighting);
        setUniform(mTiledDiffuseProgram, "uListOffset", mGrid.count());
        mTiledDiffuseProgram.use();
        glDispatchComputeIndirect(GLintptr(offsetof(GpuTileListsHeader, emptyArgs)));
        glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_FRAMEBUFFER_BARRIER_BIT);
    return mOutput;
}

} // namespace photopic
