// SPDX-License-Identifier: Apache-2.0
// RenderState::inheritedFrom: which fields a pass takes from its SubShader or Category.
#include <gtest/gtest.h>

#include "varc/shaderlab/RenderState.h"

namespace varc::shaderlab {
namespace {

StateValue literal(std::string text) { return StateValue{std::move(text), {}}; }

TEST(RenderState, UnsetFieldsTakeTheOuterValueAndSetFieldsStay) {
    RenderState inner;
    inner.cull = literal("Off");
    RenderState outer;
    outer.cull = literal("Front");
    outer.zWrite = literal("Off");
    outer.zTest = StateValue{{}, "_ZTest"};
    outer.offset = std::make_pair(literal("-1"), literal("-1"));
    outer.alphaToMask = literal("On");
    RenderState merged = inner.inheritedFrom(outer);
    EXPECT_EQ(merged.cull, literal("Off"));
    EXPECT_EQ(merged.zWrite, literal("Off"));
    EXPECT_EQ(merged.zTest.property, "_ZTest");
    EXPECT_EQ(merged.offset, outer.offset);
    EXPECT_EQ(merged.alphaToMask, literal("On"));
    EXPECT_FALSE(merged.blend);
}

TEST(RenderState, InheritingFromEmptyStateChangesNothing) {
    RenderState inner;
    inner.blend = BlendState{false, literal("One"), literal("One"), {}, {}, {}, {}};
    inner.colorMask = literal("RGB");
    EXPECT_EQ(inner.inheritedFrom(RenderState{}), inner);
    EXPECT_EQ(RenderState{}.inheritedFrom(inner), inner);
}

TEST(RenderState, BlendOpOnlyPassKeepsOuterBlendFactors) {
    RenderState inner;
    inner.blend = BlendState{};
    inner.blend->op = literal("Max");
    RenderState outer;
    outer.blend = BlendState{false, literal("One"), literal("One"), {}, {}, literal("Add"), {}};
    RenderState merged = inner.inheritedFrom(outer);
    ASSERT_TRUE(merged.blend);
    EXPECT_EQ(merged.blend->src, literal("One"));
    EXPECT_EQ(merged.blend->op, literal("Max"));
}

TEST(RenderState, BlendOffWrittenInPassIsNotOverriddenByOuterFactors) {
    RenderState inner;
    inner.blend = BlendState{};
    inner.blend->off = true;
    RenderState outer;
    outer.blend = BlendState{
        false, literal("SrcAlpha"), literal("OneMinusSrcAlpha"), {}, {}, literal("Sub"), {}};
    RenderState merged = inner.inheritedFrom(outer);
    ASSERT_TRUE(merged.blend);
    EXPECT_TRUE(merged.blend->off);
    EXPECT_FALSE(merged.blend->src.isSet());
    EXPECT_EQ(merged.blend->op, literal("Sub"));
}

TEST(RenderState, StencilFieldsInheritOneByOne) {
    RenderState inner;
    inner.stencil = StencilState{};
    inner.stencil->ref = literal("3");
    inner.stencil->back.comp = literal("Equal");
    RenderState outer;
    outer.stencil = StencilState{};
    outer.stencil->ref = literal("1");
    outer.stencil->readMask = literal("7");
    outer.stencil->front.comp = literal("Always");
    outer.stencil->back.comp = literal("Never");
    RenderState merged = inner.inheritedFrom(outer);
    ASSERT_TRUE(merged.stencil);
    EXPECT_EQ(merged.stencil->ref, literal("3"));
    EXPECT_EQ(merged.stencil->readMask, literal("7"));
    EXPECT_EQ(merged.stencil->front.comp, literal("Always"));
    EXPECT_EQ(merged.stencil->back.comp, literal("Equal"));
}

}  // namespace
}  // namespace varc::shaderlab
