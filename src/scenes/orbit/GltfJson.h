#pragma once
// The glTF loader's first pass over the JSON, before tinygltf sees it. tinygltf skips a value of the wrong
// type without a word (a "primitives" object instead of an array loads as a mesh with no primitives),
// truncates indices above INT_MAX, recurses once per level of nesting, and reads an image's bytes through
// its buffer view before checking that view's range. This pass rejects all of those first, with the JSON
// path of the value, so what tinygltf then parses has the shape the loader relies on.

#include "scenes/orbit/GltfModel.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <span>

namespace photopic::orbit::detail {

/// Parses JSON text; a syntax error, or arrays and objects nested deeper than `maxDepth`, is a ModelError.
[[nodiscard]] nlohmann::json parseGltfJson(std::span<const std::uint8_t> text,
                                           const std::filesystem::path& file, int maxDepth);

/// Checks the type of every value the loader reads, that each index fits an int, that every buffer view lies
/// inside its buffer's declared length, and that the asset is glTF 2.x.
void checkGltfJson(const nlohmann::json& root, const std::filesystem::path& file);

} // namespace photopic::orbit::detail
