// SPDX-License-Identifier: Apache-2.0
#include <gtest/gtest.h>

#include <cstddef>

#include "varc/render/VertexLayout.h"

namespace varc::render {
namespace {

TEST(VertexLayout, SemanticsAndLegacyNamesMapOntoTheMeshStreams) {
    std::vector<pack::VertexInput> inputs = {{"v.vertex", "POSITION", 0, "float4"},
                                             {"v.normal", "NORMAL", 1, "float3"},
                                             {"v.uv", "TEXCOORD0", 2, "float2"},
                                             {"varc_Color", "", 3, "float4"}};
    auto layout = vertexInputLayout(inputs);
    ASSERT_TRUE(layout) << layout.error().detail;
    EXPECT_EQ(layout->binding.stride, sizeof(MeshVertex));
    ASSERT_EQ(layout->attributes.size(), 4u);
    EXPECT_EQ(layout->attributes[0].offset, offsetof(MeshVertex, position));
    EXPECT_EQ(layout->attributes[1].offset, offsetof(MeshVertex, normal));
    EXPECT_EQ(layout->attributes[2].offset, offsetof(MeshVertex, uv));
    EXPECT_EQ(layout->attributes[2].location, 2u);
    EXPECT_EQ(layout->attributes[3].offset, offsetof(MeshVertex, color));
}

TEST(VertexLayout, UnknownSemanticIsAnErrorNamingIt) {
    auto layout = vertexInputLayout({{"v.weights", "BLENDWEIGHT", 0, "float4"}});
    ASSERT_FALSE(layout);
    EXPECT_NE(layout.error().detail.find("BLENDWEIGHT"), std::string::npos);
}

}  // namespace
}  // namespace varc::render
