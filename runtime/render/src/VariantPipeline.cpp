// SPDX-License-Identifier: Apache-2.0
#include "varc/render/VariantPipeline.h"

#include <algorithm>
#include <array>
#include <span>
#include <string>
#include <vector>

#include "varc/reader/ProgramView.h"
#include "varc/render/RenderStateResolver.h"
#include "varc/render/VertexLayout.h"
#include "varc/vulkan/CheckVk.h"
#include "varc/vulkan/ShaderModule.h"

namespace varc::render {

namespace {

Error withContext(const std::string& what, const Error& error) {
    return makeError(error.code, what + ": " + error.detail);
}

Result<std::vector<vulkan::UniqueHandle<VkDescriptorSetLayout>>> createSetLayouts(
    const vulkan::VulkanContext& context, const std::vector<DescriptorSlot>& slots) {
    std::vector<vulkan::UniqueHandle<VkDescriptorSetLayout>> layouts;
    for (uint32_t set = 0; set < descriptorSetCount(slots); ++set) {
        std::vector<VkDescriptorSetLayoutBinding> bindings;
        for (const DescriptorSlot& slot : slots) {
            if (slot.set == set)
                bindings.push_back({slot.binding, slot.type, 1, slot.stages, nullptr});
        }
        VkDescriptorSetLayoutCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
        info.bindingCount = static_cast<uint32_t>(bindings.size());
        info.pBindings = bindings.data();
        VkDescriptorSetLayout layout = VK_NULL_HANDLE;
        if (Status ok = vulkan::checkVk(
                vkCreateDescriptorSetLayout(context.device(), &info, nullptr, &layout),
                "vkCreateDescriptorSetLayout");
            !ok) {
            return ok.error();
        }
        layouts.emplace_back(context.device(), layout);
    }
    return layouts;
}

// One programmable stage of a pipeline.
struct ShaderStage {
    VkShaderStageFlagBits stage;
    VkShaderModule module;
    std::string entryPoint;
};

Result<vulkan::UniqueHandle<VkPipelineLayout>> createPipelineLayout(
    vulkan::VulkanContext& context,
    const std::vector<vulkan::UniqueHandle<VkDescriptorSetLayout>>& setLayouts) {
    std::vector<VkDescriptorSetLayout> rawLayouts;
    for (const auto& layout : setLayouts) rawLayouts.push_back(layout.get());
    VkPipelineLayoutCreateInfo layoutInfo{};
    layoutInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    layoutInfo.setLayoutCount = static_cast<uint32_t>(rawLayouts.size());
    layoutInfo.pSetLayouts = rawLayouts.data();
    VkPipelineLayout layout = VK_NULL_HANDLE;
    if (Status ok =
            vulkan::checkVk(vkCreatePipelineLayout(context.device(), &layoutInfo, nullptr, &layout),
                            "vkCreatePipelineLayout");
        !ok) {
        return ok.error();
    }
    return vulkan::UniqueHandle<VkPipelineLayout>(context.device(), layout);
}

// Unity draws meshes as triangles, so a tessellated mesh arrives in patches of three control
// points (the hull program's InputPatch<..., 3>).
constexpr uint32_t kPatchControlPoints = 3;

// A triangle-list pipeline (patches of three points with tessellation) with dynamic viewport
// and scissor, one sample, |state|'s blend on every colour attachment of |target|.
Result<vulkan::UniqueHandle<VkPipeline>> createGraphicsPipeline(
    vulkan::VulkanContext& context, std::span<const ShaderStage> shaderStages,
    const VertexInputLayout& vertexInput, VkPipelineLayout layout, const VulkanRenderState& state,
    const PipelineTarget& target, VkPipelineCache cache) {
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    for (const ShaderStage& stage : shaderStages) {
        stages.push_back({VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0,
                          stage.stage, stage.module, stage.entryPoint.c_str(), nullptr});
    }
    VkPipelineVertexInputStateCreateInfo vertexInputInfo{};
    vertexInputInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
    if (!vertexInput.attributes.empty()) {
        vertexInputInfo.vertexBindingDescriptionCount = 1;
        vertexInputInfo.pVertexBindingDescriptions = &vertexInput.binding;
        vertexInputInfo.vertexAttributeDescriptionCount =
            static_cast<uint32_t>(vertexInput.attributes.size());
        vertexInputInfo.pVertexAttributeDescriptions = vertexInput.attributes.data();
    }
    bool tessellated = std::any_of(shaderStages.begin(), shaderStages.end(), [](const auto& s) {
        return s.stage == VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT;
    });
    VkPipelineInputAssemblyStateCreateInfo assembly{};
    assembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
    assembly.topology =
        tessellated ? VK_PRIMITIVE_TOPOLOGY_PATCH_LIST : VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineTessellationStateCreateInfo tessellation{};
    tessellation.sType = VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO;
    tessellation.patchControlPoints = kPatchControlPoints;
    VkPipelineViewportStateCreateInfo viewport{};
    viewport.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    VkPipelineMultisampleStateCreateInfo multisample{};
    multisample.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    std::vector<VkPipelineColorBlendAttachmentState> attachments(target.colorAttachments,
                                                                 state.blend);
    VkPipelineColorBlendStateCreateInfo blend{};
    blend.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
    blend.attachmentCount = static_cast<uint32_t>(attachments.size());
    blend.pAttachments = attachments.data();
    std::array<VkDynamicState, 2> dynamicStates = {VK_DYNAMIC_STATE_VIEWPORT,
                                                   VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{};
    dynamic.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO;
    dynamic.dynamicStateCount = static_cast<uint32_t>(dynamicStates.size());
    dynamic.pDynamicStates = dynamicStates.data();

    VkGraphicsPipelineCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
    info.stageCount = static_cast<uint32_t>(stages.size());
    info.pStages = stages.data();
    info.pVertexInputState = &vertexInputInfo;
    info.pInputAssemblyState = &assembly;
    info.pTessellationState = tessellated ? &tessellation : nullptr;
    info.pViewportState = &viewport;
    info.pRasterizationState = &state.rasterization;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &state.depthStencil;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamic;
    info.layout = layout;
    info.renderPass = target.renderPass;
    VkPipeline pipeline = VK_NULL_HANDLE;
    if (Status ok = vulkan::checkVk(
            vkCreateGraphicsPipelines(context.device(), cache, 1, &info, nullptr, &pipeline),
            "vkCreateGraphicsPipelines");
        !ok) {
        return ok.error();
    }
    return vulkan::UniqueHandle<VkPipeline>(context.device(), pipeline);
}

}  // namespace

namespace {

// The Vulkan stage of each pack stage, in pipeline order.
constexpr std::array<std::pair<Stage, VkShaderStageFlagBits>, 5> kPipelineStages = {{
    {Stage::Vertex, VK_SHADER_STAGE_VERTEX_BIT},
    {Stage::Hull, VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT},
    {Stage::Domain, VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT},
    {Stage::Geometry, VK_SHADER_STAGE_GEOMETRY_BIT},
    {Stage::Fragment, VK_SHADER_STAGE_FRAGMENT_BIT},
}};

}  // namespace

Result<VariantPipeline> VariantPipeline::create(vulkan::VulkanContext& context,
                                                const reader::VariantView& variant,
                                                const pack::PackRenderState& resolvedState,
                                                const PipelineTarget& target,
                                                VkPipelineCache cache) {
    VariantPipeline result;
    result.mDescription = variant.describe();
    std::vector<std::pair<VkShaderStageFlagBits, reader::ProgramView>> programs;
    for (const auto& [stage, vulkanStage] : kPipelineStages) {
        if (std::optional<reader::ProgramView> program = variant.program(stage)) {
            programs.emplace_back(vulkanStage, *program);
        }
    }
    if (!variant.program(Stage::Vertex) || !variant.program(Stage::Fragment)) {
        return makeError(ErrorCode::InvalidInput,
                         result.mDescription + ": needs a vertex and a fragment program");
    }
    if (variant.program(Stage::Hull).has_value() != variant.program(Stage::Domain).has_value()) {
        return makeError(ErrorCode::InvalidInput,
                         result.mDescription + ": needs both a hull and a domain program");
    }
    std::vector<pack::ProgramReflection> reflections;
    for (const auto& [vulkanStage, program] : programs) reflections.push_back(program.reflection());
    std::vector<StageReflection> stageReflections;
    for (size_t i = 0; i < programs.size(); ++i) {
        stageReflections.push_back({programs[i].first, &reflections[i]});
    }
    auto slots = collectDescriptorSlots(stageReflections);
    if (!slots) return withContext(result.mDescription, slots.error());
    result.mSlots = std::move(*slots);
    auto vertexInput = vertexInputLayout(reflections.front().vertexInputs);
    if (!vertexInput) return withContext(result.mDescription, vertexInput.error());

    std::vector<vulkan::UniqueHandle<VkShaderModule>> modules;
    std::vector<ShaderStage> stages;
    for (const auto& [vulkanStage, program] : programs) {
        auto spirv = program.spirv();
        if (!spirv) return withContext(result.mDescription, spirv.error());
        auto module = createShaderModule(context, *spirv, program.describe());
        if (!module) return withContext(result.mDescription, module.error());
        stages.push_back({vulkanStage, module->get(), std::string(program.entryPoint())});
        modules.push_back(std::move(*module));
    }
    auto setLayouts = createSetLayouts(context, result.mSlots);
    if (!setLayouts) return withContext(result.mDescription, setLayouts.error());
    result.mSetLayouts = std::move(*setLayouts);

    auto layout = createPipelineLayout(context, result.mSetLayouts);
    if (!layout) return withContext(result.mDescription, layout.error());
    result.mLayout = std::move(*layout);
    auto pipeline =
        createGraphicsPipeline(context, stages, *vertexInput, result.mLayout.get(),
                               toVulkan(resolvedState, target.hasStencil), target, cache);
    if (!pipeline) return withContext(result.mDescription, pipeline.error());
    result.mPipeline = std::move(*pipeline);
    context.nameObject(result.mPipeline, result.mDescription);
    return result;
}

}  // namespace varc::render
