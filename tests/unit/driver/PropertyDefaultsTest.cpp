// SPDX-License-Identifier: Apache-2.0
// toPackProperty: ShaderLab default texts to the pack's property defaults.
#include <gtest/gtest.h>

#include "varc/driver/PropertyDefaults.h"

namespace varc::driver {
namespace {

shaderlab::Property property(std::string name, shaderlab::PropertyType type, std::string text) {
    shaderlab::Property p;
    p.name = std::move(name);
    p.type = type;
    p.defaultValue = std::move(text);
    return p;
}

TEST(PropertyDefaults, ReadsNumbersVectorsAndTextureNames) {
    using T = shaderlab::PropertyType;
    auto gloss = toPackProperty(property("_Glossiness", T::Range, "0.5"));
    ASSERT_TRUE(gloss.ok());
    EXPECT_EQ(gloss->kind, pack::PropertyKind::Float);
    EXPECT_EQ(gloss->value[0], 0.5f);
    auto color = toPackProperty(property("_Color", T::Color, "( 1, 0.25 ,0,1 )"));
    ASSERT_TRUE(color.ok());
    EXPECT_EQ(color->kind, pack::PropertyKind::Color);
    EXPECT_EQ(color->value, (std::array<float, 4>{1.0f, 0.25f, 0.0f, 1.0f}));
    auto offset = toPackProperty(property("_Offset", T::Vector, "(2, -3)"));
    ASSERT_TRUE(offset.ok());
    EXPECT_EQ(offset->value, (std::array<float, 4>{2.0f, -3.0f, 0.0f, 0.0f}));
    auto count = toPackProperty(property("_Count", T::Int, "+4"));
    ASSERT_TRUE(count.ok());
    EXPECT_EQ(count->value[0], 4.0f);
    auto bump = toPackProperty(property("_BumpMap", T::Texture2D, "\"bump\" {}"));
    ASSERT_TRUE(bump.ok());
    EXPECT_EQ(bump->kind, pack::PropertyKind::Texture);
    EXPECT_EQ(bump->texture, "bump");
    auto none = toPackProperty(property("_Cube", T::Cube, "\"\" { TexGen CubeReflect }"));
    ASSERT_TRUE(none.ok());
    EXPECT_EQ(none->texture, "");
}

TEST(PropertyDefaults, AMalformedDefaultSaysWhatWasExpected) {
    using T = shaderlab::PropertyType;
    auto color = toPackProperty(property("_Color", T::Color, "1"));
    ASSERT_FALSE(color.ok());
    EXPECT_EQ(color.error().detail,
              "the default of _Color (Color) should be (x, y, z, w), not '1'");
    EXPECT_FALSE(toPackProperty(property("_F", T::Float, "0.5x")).ok());
    EXPECT_FALSE(toPackProperty(property("_V", T::Vector, "(1, 2, 3, 4, 5)")).ok());
    EXPECT_FALSE(toPackProperty(property("_V", T::Vector, "(1)")).ok());
    EXPECT_FALSE(toPackProperty(property("_T", T::Texture2D, "white {}")).ok());
}

}  // namespace
}  // namespace varc::driver
