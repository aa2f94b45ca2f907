// SPDX-License-Identifier: Apache-2.0
#include <gtest/gtest.h>

#include <cstring>

#include "varc/render/UniformBlockWriter.h"

namespace varc::render {
namespace {

float floatAt(const std::vector<std::byte>& bytes, size_t offset) {
    float value = 0;
    std::memcpy(&value, bytes.data() + offset, 4);
    return value;
}

int32_t intAt(const std::vector<std::byte>& bytes, size_t offset) {
    int32_t value = 0;
    std::memcpy(&value, bytes.data() + offset, 4);
    return value;
}

// A block laid out as glslang lays out a cbuffer (std140-like), offsets chosen by hand.
pack::UniformBlock sampleBlock() {
    pack::UniformBlock block{"UnityPerDraw", 0, 0, 160, {}};
    block.members = {{"_Tint", 0, 16, "float4", 0, false},
                     {"_Smoothness", 16, 4, "float", 0, false},
                     {"_Direction", 20, 12, "float3", 0, false},
                     {"unity_ObjectToWorld", 32, 64, "float4x4", 0, true},
                     {"_Colors", 96, 48, "float4", 3, false},
                     {"_Count", 144, 4, "int", 0, false},
                     {"_Unset", 148, 4, "float", 0, false}};
    return block;
}

TEST(UniformBlockWriter, WritesEachMemberAtItsReflectedOffset) {
    ShaderValues values;
    values.set("_Tint", glm::vec4(0.1f, 0.2f, 0.3f, 0.4f));
    values.set("_Smoothness", 0.75f);
    values.set("_Direction", glm::vec4(1, 2, 3, 99));  // w must not spill into _ObjectToWorld
    glm::mat4 matrix(1.0f);
    matrix[3] = glm::vec4(5, 6, 7, 1);  // translation: column 3
    values.set("unity_ObjectToWorld", matrix);
    std::vector<glm::vec4> colors = {glm::vec4(1), glm::vec4(2)};
    values.setArray("_Colors", colors);
    values.set("_Count", 3.0f);
    const ShaderValues* layers[] = {&values};
    std::vector<std::byte> bytes;
    BlockWriteReport report = writeUniformBlock(sampleBlock(), layers, bytes);

    ASSERT_EQ(bytes.size(), 160u);
    EXPECT_FLOAT_EQ(floatAt(bytes, 8), 0.3f);
    EXPECT_FLOAT_EQ(floatAt(bytes, 16), 0.75f);
    EXPECT_FLOAT_EQ(floatAt(bytes, 28), 3.0f);
    EXPECT_FLOAT_EQ(floatAt(bytes, 32), 1.0f);       // column 0, row 0
    EXPECT_FLOAT_EQ(floatAt(bytes, 32 + 48), 5.0f);  // column 3, row 0 (glm's column-major order)
    EXPECT_FLOAT_EQ(floatAt(bytes, 32 + 52), 6.0f);
    EXPECT_FLOAT_EQ(floatAt(bytes, 96 + 16), 2.0f);  // _Colors[1].x at stride 16
    EXPECT_FLOAT_EQ(floatAt(bytes, 96 + 32), 0.0f);  // _Colors[2] was not given
    EXPECT_EQ(intAt(bytes, 144), 3);
    EXPECT_EQ(report.missing, std::vector<std::string>{"_Unset"});
}

TEST(UniformBlockWriter, EarlierLayersWin) {
    ShaderValues object, material;
    object.set("_Tint", glm::vec4(1, 0, 0, 1));
    material.set("_Tint", glm::vec4(0, 1, 0, 1));
    material.set("_Smoothness", 0.5f);
    const ShaderValues* layers[] = {&object, &material};
    std::vector<std::byte> bytes;
    writeUniformBlock(sampleBlock(), layers, bytes);
    EXPECT_FLOAT_EQ(floatAt(bytes, 0), 1.0f);
    EXPECT_FLOAT_EQ(floatAt(bytes, 4), 0.0f);
    EXPECT_FLOAT_EQ(floatAt(bytes, 16), 0.5f);
}

TEST(UniformBlockWriter, NeverWritesPastAMemberThatOverrunsTheBlock) {
    pack::UniformBlock block{"Broken", 0, 0, 16, {{"_Big", 8, 64, "float4x4", 0, false}}};
    ShaderValues values;
    values.set("_Big", glm::mat4(2.0f));
    const ShaderValues* layers[] = {&values};
    std::vector<std::byte> bytes;
    writeUniformBlock(block, layers, bytes);
    ASSERT_EQ(bytes.size(), 16u);
    EXPECT_FLOAT_EQ(floatAt(bytes, 8), 0.0f);
}

}  // namespace
}  // namespace varc::render
