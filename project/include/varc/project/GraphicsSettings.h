// SPDX-License-Identifier: Apache-2.0
// The fields of `ProjectSettings/GraphicsSettings.asset` that decide which variants a build keeps.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "varc/project/AssetReference.h"

namespace varc::project {

// A preloaded ShaderVariantCollection: the reference as written and, when a `.meta` of the
// project defines its GUID, the collection's asset path.
struct PreloadedCollection {
    AssetReference asset;
    std::string collectionPath;
};

// Each field is nullopt when the file does not have it (older Unity versions lack some; Unity
// then uses 0 / "keep"). Values are Unity's: stripping 0 = Automatic, 1 = Custom; instancing
// 0 = Strip Unused, 1 = Strip All, 2 = Keep All.
struct GraphicsSettings {
    std::string path;  // on disk
    std::optional<int> serializedVersion;
    std::vector<ShaderReference> alwaysIncluded;  // `m_AlwaysIncludedShaders`, in file order
    std::vector<PreloadedCollection> preloaded;   // `m_PreloadedShaders`
    std::optional<int> lightmapStripping;
    std::optional<int> fogStripping;
    std::optional<int> instancingStripping;
    std::optional<int> brgStripping;
    std::optional<bool> lightmapKeepPlain, lightmapKeepDirCombined, lightmapKeepDynamicPlain,
        lightmapKeepDynamicDirCombined, lightmapKeepShadowMask, lightmapKeepSubtractive;
    // Only in files of Unity before 5.6 (serializedVersion 5).
    std::optional<bool> lightmapKeepDirSeparate, lightmapKeepDynamicDirSeparate;
    std::optional<bool> fogKeepLinear, fogKeepExp, fogKeepExp2;
    // `m_CustomRenderPipeline`; nullopt when absent or `{fileID: 0}` (the Built-in pipeline).
    std::optional<AssetReference> customRenderPipeline;
};

}  // namespace varc::project
