// SPDX-License-Identifier: Apache-2.0
// The single-pass light buffer and per-draw light lists (SHADER_ABI.md §4.12).
#include <gtest/gtest.h>

#include <cmath>

#include "varc/render/SinglePassValues.h"

namespace varc::render {
namespace {

glm::vec4 element(const ShaderValues& values, const char* name, size_t i) {
    const ShaderValue* value = values.find(name);
    if (!value || value->width != 4 || value->elements() <= i) return glm::vec4(NAN);
    const float* f = value->data.data() + 4 * i;
    return {f[0], f[1], f[2], f[3]};
}

TEST(SinglePassValues, SpotConstantsFollowTheInnerAngleRule) {
    // 90°: outer 45°, tan(inner) = 46/64 tan(outer), so cos(inner) = 1/sqrt(1 + (46/64)²).
    const float outerCos = std::sqrt(0.5f);
    const float innerCos = 1.0f / std::sqrt(1.0f + (46.0f / 64.0f) * (46.0f / 64.0f));  // 0.81202
    const glm::vec2 ab = spotFadeConstants(90.0f);
    EXPECT_NEAR(ab.x, 1.0f / (innerCos - outerCos), 1e-3f);
    EXPECT_NEAR(ab.y, -outerCos * ab.x, 1e-3f);
    // The fade is 0 at the outer edge and 1 at the inner one.
    EXPECT_NEAR(outerCos * ab.x + ab.y, 0.0f, 1e-4f);
    EXPECT_NEAR(innerCos * ab.x + ab.y, 1.0f, 1e-4f);
    // A 0° cone keeps the denominator at 0.001 instead of dividing by zero.
    EXPECT_FLOAT_EQ(spotFadeConstants(0.0f).x, 1000.0f);
}

TEST(SinglePassValues, LightBufferPerLightType) {
    scene::Scene s;
    scene::Light directional;
    directional.color = {1.0f, 0.5f, 0.25f};
    directional.intensity = 2.0f;
    directional.transform.rotationDegrees = {90, 0, 0};  // travels down -y
    scene::Light point;
    point.type = scene::LightType::Point;
    point.transform.position = {1, 2, 3};
    point.range = 4.0f;
    scene::Light spot = point;
    spot.type = scene::LightType::Spot;
    spot.spotAngle = 90.0f;
    s.lights = {directional, point, spot};
    scene::VisibleLightSet visible;
    visible.slots = {2, 0, 1};
    const ShaderValues values = lightBufferValues(s, visible);
    EXPECT_EQ(values.find("_VisibleLightColors")->elements(), 16u);
    EXPECT_EQ(element(values, "_VisibleLightColors", 1), glm::vec4(2.0f, 1.0f, 0.5f, 0.0f));
    const glm::vec4 towards = element(values, "_VisibleLightDirectionsOrPositions", 1);
    EXPECT_NEAR(towards.y, 1.0f, 1e-6f);
    EXPECT_EQ(towards.w, 0.0f);
    EXPECT_EQ(element(values, "_VisibleLightAttenuations", 1), glm::vec4(0, 0, 0, 1));
    EXPECT_EQ(element(values, "_VisibleLightDirectionsOrPositions", 2), glm::vec4(1, 2, 3, 1));
    EXPECT_EQ(element(values, "_VisibleLightAttenuations", 2), glm::vec4(1.0f / 16.0f, 0, 0, 1));
    const glm::vec2 ab = spotFadeConstants(90.0f);
    EXPECT_EQ(element(values, "_VisibleLightAttenuations", 0),
              glm::vec4(1.0f / 16.0f, 0, ab.x, ab.y));
    EXPECT_EQ(element(values, "_VisibleLightSpotDirections", 0), glm::vec4(0, 0, -1, 0));
    EXPECT_EQ(element(values, "_VisibleLightColors", 3), glm::vec4(0.0f));
}

TEST(SinglePassValues, DrawListsSplitIntoPixelAndVertexLights) {
    scene::ObjectLightList list;
    list.count = 11;
    list.slots = {5, 3, 9, 0, 15, 1, 2, 7};
    const ShaderValues values = drawLightValues(list);
    EXPECT_EQ(element(values, "unity_LightIndicesOffsetAndCount", 0), glm::vec4(0, 11, 0, 0));
    EXPECT_EQ(element(values, "unity_4LightIndices0", 0), glm::vec4(5, 3, 9, 0));
    EXPECT_EQ(element(values, "unity_4LightIndices1", 0), glm::vec4(15, 1, 2, 7));
    scene::ObjectLightList none;
    EXPECT_EQ(element(drawLightValues(none), "unity_LightIndicesOffsetAndCount", 0),
              glm::vec4(0.0f));
}

}  // namespace
}  // namespace varc::render
