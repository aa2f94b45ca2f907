// SPDX-License-Identifier: Apache-2.0
// Parsing UnityYAML text with yaml-cpp, and the small typed accessors every reader uses.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "LoadContext.h"
#include "varc/project/AssetReference.h"

namespace varc::project {

// True when |text| is a binary-serialised Unity asset: those start with the big-endian
// SerializedFile header (metadata size, file size, ...), so NUL bytes come within the first
// bytes, which text YAML never has.
bool isBinaryAsset(std::string_view text);

// The documents of UnityYAML |text| read from |file| (`%YAML 1.1`, `%TAG !u! ...`, then one
// `--- !u!<class> &<fileID>` document per object; yaml-cpp reads these as they are, so no
// pre-processing is needed). Nullopt after a warning for a binary asset or malformed YAML (at
// yaml-cpp's line and column). Never throws.
std::optional<std::vector<YAML::Node>> parseUnityYaml(std::string_view text,
                                                      const std::filesystem::path& file,
                                                      LoadContext& context);

// The first document's object mapping under |className| (`Material:`, `GraphicsSettings:`), or
// nullopt when no document has one.
std::optional<YAML::Node> findObject(const std::vector<YAML::Node>& documents,
                                     std::string_view className);

// |map|[|key|] when |map| is a mapping that has |key|; nullopt otherwise.
std::optional<YAML::Node> field(const YAML::Node& map, const char* key);
// The text of a scalar; "" for a null (empty) value; nullopt for a mapping or sequence. yaml-cpp
// reads the plain scalars `null`, `Null`, `NULL` and `~` as null, so they come back as "" too (a
// material named "Null" has no name here); Unity does not quote them.
std::optional<std::string> scalarText(const YAML::Node& node);
// A decimal integer scalar (Unity writes `0`, `1`, `-1`); nullopt otherwise.
std::optional<int64_t> integerValue(const YAML::Node& node);
// `{fileID: F, guid: G, type: T}`; nullopt when it is not a mapping with an integer fileID.
std::optional<AssetReference> assetReference(const YAML::Node& node);
// 1-based (line, column) of |node| in its file; (0, 0) when yaml-cpp has none.
std::pair<uint32_t, uint32_t> positionOf(const YAML::Node& node);

// Keywords from a space-separated string (a wrapped plain scalar arrives joined by spaces) or a
// sequence of strings (Unity 4 and the 2021.2+ lists). Tokens made only of `_` are dropped.
std::vector<std::string> keywordList(const YAML::Node& node);

}  // namespace varc::project
