// SPDX-License-Identifier: Apache-2.0
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "varc/render/RenderStateResolver.h"

namespace varc::render {
namespace {

// Seed 002's light pass: `Blend [_SrcBlend] [_DstBlend]`, ZWrite Off.
pack::PackRenderState deferredLightState() {
    pack::PackRenderState state;
    state.blendEnabled = true;
    state.srcColor = {pack::BlendFactor::One, "_SrcBlend"};
    state.dstColor = {pack::BlendFactor::Zero, "_DstBlend"};
    state.zWrite = {false, {}};
    return state;
}

TEST(RenderStateResolver, PropertiesTakeTheMaterialsUnityEnumValues) {
    ShaderValues material;
    material.set("_SrcBlend", 2.0f);  // DstColor (LDR: multiply into exp2(-c))
    material.set("_DstBlend", 0.0f);  // Zero
    pack::PackRenderState resolved = resolveRenderState(deferredLightState(), material);
    EXPECT_EQ(resolved.srcColor.value, pack::BlendFactor::DstColor);
    EXPECT_EQ(resolved.dstColor.value, pack::BlendFactor::Zero);
    EXPECT_FALSE(resolved.srcColor.isProperty());
    VulkanRenderState vk = toVulkan(resolved, true);
    EXPECT_EQ(vk.blend.srcColorBlendFactor, VK_BLEND_FACTOR_DST_COLOR);
    EXPECT_EQ(vk.blend.dstColorBlendFactor, VK_BLEND_FACTOR_ZERO);
    EXPECT_EQ(vk.depthStencil.depthWriteEnable, VK_FALSE);
}

TEST(RenderStateResolver, MissingOrOutOfRangePropertiesKeepTheDefault) {
    ShaderValues material;
    material.set("_DstBlend", 42.0f);  // not a BlendFactor
    pack::PackRenderState resolved = resolveRenderState(deferredLightState(), material);
    EXPECT_EQ(resolved.srcColor.value, pack::BlendFactor::One);
    EXPECT_EQ(resolved.dstColor.value, pack::BlendFactor::Zero);
}

TEST(RenderStateResolver, CullingAndColorMaskFollowUnityConventions) {
    pack::PackRenderState state;
    state.cull = {pack::CullMode::Front, {}};
    state.colorMask = {static_cast<uint8_t>(pack::kColorWriteRed | pack::kColorWriteAlpha), {}};
    VulkanRenderState vk = toVulkan(resolveRenderState(state, {}), true);
    EXPECT_EQ(vk.rasterization.cullMode, static_cast<VkCullModeFlags>(VK_CULL_MODE_FRONT_BIT));
    EXPECT_EQ(vk.rasterization.frontFace, VK_FRONT_FACE_CLOCKWISE);
    EXPECT_EQ(vk.blend.colorWriteMask, static_cast<VkColorComponentFlags>(
                                           VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_A_BIT));
}

TEST(RenderStateResolver, AMirroringTransformSwapsTheCulledSide) {
    pack::PackRenderState back;
    const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 2.0f, 1.0f));
    const glm::mat4 plain = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 2.0f, 1.0f));
    EXPECT_EQ(forObjectTransform(back, mirror).cull.value, pack::CullMode::Front);
    EXPECT_EQ(forObjectTransform(back, plain).cull.value, pack::CullMode::Back);
    pack::PackRenderState front = back;
    front.cull.value = pack::CullMode::Front;
    EXPECT_EQ(forObjectTransform(front, mirror).cull.value, pack::CullMode::Back);
    pack::PackRenderState off = back;
    off.cull.value = pack::CullMode::Off;
    EXPECT_EQ(forObjectTransform(off, mirror).cull.value, pack::CullMode::Off);
    // Two mirrorings are a rotation: nothing changes.
    const glm::mat4 twice = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, -1.0f, 1.0f));
    EXPECT_EQ(forObjectTransform(back, twice).cull.value, pack::CullMode::Back);
}

TEST(RenderStateResolver, StencilNeedsAStencilAttachment) {
    pack::PackRenderState state;
    state.stencilEnabled = true;
    EXPECT_EQ(toVulkan(state, true).depthStencil.stencilTestEnable, VK_TRUE);
    EXPECT_EQ(toVulkan(state, false).depthStencil.stencilTestEnable, VK_FALSE);
}

}  // namespace
}  // namespace varc::render
