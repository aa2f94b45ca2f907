// SPDX-License-Identifier: Apache-2.0
// Unity's built-in shaders by fileID, and finding a built-in shader's source by its name.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "varc/project/AssetReference.h"

namespace varc::project {

// The Unity shader name of built-in reference (|guid|, |fileId|), or nullopt when varc's table
// does not know it. The table holds only IDs whose names two independent sources agree on (or
// that real GraphicsSettings slots confirm), e.g. (kBuiltinExtraGuid, 46) -> "Standard",
// (kBuiltinExtraGuid, 45) -> "Standard (Specular setup)"; an unknown ID is reported, never guessed.
std::optional<std::string_view> builtinShaderName(std::string_view guid, int64_t fileId);

// Other names the same shader had in other Unity versions (e.g. the particle shaders gained a
// "Legacy Shaders/" prefix); empty for most.
std::vector<std::string_view> builtinShaderAliases(std::string_view guid, int64_t fileId);

// A shader the caller can supply for a built-in one: its ShaderLab name (`Shader "Name"`) and
// where its source is.
struct NamedShader {
    std::string name;
    std::string path;
};

struct BuiltinResolution {
    std::optional<std::string> name;    // the Unity shader name, when the table knows the ID
    std::optional<size_t> shaderIndex;  // index into the candidates whose name matched
    std::string note;                   // why nothing was found; empty on success
};

// Finds the source of built-in |reference| among |candidates| by name (the first exact match,
// trying the aliases after the name). Fails with a note when |reference| is not a built-in
// resource, its fileID is not in the table ("unknown built-in shader fileID 10755 in
// unity_builtin_extra"), or no candidate has its name.
BuiltinResolution resolveBuiltinShader(const AssetReference& reference,
                                       const std::vector<NamedShader>& candidates);

}  // namespace varc::project
