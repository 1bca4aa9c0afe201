#include "passes/FramePass.h"

#include <array>

namespace photopic {

namespace {
/// By Resource, in its order.
constexpr std::array<std::string_view, kResourceCount> kResourceNames = {
    "color",              // Color
    "depth",              // Depth
    "normals",            // Normals
    "motion",             // Motion
    "camera",             // Camera
    "sunDirection",       // SunDirection
    "objectId",           // ObjectId
    "meteringMask",       // MeteringMask
    "sceneColor",         // SceneColor
    "linearDepth",        // LinearDepth
    "histogram",          // Histogram
    "metering",           // Metering
    "exposure",           // ExposureState
    "bloom",              // Bloom
    "lensFlare",          // LensFlare
    "taaDebug",           // TaaDebug
    "ambientOcclusion",   // AmbientOcclusion
    "contactShadows",     // ContactShadows
    "debugColor",         // DebugColor
    "displayColor",       // DisplayColor
    "contactShadowSteps", // ContactShadowSteps
    "dofCoc",             // DofCoc
    "material",           // Material
    "depthPyramid",       // DepthPyramid
    "reflections",        // Reflections
    "velocityTiles",      // VelocityTiles
    "volumetricLight",    // VolumetricLight
    "sunShadow",          // SunShadowMap
    "ssrHistory",         // SsrHistory
};
static_assert(!kResourceNames.back().empty(), "one name per Resource, in its order");
} // namespace

std::string_view resourceName(Resource resource) noexcept {
    const auto index = std::size_t(resource);
    return index < kResourceNames.size() ? kResourceNames[index] : "?";
}

void FrameResources::clear() noexcept {
    mTextures.fill(nullptr);
    mBuffers.fill(nullptr);
    mPresent.fill(false);
}

int normalsSource(const FrameContext& ctx, const FrameResources& resources) noexcept {
    if (resources.texture(Resource::Normals) == nullptr) {
        return 0;
    }
    return ctx.inputs.normalEncoding == NormalEncoding::Octahedral ? 2 : 1;
}

QualityTier effectiveTier(const Capabilities& caps, Quality quality) noexcept {
    QualityTier tier = qualityTier(quality);
    if (caps.path == ColorPath::Ldr) {
        const QualityTier legacy = qualityTier(Quality::Legacy);
        tier.hdrPath = false;
        tier.bloom = legacy.bloom;
        tier.glow = legacy.glow;
        tier.lensFlare = legacy.lensFlare;
    }
    return tier;
}

bool legacyGlow(const QualityTier& tier, const Settings& settings) noexcept {
    return !tier.hdrPath && tier.glow && settings.bloom.enabled;
}

} // namespace photopic
