// The glTF Builder's materials (GltfBuilder.h): factors checked, textures and their samplers, and images
// read, checked for size and decoded with stb_image.
#include "scenes/orbit/GltfBuilder.h"

#include <stb_image.h>

#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>

namespace photopic::orbit::detail {

// ---- Materials, textures, images ------------------------------------------------------------------------

namespace {

float finiteFactor(double value, const ModelError& error, float lo, float hi) {
    if (!std::isfinite(value)) {
        throw error;
    }
    return std::clamp(float(value), lo, hi);
}

} // namespace

Material Builder::convertMaterial(std::size_t index, Model& model) {
    const tinygltf::Material& m = mGltf.materials[index];
    const std::string where = path("materials", index);
    const ModelError nonFinite(mFile, ModelIssue::NonFinite, where, "a factor is not finite");
    const float big = std::numeric_limits<float>::max();
    Material out;
    out.name = m.name;
    const auto& pbr = m.pbrMetallicRoughness;
    for (int c = 0; c < 4; ++c) {
        out.baseColorFactor[c] = finiteFactor(pbr.baseColorFactor.at(std::size_t(c)), nonFinite, 0.0f, 1.0f);
    }
    for (int c = 0; c < 3; ++c) {
        out.emissiveFactor[c] = finiteFactor(m.emissiveFactor.at(std::size_t(c)), nonFinite, 0.0f, big);
    }
    out.metallicFactor = finiteFactor(pbr.metallicFactor, nonFinite, 0.0f, 1.0f);
    out.roughnessFactor = finiteFactor(pbr.roughnessFactor, nonFinite, 0.0f, 1.0f);
    out.normalScale = finiteFactor(m.normalTexture.scale, nonFinite, -big, big);
    out.occlusionStrength = finiteFactor(m.occlusionTexture.strength, nonFinite, 0.0f, 1.0f);
    out.alphaCutoff = finiteFactor(m.alphaCutoff, nonFinite, 0.0f, big);
    out.doubleSided = m.doubleSided;
    if (m.alphaMode == "MASK" || m.alphaMode == "BLEND" || m.alphaMode == "OPAQUE") {
        out.alphaMode = m.alphaMode == "MASK"    ? AlphaMode::Mask
                        : m.alphaMode == "BLEND" ? AlphaMode::Blend
                                                 : AlphaMode::Opaque;
    } else {
        fail(ModelIssue::WrongType, where + ".alphaMode",
             "\"" + m.alphaMode + "\" is not OPAQUE, MASK or BLEND");
    }
    const std::string pbrWhere = where + ".pbrMetallicRoughness";
    // Colour is stored sRGB-encoded, data (normals, metallic-roughness, occlusion) linear.
    const auto& base = pbr.baseColorTexture;
    const auto& orm = pbr.metallicRoughnessTexture;
    const auto& normal = m.normalTexture;
    const auto& occlusion = m.occlusionTexture;
    const auto& emissive = m.emissiveTexture;
    out.baseColorTexture = textureUse(base.index, base.texCoord, true, pbrWhere + ".baseColorTexture", model);
    out.metallicRoughnessTexture =
        textureUse(orm.index, orm.texCoord, false, pbrWhere + ".metallicRoughnessTexture", model);
    out.normalTexture = textureUse(normal.index, normal.texCoord, false, where + ".normalTexture", model);
    out.occlusionTexture =
        textureUse(occlusion.index, occlusion.texCoord, false, where + ".occlusionTexture", model);
    out.emissiveTexture =
        textureUse(emissive.index, emissive.texCoord, true, where + ".emissiveTexture", model);
    return out;
}

int Builder::textureUse(int index, int texCoord, bool srgb, const std::string& where, Model& model) {
    if (index < 0) {
        return -1;
    }
    checkIndex(index, mGltf.textures.size(), where + ".index", "texture");
    if (texCoord != 0) {
        fail(ModelIssue::Unsupported, where + ".texCoord",
             "TEXCOORD_" + std::to_string(texCoord) + " (only TEXCOORD_0 is read)");
    }
    const auto key = std::make_pair(index, srgb);
    if (const auto it = mTextureUses.find(key); it != mTextureUses.end()) {
        return it->second;
    }
    const tinygltf::Texture& t = mGltf.textures[std::size_t(index)];
    const std::string textureWhere = path("textures", std::size_t(index));
    if (t.source < 0) {
        fail(ModelIssue::Unsupported, textureWhere,
             "no source image (an extension's image format is not read)");
    }
    ModelTexture texture;
    texture.srgb = srgb;
    texture.image = decodeImage(t.source, textureWhere + ".source", model);
    if (t.sampler >= 0) {
        checkIndex(t.sampler, mGltf.samplers.size(), textureWhere + ".sampler", "sampler");
        const tinygltf::Sampler& s = mGltf.samplers[std::size_t(t.sampler)];
        texture.sampler = {.magFilter = std::max(s.magFilter, 0),
                           .minFilter = std::max(s.minFilter, 0),
                           .wrapS = s.wrapS,
                           .wrapT = s.wrapT};
    }
    model.textures.push_back(texture);
    mTextureUses.emplace(key, int(model.textures.size() - 1));
    return int(model.textures.size() - 1);
}

int Builder::decodeImage(int image, const std::string& where, Model& model) {
    checkIndex(image, mGltf.images.size(), where, "image");
    if (const auto it = mImages.find(image); it != mImages.end()) {
        return it->second;
    }
    const tinygltf::Image& source = mGltf.images[std::size_t(image)];
    const std::string imageWhere = path("images", std::size_t(image));
    Bytes file;
    if (!source.uri.empty() && !isDataUri(source.uri)) {
        file = readFile(resolveUri(source.uri, mBaseDir, mFile, imageWhere + ".uri"), mFile,
                        imageWhere + ".uri", mLimits.maxFileBytes);
    }
    const Bytes& encoded = file.empty() ? source.image : file;
    int width = 0;
    int height = 0;
    int channels = 0;
    if (encoded.empty() || encoded.size() > std::size_t(INT_MAX) ||
        !stbi_info_from_memory(encoded.data(), int(encoded.size()), &width, &height, &channels)) {
        fail(ModelIssue::BadImage, imageWhere,
             std::string("cannot be decoded: ") + (encoded.empty() ? "no data" : stbi_failure_reason()));
    }
    if (width > mLimits.maxImageSide || height > mLimits.maxImageSide) {
        fail(ModelIssue::TooLarge, imageWhere,
             std::to_string(width) + " x " + std::to_string(height) + " pixels, over the limit of " +
                 std::to_string(mLimits.maxImageSide));
    }
    const std::uint64_t pixelCount = std::uint64_t(width) * std::uint64_t(height);
    if (pixelCount > mLimits.maxImagePixels) {
        fail(ModelIssue::TooLarge, imageWhere,
             fmt::format("{} x {} pixels, over the limit of {} pixels", width, height,
                         mLimits.maxImagePixels));
    }
    // Checked before decoding, from the header: an image whose stored samples could not come from this
    // many bytes is a decompression bomb or lies about its size.
    if (const std::uint64_t needed = minimumEncodedBytes(encoded, width, height, channels);
        encoded.size() < needed) {
        fail(ModelIssue::BadImage, imageWhere,
             fmt::format("{} bytes cannot hold the {} x {} image its header declares (at least {} needed)",
                         encoded.size(), width, height, needed));
    }
    reserve(0, 0, std::uint64_t(width) * std::uint64_t(height) * 4, imageWhere);
    stbi_uc* pixels =
        stbi_load_from_memory(encoded.data(), int(encoded.size()), &width, &height, &channels, 4);
    if (!pixels) {
        fail(ModelIssue::BadImage, imageWhere, std::string("cannot be decoded: ") + stbi_failure_reason());
    }
    TextureImage out;
    out.name = source.name.empty() ? source.uri.substr(0, 64) : source.name;
    out.width = width;
    out.height = height;
    out.rgba.assign(pixels, pixels + std::size_t(width) * std::size_t(height) * 4);
    stbi_image_free(pixels);
    model.images.push_back(std::move(out));
    mImages.emplace(image, int(model.images.size() - 1));
    return int(model.images.size() - 1);
}

} // namespace photopic::orbit::detail
