#include "passes/FramePass.h"

namespace photopic {

std::string_view resourceName(Resource resource) noexcept {
    switch (resource) {
    case Resource::Color:
        return "color";
    case Resource::Depth:
        return "depth";
    case Resource::Normals:
        return "normals";
    case Resource::Motion:
        return "motion";
    case Resource::Camera:
        return "camera";
    case Resource::SunDirection:
        return "sunDirection";
    case Resource::ObjectId:
        return "objectId";
    case Resource::MeteringMask:
        return "meteringMask";
    case Resource::SceneColor:
        return "sceneColor";
    case Resource::LinearDepth:
        return "linearDepth";
    case Resource::Histogram:
        return "histogram";
    case Resource::Metering:
        return "metering";
    case Resource::ExposureState:
        return "exposure";
    case Resource::Bloom:
        return "bloom";
    case Resource::LensFlare:
        return "lensFlare";
    case Resource::TaaDebug:
        return "taaDebug";
    case Resource::AmbientOcclusion:
        return "ambientOcclusion";
    case Resource::ContactShadows:
        return "contactShadows";
    case Resource::ContactShadowSteps:
        return "contactShadowSteps";
    case Resource::DofCoc:
        return "dofCoc";
    case Resource::Material:
        return "material";
    case Resource::DepthPyramid:
        return "depthPyramid";
    case Resource::Reflections:
        return "reflections";
    case Resource::VelocityTiles:
        return "velocityTiles";
    case Resource::VolumetricLight:
        return "volumetricLight";
    case Resource::SunShadowMap:
        return "sunShadow";
    case Resource::DebugColor:
        return "debugColor";
    case Resource::DisplayColor:
        return "displayColor";
    case Resource::Count:
        break;
    }
    return "?";
}

void FrameResources::clear() noexcept {
    mTextures.fill(nullptr);
    mBuffers.fill(nullptr);
    mPresent.fill(false);
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
