// SPDX-License-Identifier: Apache-2.0
// objectLightmaps: an object's ForwardBase lightmap keywords per mixed lighting mode.
#include <gtest/gtest.h>

#include "varc/scene/ObjectLightmaps.h"

namespace varc::scene {
namespace {

Object withLightmap(bool baked, bool realtime, bool directional) {
    Object object;
    Lightmap lightmap;
    if (baked) lightmap.baked = glm::vec3(1.0f);
    if (realtime) lightmap.realtime = glm::vec3(1.0f);
    if (directional) lightmap.directional = glm::vec4(0, 1, 0, 1);
    object.lightmap = lightmap;
    return object;
}

TEST(ObjectLightmaps, DynamicObjectUsesProbesOnly) {
    Scene scene;
    const ObjectLightmaps keys = objectLightmaps(scene, Object{});
    EXPECT_FALSE(keys.lightmap || keys.dirLightmap || keys.dynamicLightmap || keys.shadowmask ||
                 keys.shadowMixing);
    EXPECT_TRUE(keys.lightProbes);
    EXPECT_TRUE(keys.vertexLights());
}

TEST(ObjectLightmaps, LightmapsSetTheirKeywordsAndDropProbesAndVertexLights) {
    Scene scene;
    ObjectLightmaps keys = objectLightmaps(scene, withLightmap(true, true, true));
    EXPECT_TRUE(keys.lightmap && keys.dynamicLightmap && keys.dirLightmap);
    EXPECT_FALSE(keys.lightProbes);
    EXPECT_FALSE(keys.vertexLights());
    keys = objectLightmaps(scene, withLightmap(false, true, false));  // realtime GI only
    EXPECT_FALSE(keys.lightmap || keys.dirLightmap || keys.lightProbes);
    EXPECT_TRUE(keys.dynamicLightmap && keys.vertexLights());
    Object probes = withLightmap(true, false, false);
    probes.lightProbes = true;
    EXPECT_TRUE(objectLightmaps(scene, probes).lightProbes);
}

TEST(ObjectLightmaps, MixedModesSetTheShadowMixingKeywords) {
    Scene scene;
    const Object lightmapped = withLightmap(true, false, false);
    const Object dynamic;
    struct Case {
        MixedLightingMode mode;
        bool lightmappedMask, lightmappedMixing, dynamicMask, dynamicMixing;
    };
    for (const Case& c : {Case{MixedLightingMode::BakedIndirect, false, false, false, false},
                          Case{MixedLightingMode::Subtractive, false, true, false, false},
                          Case{MixedLightingMode::Shadowmask, true, true, true, true},
                          Case{MixedLightingMode::DistanceShadowmask, true, false, true, false}}) {
        scene.mixedLighting = c.mode;
        const ObjectLightmaps a = objectLightmaps(scene, lightmapped);
        const ObjectLightmaps b = objectLightmaps(scene, dynamic);
        EXPECT_EQ(a.shadowmask, c.lightmappedMask);
        EXPECT_EQ(a.shadowMixing, c.lightmappedMixing);
        EXPECT_EQ(b.shadowmask, c.dynamicMask);
        EXPECT_EQ(b.shadowMixing, c.dynamicMixing);
    }
}

}  // namespace
}  // namespace varc::scene
