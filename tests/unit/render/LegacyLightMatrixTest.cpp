// SPDX-License-Identifier: Apache-2.0
// The legacy light matrix name _LightMatrix0 carries unity_WorldToLight (SHADER_ABI.md §4.6).
#include <gtest/gtest.h>

#include "varc/render/DeferredValues.h"
#include "varc/render/SceneValues.h"

namespace varc::render {
namespace {

// A GLSLPROGRAM declares `uniform mat4 _LightMatrix0;` itself (the corpus's Custom/LightCookie):
// it must read the same matrix as unity_WorldToLight, for every light and for none.
void expectSameMatrix(const ShaderValues& values) {
    const ShaderValue* modern = values.find("unity_WorldToLight");
    const ShaderValue* legacy = values.find("_LightMatrix0");
    ASSERT_TRUE(modern && legacy);
    EXPECT_EQ(legacy->width, 16u);
    EXPECT_EQ(legacy->data, modern->data);
}

TEST(LegacyLightMatrix, CarriesTheWorldToLightMatrixOfEveryLight) {
    scene::Light point;
    point.type = scene::LightType::Point;
    point.transform.position = {1.0f, 2.0f, 3.0f};
    point.range = 4.0f;
    scene::Light spot = point;
    spot.type = scene::LightType::Spot;
    expectSameMatrix(forwardLightValues(nullptr));
    expectSameMatrix(forwardLightValues(&point));
    expectSameMatrix(forwardLightValues(&spot));
    expectSameMatrix(deferredLightValues(spot, false));
    // Not the identity: a point light's matrix scales by 1 / range.
    EXPECT_FLOAT_EQ(forwardLightValues(&point).find("_LightMatrix0")->data[0], 0.25f);
}

}  // namespace
}  // namespace varc::render
