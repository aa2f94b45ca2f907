// SPDX-License-Identifier: Apache-2.0
// Unity's `{fileID, guid, type}` references and what a shader reference resolves to.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace varc::project {

// The GUIDs of Unity's two built-in resource files: `Resources/unity_builtin_extra` (where the
// built-in shaders materials use live) and `Library/unity default resources`. The same fileID
// names different objects in the two, so a built-in reference is the pair (GUID, fileID).
inline constexpr std::string_view kBuiltinExtraGuid = "0000000000000000f000000000000000";
inline constexpr std::string_view kDefaultResourcesGuid = "0000000000000000e000000000000000";

// The main object of an imported `.shader` (class 48 × 100000).
inline constexpr int64_t kShaderMainFileId = 4800000;

// `{fileID: F, guid: G, type: T}` as written; `{fileID: 0}` (no object) has an empty guid.
struct AssetReference {
    int64_t fileId = 0;
    std::string guid;
    int type = 0;

    bool isNull() const { return fileId == 0 && guid.empty(); }
    bool isBuiltin() const { return guid == kBuiltinExtraGuid || guid == kDefaultResourcesGuid; }
    friend bool operator==(const AssetReference&, const AssetReference&) = default;
};

enum class ShaderReferenceKind {
    Project,      // a GUID some `.shader.meta` of the project defines: |shaderPath| is set
    UnknownGuid,  // a GUID no `.shader.meta` defines: Unity draws with its error shader
    Builtin,      // a built-in resource GUID; see BuiltinShaders.h for the fileID's name
    Missing,      // `{fileID: 0}`, no `m_Shader` field, or an unreadable reference
};

// "project", "unknown-guid", "builtin" or "missing".
const char* shaderReferenceKindName(ShaderReferenceKind kind);

// Where a material (or a collection, or GraphicsSettings) points for its shader.
struct ShaderReference {
    ShaderReferenceKind kind = ShaderReferenceKind::Missing;
    AssetReference asset;  // as written in the file
    std::string
        shaderPath;  // kind Project: the shader's asset path, e.g. "Assets/Shaders/Rock.shader"
};

}  // namespace varc::project
