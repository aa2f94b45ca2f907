// SPDX-License-Identifier: Apache-2.0
// The built-in shader fileID table and name lookup among caller-supplied shaders.
#include "varc/project/BuiltinShaders.h"

#include <algorithm>
#include <array>

namespace varc::project {

namespace {

struct BuiltinEntry {
    int64_t fileId;
    std::string_view name;
    std::string_view alias;  // the name in other Unity versions; empty for none
};

// `unity_builtin_extra` (kBuiltinExtraGuid), sorted by fileID. Only IDs whose names two
// independent sources agree on, plus 45/46 (confirmed by real projects) and 62-75 (confirmed
// by GraphicsSettings slots). Left out as uncertain: 47, 102, 105, 209, 210, 211, 10706
// (name varies), 10753 (sources disagree on the resource file), 10757, 10783, 14002, 15104-15106,
// 16000-16002, 17000.
constexpr std::array<BuiltinEntry, 101> kExtra{{
    {1, "Legacy Shaders/Diffuse Fast", ""},
    {2, "Legacy Shaders/Bumped Diffuse", ""},
    {3, "Legacy Shaders/Specular", ""},
    {4, "Legacy Shaders/Bumped Specular", ""},
    {5, "Legacy Shaders/Diffuse Detail", ""},
    {6, "Legacy Shaders/VertexLit", ""},
    {7, "Legacy Shaders/Diffuse", ""},
    {8, "Legacy Shaders/Parallax Diffuse", ""},
    {9, "Legacy Shaders/Parallax Specular", ""},
    {10, "Legacy Shaders/Self-Illumin/Diffuse", ""},
    {11, "Legacy Shaders/Self-Illumin/Bumped Diffuse", ""},
    {12, "Legacy Shaders/Self-Illumin/Specular", ""},
    {13, "Legacy Shaders/Self-Illumin/Bumped Specular", ""},
    {14, "Legacy Shaders/Self-Illumin/VertexLit", ""},
    {15, "Legacy Shaders/Self-Illumin/Parallax Diffuse", ""},
    {16, "Legacy Shaders/Self-Illumin/Parallax Specular", ""},
    {20, "Legacy Shaders/Reflective/Diffuse", ""},
    {21, "Legacy Shaders/Reflective/Bumped Diffuse", ""},
    {22, "Legacy Shaders/Reflective/Specular", ""},
    {23, "Legacy Shaders/Reflective/Bumped Specular", ""},
    {24, "Legacy Shaders/Reflective/VertexLit", ""},
    {25, "Legacy Shaders/Reflective/Bumped Unlit", ""},
    {26, "Legacy Shaders/Reflective/Bumped VertexLit", ""},
    {27, "Legacy Shaders/Reflective/Parallax Diffuse", ""},
    {28, "Legacy Shaders/Reflective/Parallax Specular", ""},
    {30, "Legacy Shaders/Transparent/Diffuse", ""},
    {31, "Legacy Shaders/Transparent/Bumped Diffuse", ""},
    {32, "Legacy Shaders/Transparent/Specular", ""},
    {33, "Legacy Shaders/Transparent/Bumped Specular", ""},
    {34, "Legacy Shaders/Transparent/VertexLit", ""},
    {35, "Legacy Shaders/Transparent/Parallax Diffuse", ""},
    {36, "Legacy Shaders/Transparent/Parallax Specular", ""},
    {40, "Legacy Shaders/Lightmapped/VertexLit", ""},
    {41, "Legacy Shaders/Lightmapped/Diffuse", ""},
    {42, "Legacy Shaders/Lightmapped/Bumped Diffuse", ""},
    {43, "Legacy Shaders/Lightmapped/Specular", ""},
    {44, "Legacy Shaders/Lightmapped/Bumped Specular", ""},
    {45, "Standard (Specular setup)", ""},
    {46, "Standard", ""},
    {50, "Legacy Shaders/Transparent/Cutout/VertexLit", ""},
    {51, "Legacy Shaders/Transparent/Cutout/Diffuse", ""},
    {52, "Legacy Shaders/Transparent/Cutout/Bumped Diffuse", ""},
    {53, "Legacy Shaders/Transparent/Cutout/Specular", ""},
    {54, "Legacy Shaders/Transparent/Cutout/Bumped Specular", ""},
    {62, "Hidden/Internal-DepthNormalsTexture", ""},
    {63, "Hidden/Internal-PrePassLighting", ""},
    {64, "Hidden/Internal-ScreenSpaceShadows", ""},
    {69, "Hidden/Internal-DeferredShading", ""},
    {74, "Hidden/Internal-DeferredReflections", ""},
    {75, "Hidden/Internal-MotionVectors", ""},
    {100, "Legacy Shaders/Decal", ""},
    {101, "FX/Flare", ""},
    {103, "Skybox/Cubemap", ""},
    {104, "Skybox/6 Sided", ""},
    {106, "Skybox/Procedural", ""},
    {200, "Legacy Shaders/Particles/Additive", "Particles/Additive"},
    {201, "Legacy Shaders/Particles/~Additive-Multiply", "Particles/~Additive-Multiply"},
    {202, "Legacy Shaders/Particles/Additive (Soft)", "Particles/Additive (Soft)"},
    {203, "Legacy Shaders/Particles/Alpha Blended", "Particles/Alpha Blended"},
    {205, "Legacy Shaders/Particles/Multiply", "Particles/Multiply"},
    {206, "Legacy Shaders/Particles/Multiply (Double)", "Particles/Multiply (Double)"},
    {207, "Legacy Shaders/Particles/Alpha Blended Premultiply",
     "Particles/Alpha Blended Premultiply"},
    {208, "Legacy Shaders/Particles/VertexLit Blended", "Particles/VertexLit Blended"},
    {10505, "Nature/Terrain/Diffuse", ""},
    {10509, "Nature/Tree Soft Occlusion Bark", ""},
    {10511, "Nature/Tree Soft Occlusion Leaves", ""},
    {10512, "Legacy Shaders/Transparent/Cutout/Soft Edge Unlit", ""},
    {10600, "Nature/Tree Creator Bark", ""},
    {10601, "Nature/Tree Creator Leaves", ""},
    {10606, "Nature/Tree Creator Leaves Fast", ""},
    {10620, "Nature/Terrain/Specular", ""},
    {10623, "Nature/Terrain/Standard", ""},
    {10700, "Mobile/Skybox", ""},
    {10701, "Mobile/VertexLit", ""},
    {10703, "Mobile/Diffuse", ""},
    {10704, "Mobile/Bumped Diffuse", ""},
    {10705, "Mobile/Bumped Specular", ""},
    {10707, "Mobile/VertexLit (Only Directional Lights)", ""},
    {10708, "Mobile/Unlit (Supports Lightmap)", ""},
    {10720, "Mobile/Particles/Additive", ""},
    {10721, "Mobile/Particles/Alpha Blended", ""},
    {10722, "Mobile/Particles/VertexLit Blended", ""},
    {10723, "Mobile/Particles/Multiply", ""},
    {10750, "Unlit/Transparent", ""},
    {10751, "Unlit/Transparent Cutout", ""},
    {10752, "Unlit/Texture", ""},
    {10755, "Unlit/Color", ""},
    {10760, "UI/Unlit/Transparent", ""},
    {10761, "UI/Unlit/Detail", ""},
    {10762, "UI/Unlit/Text", ""},
    {10763, "UI/Unlit/Text Detail", ""},
    {10764, "UI/Lit/Transparent", ""},
    {10765, "UI/Lit/Bumped", ""},
    {10766, "UI/Lit/Detail", ""},
    {10767, "UI/Lit/Refraction", ""},
    {10768, "UI/Lit/Refraction Detail", ""},
    {10770, "UI/Default", ""},
    {10782, "UI/Default Font", ""},
    {10800, "Sprites/Diffuse", ""},
    {14000, "Nature/SpeedTree", ""},
    {14001, "Nature/SpeedTree Billboard", ""},
}};

// `unity default resources` (kDefaultResourcesGuid).
constexpr std::array<BuiltinEntry, 1> kDefaultResources{{{10101, "GUI/Text Shader", ""}}};

const BuiltinEntry* findEntry(std::string_view guid, int64_t fileId) {
    auto search = [fileId](const auto& table) -> const BuiltinEntry* {
        auto it = std::lower_bound(table.begin(), table.end(), fileId,
                                   [](const BuiltinEntry& e, int64_t id) { return e.fileId < id; });
        return it != table.end() && it->fileId == fileId ? &*it : nullptr;
    };
    if (guid == kBuiltinExtraGuid) return search(kExtra);
    if (guid == kDefaultResourcesGuid) return search(kDefaultResources);
    return nullptr;
}

std::string_view resourceFileName(std::string_view guid) {
    return guid == kBuiltinExtraGuid ? "unity_builtin_extra" : "unity default resources";
}

}  // namespace

std::optional<std::string_view> builtinShaderName(std::string_view guid, int64_t fileId) {
    const BuiltinEntry* entry = findEntry(guid, fileId);
    if (!entry) return std::nullopt;
    return entry->name;
}

std::vector<std::string_view> builtinShaderAliases(std::string_view guid, int64_t fileId) {
    const BuiltinEntry* entry = findEntry(guid, fileId);
    if (!entry || entry->alias.empty()) return {};
    return {entry->alias};
}

BuiltinResolution resolveBuiltinShader(const AssetReference& reference,
                                       const std::vector<NamedShader>& candidates) {
    BuiltinResolution result;
    if (!reference.isBuiltin()) {
        result.note = "not a built-in resource reference (guid " + reference.guid + ")";
        return result;
    }
    const BuiltinEntry* entry = findEntry(reference.guid, reference.fileId);
    if (!entry) {
        result.note = "unknown built-in shader fileID " + std::to_string(reference.fileId) +
                      " in " + std::string(resourceFileName(reference.guid)) +
                      "; varc's table names only IDs it knows for certain";
        return result;
    }
    result.name = std::string(entry->name);
    for (std::string_view wanted : {entry->name, entry->alias}) {
        if (wanted.empty()) continue;
        for (size_t i = 0; i < candidates.size(); ++i) {
            if (candidates[i].name == wanted) {
                result.shaderIndex = i;
                return result;
            }
        }
    }
    result.note = "no shader named \"" + std::string(entry->name) + "\" (built-in fileID " +
                  std::to_string(reference.fileId) + ") among the shaders supplied";
    return result;
}

}  // namespace varc::project
