// SPDX-License-Identifier: Apache-2.0
#include "varc/render/RenderStateResolver.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace varc::render {

namespace {

template <typename T>
void resolve(pack::StateField<T>& field, const ShaderValues& material, uint32_t enumCount) {
    if (!field.isProperty()) return;
    if (const ShaderValue* value = material.find(field.property); value && !value->data.empty()) {
        float number = value->data[0];
        if constexpr (std::is_same_v<T, bool>) {
            field.value = number != 0.0f;
        } else if constexpr (std::is_same_v<T, float>) {
            field.value = number;
        } else if constexpr (std::is_same_v<T, uint8_t>) {
            field.value = static_cast<uint8_t>(std::clamp(number, 0.0f, 255.0f));
        } else {
            auto index = static_cast<uint32_t>(std::max(0.0f, std::round(number)));
            if (index < enumCount) field.value = static_cast<T>(index);
        }
    }
    field.property.clear();
}

VkBlendFactor toVk(pack::BlendFactor factor) {
    switch (factor) {
        case pack::BlendFactor::Zero:
            return VK_BLEND_FACTOR_ZERO;
        case pack::BlendFactor::One:
            return VK_BLEND_FACTOR_ONE;
        case pack::BlendFactor::DstColor:
            return VK_BLEND_FACTOR_DST_COLOR;
        case pack::BlendFactor::SrcColor:
            return VK_BLEND_FACTOR_SRC_COLOR;
        case pack::BlendFactor::OneMinusDstColor:
            return VK_BLEND_FACTOR_ONE_MINUS_DST_COLOR;
        case pack::BlendFactor::SrcAlpha:
            return VK_BLEND_FACTOR_SRC_ALPHA;
        case pack::BlendFactor::OneMinusSrcColor:
            return VK_BLEND_FACTOR_ONE_MINUS_SRC_COLOR;
        case pack::BlendFactor::DstAlpha:
            return VK_BLEND_FACTOR_DST_ALPHA;
        case pack::BlendFactor::OneMinusDstAlpha:
            return VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA;
        case pack::BlendFactor::SrcAlphaSaturate:
            return VK_BLEND_FACTOR_SRC_ALPHA_SATURATE;
        case pack::BlendFactor::OneMinusSrcAlpha:
            return VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    }
    return VK_BLEND_FACTOR_ONE;
}

VkBlendOp toVk(pack::BlendOp op) {
    switch (op) {
        case pack::BlendOp::Add:
            return VK_BLEND_OP_ADD;
        case pack::BlendOp::Subtract:
            return VK_BLEND_OP_SUBTRACT;
        case pack::BlendOp::ReverseSubtract:
            return VK_BLEND_OP_REVERSE_SUBTRACT;
        case pack::BlendOp::Min:
            return VK_BLEND_OP_MIN;
        case pack::BlendOp::Max:
            return VK_BLEND_OP_MAX;
    }
    return VK_BLEND_OP_ADD;
}

VkCompareOp toVk(pack::CompareFunction function) {
    switch (function) {
        case pack::CompareFunction::Disabled:
            return VK_COMPARE_OP_ALWAYS;
        case pack::CompareFunction::Never:
            return VK_COMPARE_OP_NEVER;
        case pack::CompareFunction::Less:
            return VK_COMPARE_OP_LESS;
        case pack::CompareFunction::Equal:
            return VK_COMPARE_OP_EQUAL;
        case pack::CompareFunction::LessEqual:
            return VK_COMPARE_OP_LESS_OR_EQUAL;
        case pack::CompareFunction::Greater:
            return VK_COMPARE_OP_GREATER;
        case pack::CompareFunction::NotEqual:
            return VK_COMPARE_OP_NOT_EQUAL;
        case pack::CompareFunction::GreaterEqual:
            return VK_COMPARE_OP_GREATER_OR_EQUAL;
        case pack::CompareFunction::Always:
            return VK_COMPARE_OP_ALWAYS;
    }
    return VK_COMPARE_OP_ALWAYS;
}

VkStencilOp toVk(pack::StencilOp op) {
    switch (op) {
        case pack::StencilOp::Keep:
            return VK_STENCIL_OP_KEEP;
        case pack::StencilOp::Zero:
            return VK_STENCIL_OP_ZERO;
        case pack::StencilOp::Replace:
            return VK_STENCIL_OP_REPLACE;
        case pack::StencilOp::IncrementSaturate:
            return VK_STENCIL_OP_INCREMENT_AND_CLAMP;
        case pack::StencilOp::DecrementSaturate:
            return VK_STENCIL_OP_DECREMENT_AND_CLAMP;
        case pack::StencilOp::Invert:
            return VK_STENCIL_OP_INVERT;
        case pack::StencilOp::IncrementWrap:
            return VK_STENCIL_OP_INCREMENT_AND_WRAP;
        case pack::StencilOp::DecrementWrap:
            return VK_STENCIL_OP_DECREMENT_AND_WRAP;
    }
    return VK_STENCIL_OP_KEEP;
}

void resolveFace(pack::PackStencilFace& face, const ShaderValues& material) {
    resolve(face.comp, material, pack::kCompareFunctionCount);
    resolve(face.pass, material, pack::kStencilOpCount);
    resolve(face.fail, material, pack::kStencilOpCount);
    resolve(face.zFail, material, pack::kStencilOpCount);
}

VkStencilOpState toVk(const pack::PackStencilFace& face, const pack::PackRenderState& state) {
    VkStencilOpState op{};
    op.failOp = toVk(face.fail.value);
    op.passOp = toVk(face.pass.value);
    op.depthFailOp = toVk(face.zFail.value);
    op.compareOp = toVk(face.comp.value);
    op.compareMask = state.stencilReadMask.value;
    op.writeMask = state.stencilWriteMask.value;
    op.reference = state.stencilRef.value;
    return op;
}

VkColorComponentFlags toVkColorMask(uint8_t unityMask) {
    VkColorComponentFlags flags = 0;
    if (unityMask & pack::kColorWriteRed) flags |= VK_COLOR_COMPONENT_R_BIT;
    if (unityMask & pack::kColorWriteGreen) flags |= VK_COLOR_COMPONENT_G_BIT;
    if (unityMask & pack::kColorWriteBlue) flags |= VK_COLOR_COMPONENT_B_BIT;
    if (unityMask & pack::kColorWriteAlpha) flags |= VK_COLOR_COMPONENT_A_BIT;
    return flags;
}

}  // namespace

