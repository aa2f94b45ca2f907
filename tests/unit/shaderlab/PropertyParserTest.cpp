// SPDX-License-Identifier: Apache-2.0
// parseShaderLab: the Properties block (types, attributes, defaults, errors).
#include <gtest/gtest.h>

#include "ShaderLabTestSupport.h"
#include "varc/shaderlab/ShaderLabParser.h"

namespace varc::shaderlab {
namespace {

using testing::parse;
using testing::trimMargin;

// Parses `Shader "A" { Properties { <body> } }`.
testing::ParseOutcome parseProperties(std::string_view body) {
    return parse("Shader \"A\" { Properties { " + std::string(body) + " } }");
}

TEST(PropertyParser, ParsesEveryPropertyType) {
    auto outcome = parse(trimMargin(R"(
        |Shader "A" {
        |    Properties {
        |        _C ("c", Color) = (1, 0.5, 0, 1)
        |        _V ("v", Vector) = (0,0,0,0)
        |        _F ("f", Float) = 1.5
        |        _I ("i", Int) = 2
        |        _J ("j", Integer) = -3
        |        _R ("r", Range(-1, .5)) = 0
        |        _T2 ("t2", 2D) = "white" {}
        |        _T3 ("t3", 3D) = "" {}
        |        _TC ("tc", Cube) = "" {}
        |        _TA ("ta", 2DArray) = "" {}
        |        _TCA ("tca", CubeArray) = "" {}
        |        _TX ("tx", Any) = "" {}
        |    }
        |}
    )"));
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    const auto& properties = outcome.shader->properties;
    std::vector<PropertyType> types;
    for (const Property& property : properties) types.push_back(property.type);
    EXPECT_EQ(types,
              (std::vector<PropertyType>{
                  PropertyType::Color, PropertyType::Vector, PropertyType::Float, PropertyType::Int,
                  PropertyType::Integer, PropertyType::Range, PropertyType::Texture2D,
                  PropertyType::Texture3D, PropertyType::Cube, PropertyType::Texture2DArray,
                  PropertyType::CubeArray, PropertyType::Any}));
    EXPECT_EQ(properties.at(5).rangeMin, -1.0f);
    EXPECT_EQ(properties.at(5).rangeMax, 0.5f);
    EXPECT_EQ(properties.at(0).name, "_C");
    EXPECT_EQ(properties.at(0).displayName, "c");
    EXPECT_EQ(properties.at(0).location, (SourceLocation{testing::kTestFile, 3, 9}));
}

TEST(PropertyParser, KeepsDefaultValuesAsWritten) {
    auto outcome = parseProperties(R"(
        _Tint ("Tint", Color) = (1, 1, 1, 1)
        _Two ("Two", Vector) = (1,2)
        _Neg ("Neg", Float) = -0.25
        _Half ("Half", Float) = .5
        _Tex ("Tex", 2D) = "white" {}
        _Bump ("Bump", 2D) = "bump"
        _Cube ("Cube", Cube) = "" { TexGen CubeReflect })");
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    std::vector<std::string> defaults;
    for (const Property& property : outcome.shader->properties) {
        defaults.push_back(property.defaultValue);
    }
    EXPECT_EQ(defaults,
              (std::vector<std::string>{"(1, 1, 1, 1)", "(1,2)", "-0.25", ".5", "\"white\" {}",
                                        "\"bump\"", "\"\" { TexGen CubeReflect }"}));
}

TEST(PropertyParser, KeepsAttributesAsWrittenWithoutBrackets) {
    auto outcome = parseProperties(R"(
        [Gamma] _Metallic ("Metallic", Range(0, 1)) = 0
        [HDR] [PerRendererData] _E ("E", Color) = (0,0,0,1)
        [Toggle] _T ("T", Float) = 0
        [Toggle(_FOO_ON)] _T2 ("T2", Float) = 0
        [KeywordEnum(A, B)] _K ("K", Float) = 0
        [Enum(UnityEngine.Rendering.BlendMode)] _SrcBlend ("Src", Float) = 1
        [NoScaleOffset] [MainTexture] _M ("M", 2D) = "white" {}
        [Header(Some text: with, punctuation!)] [Space(10)] _H ("H", Float) = 0)");
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    const auto& p = outcome.shader->properties;
    ASSERT_EQ(p.size(), 8u);
    using Attributes = std::vector<std::string>;
    EXPECT_EQ(p[0].attributes, (Attributes{"Gamma"}));
    EXPECT_EQ(p[1].attributes, (Attributes{"HDR", "PerRendererData"}));
    EXPECT_EQ(p[2].attributes, (Attributes{"Toggle"}));
    EXPECT_EQ(p[3].attributes, (Attributes{"Toggle(_FOO_ON)"}));
    EXPECT_EQ(p[4].attributes, (Attributes{"KeywordEnum(A, B)"}));
    EXPECT_EQ(p[5].attributes, (Attributes{"Enum(UnityEngine.Rendering.BlendMode)"}));
    EXPECT_EQ(p[6].attributes, (Attributes{"NoScaleOffset", "MainTexture"}));
    EXPECT_EQ(p[7].attributes, (Attributes{"Header(Some text: with, punctuation!)", "Space(10)"}));
}

TEST(PropertyParser, AcceptsEmptyPropertiesBlock) {
    auto outcome = parseProperties("");
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    EXPECT_TRUE(outcome.shader->properties.empty());
}

TEST(PropertyParser, ReportsUnknownPropertyTypeAtTheType) {
    auto outcome = parseProperties("_X (\"X\", Matrix) = 0");
    EXPECT_FALSE(outcome.shader);
    EXPECT_EQ(outcome.firstMessage(), "unknown property type 'Matrix'");
    EXPECT_EQ(outcome.firstLocation(), (SourceLocation{testing::kTestFile, 1, 36}));
}

TEST(PropertyParser, ReportsDefaultOfTheWrongKind) {
    auto number = parseProperties("_F (\"F\", Float) = \"white\"");
    EXPECT_FALSE(number.shader);
    EXPECT_EQ(number.firstMessage(),
              "expected a number as the default of property _F, found \"white\"");
    auto texture = parseProperties("_T (\"T\", 2D) = 1");
    EXPECT_FALSE(texture.shader);
    EXPECT_EQ(texture.firstMessage(),
              "expected a texture name string as the default of property _T, found '1'");
    auto color = parseProperties("_C (\"C\", Color) = (1, 1, 1, 1, 1)");
    EXPECT_FALSE(color.shader);
    EXPECT_EQ(color.firstMessage(), "expected ')' after four components, found ','");
}

TEST(PropertyParser, ReportsMissingDisplayNameAndUnterminatedAttribute) {
    auto display = parseProperties("_X (Float) = 0");
    EXPECT_FALSE(display.shader);
    EXPECT_EQ(display.firstMessage(), "expected a display name string, found 'Float'");
    auto attribute = parseProperties("[Header(oops) _X (\"X\", Float) = 0\n");
    EXPECT_FALSE(attribute.shader);
    EXPECT_EQ(attribute.firstMessage(),
              "unterminated attribute: missing ']' before the end of the line");
    EXPECT_EQ(attribute.firstLocation(), (SourceLocation{testing::kTestFile, 1, 27}));
}

}  // namespace
}  // namespace varc::shaderlab
