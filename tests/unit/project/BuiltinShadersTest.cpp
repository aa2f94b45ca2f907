// SPDX-License-Identifier: Apache-2.0
// The built-in shader fileID table and resolving built-in references by shader name.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "varc/project/BuiltinShaders.h"

namespace varc::project {
namespace {

using ::testing::HasSubstr;

AssetReference extra(int64_t fileId) { return {fileId, std::string(kBuiltinExtraGuid), 0}; }

TEST(BuiltinShaders, KnownIdsHaveTheirUnityNames) {
    EXPECT_EQ(builtinShaderName(kBuiltinExtraGuid, 46), "Standard");
    EXPECT_EQ(builtinShaderName(kBuiltinExtraGuid, 45), "Standard (Specular setup)");
    EXPECT_EQ(builtinShaderName(kBuiltinExtraGuid, 10752), "Unlit/Texture");
    EXPECT_EQ(builtinShaderName(kBuiltinExtraGuid, 10755), "Unlit/Color");
    EXPECT_EQ(builtinShaderName(kDefaultResourcesGuid, 10101), "GUI/Text Shader");
}

TEST(BuiltinShaders, TheGuidDecidesWhichFileTheIdIsIn) {
    EXPECT_EQ(builtinShaderName(kDefaultResourcesGuid, 10755), std::nullopt);
    EXPECT_EQ(builtinShaderName(kDefaultResourcesGuid, 46), std::nullopt);
    EXPECT_EQ(builtinShaderName("0123456789abcdef0123456789abcdef", 46), std::nullopt);
}

TEST(BuiltinShaders, UncertainIdsAreNotGuessed) {
    EXPECT_EQ(builtinShaderName(kBuiltinExtraGuid, 47), std::nullopt);
    EXPECT_EQ(builtinShaderName(kBuiltinExtraGuid, 10753), std::nullopt);
    EXPECT_EQ(builtinShaderName(kBuiltinExtraGuid, 15104), std::nullopt);
}

TEST(BuiltinShaders, ResolvesByNameAmongTheCandidates) {
    std::vector<NamedShader> candidates = {{"Unlit/Texture", "b/Unlit-Normal.shader"},
                                           {"Standard", "b/Standard.shader"}};
    BuiltinResolution found = resolveBuiltinShader(extra(46), candidates);
    EXPECT_EQ(found.name, "Standard");
    EXPECT_EQ(found.shaderIndex, 1u);
    EXPECT_TRUE(found.note.empty());
    BuiltinResolution absent = resolveBuiltinShader(extra(45), candidates);
    EXPECT_EQ(absent.name, "Standard (Specular setup)");
    EXPECT_EQ(absent.shaderIndex, std::nullopt);
    EXPECT_THAT(absent.note, HasSubstr("no shader named \"Standard (Specular setup)\""));
}

TEST(BuiltinShaders, OlderParticleNamesAreTriedAsAliases) {
    std::vector<NamedShader> candidates = {{"Particles/Alpha Blended", "p.shader"}};
    EXPECT_EQ(resolveBuiltinShader(extra(203), candidates).shaderIndex, 0u);
}

TEST(BuiltinShaders, UnknownIdAndNonBuiltinReferencesGiveClearNotes) {
    BuiltinResolution unknown = resolveBuiltinShader(extra(99999), {{"Standard", "s"}});
    EXPECT_EQ(unknown.name, std::nullopt);
    EXPECT_THAT(unknown.note,
                HasSubstr("unknown built-in shader fileID 99999 in unity_builtin_extra"));
    AssetReference project{4800000, "0123456789abcdef0123456789abcdef", 3};
    EXPECT_THAT(resolveBuiltinShader(project, {}).note, HasSubstr("not a built-in"));
}

}  // namespace
}  // namespace varc::project