pack::PackRenderState resolveRenderState(const pack::PackRenderState& state,
                                         const ShaderValues& material) {
    pack::PackRenderState resolved = state;
    resolve(resolved.srcColor, material, pack::kBlendFactorCount);
    resolve(resolved.dstColor, material, pack::kBlendFactorCount);
    resolve(resolved.srcAlpha, material, pack::kBlendFactorCount);
    resolve(resolved.dstAlpha, material, pack::kBlendFactorCount);
    resolve(resolved.colorOp, material, pack::kBlendOpCount);
    resolve(resolved.alphaOp, material, pack::kBlendOpCount);
    resolve(resolved.zWrite, material, 2);
    resolve(resolved.zTest, material, pack::kCompareFunctionCount);
    resolve(resolved.cull, material, pack::kCullModeCount);
    resolve(resolved.colorMask, material, 16);
    resolve(resolved.offsetFactor, material, 0);
    resolve(resolved.offsetUnits, material, 0);
    resolve(resolved.stencilRef, material, 256);
    resolve(resolved.stencilReadMask, material, 256);
    resolve(resolved.stencilWriteMask, material, 256);
    resolveFace(resolved.front, material);
    resolveFace(resolved.back, material);
    return resolved;
}

pack::PackRenderState forObjectTransform(pack::PackRenderState state,
                                         const glm::mat4& objectToWorld) {
    if (glm::determinant(objectToWorld) >= 0.0f) return state;
    if (state.cull.value == pack::CullMode::Back) {
        state.cull.value = pack::CullMode::Front;
    } else if (state.cull.value == pack::CullMode::Front) {
        state.cull.value = pack::CullMode::Back;
    }
    return state;
}

VulkanRenderState toVulkan(const pack::PackRenderState& state, bool hasStencil) {
    VulkanRenderState vk;
    auto& raster = vk.rasterization;
    raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.lineWidth = 1.0f;
    raster.frontFace = VK_FRONT_FACE_CLOCKWISE;
    switch (state.cull.value) {
        case pack::CullMode::Off:
            raster.cullMode = VK_CULL_MODE_NONE;
            break;
        case pack::CullMode::Front:
            raster.cullMode = VK_CULL_MODE_FRONT_BIT;
            break;
        case pack::CullMode::Back:
            raster.cullMode = VK_CULL_MODE_BACK_BIT;
            break;
    }
    if (state.offsetFactor.value != 0.0f || state.offsetUnits.value != 0.0f) {
        raster.depthBiasEnable = VK_TRUE;
        raster.depthBiasSlopeFactor = state.offsetFactor.value;
        raster.depthBiasConstantFactor = state.offsetUnits.value;
    }
    auto& depth = vk.depthStencil;
    depth.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
    depth.depthTestEnable = VK_TRUE;  // ZTest Off = Disabled = always pass, but still a test
    depth.depthWriteEnable = state.zWrite.value ? VK_TRUE : VK_FALSE;
    depth.depthCompareOp = toVk(state.zTest.value);
    depth.stencilTestEnable = (state.stencilEnabled && hasStencil) ? VK_TRUE : VK_FALSE;
    depth.front = toVk(state.front, state);
    depth.back = toVk(state.back, state);
    depth.maxDepthBounds = 1.0f;
    auto& blend = vk.blend;
    blend.blendEnable = state.blendEnabled ? VK_TRUE : VK_FALSE;
    blend.srcColorBlendFactor = toVk(state.srcColor.value);
    blend.dstColorBlendFactor = toVk(state.dstColor.value);
    blend.colorBlendOp = toVk(state.colorOp.value);
    blend.srcAlphaBlendFactor = toVk(state.srcAlpha.value);
    blend.dstAlphaBlendFactor = toVk(state.dstAlpha.value);
    blend.alphaBlendOp = toVk(state.alphaOp.value);
    blend.colorWriteMask = toVkColorMask(state.colorMask.value);
    return vk;
}

}  // namespace varc::render
