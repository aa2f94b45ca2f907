// SPDX-License-Identifier: Apache-2.0
// Shared helpers for the lavapipe tests: a strict-validation fixture, fixtures for the renderers
// on the library pack, image measures and a minimal pipeline.
#include "VulkanTestSupport.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <utility>

#include "varc/vulkan/CheckVk.h"

namespace varc::render::testing {

std::string spirvPath(const std::string& shaderName) {
    return std::string(VARC_VULKAN_TEST_SPIRV_DIR) + "/" + shaderName + ".spv";
}

void VulkanTest::SetUp() {
    vulkan::ContextOptions options;
    options.enableValidation = true;
    options.applicationName = "varc_vulkan_tests";
    options.onMessage = [this](const vulkan::ValidationMessage& message) {
        if (mTolerated.count(message.idName)) {
            ++mToleratedCount;
            return;
        }
        if (!mExpectMessages) ADD_FAILURE() << "Vulkan validation: " << toString(message);
    };
    Result<vulkan::VulkanContext> created = vulkan::VulkanContext::create(options);
    ASSERT_TRUE(created.ok()) << created.error().detail;
    mContext.emplace(std::move(*created));
}

void VulkanTest::TearDown() {
    if (!mContext) return;
    EXPECT_EQ(mContext->validationMessageCount(), mToleratedCount) << mContext->validationReport();
    // Messages from device and instance destruction (e.g. leaked objects) reach onMessage.
    mContext.reset();
}

void PackTest::SetUp() {
    VulkanTest::SetUp();
    if (HasFatalFailure()) return;
    auto pack = reader::Pack::open(VARC_TEST_PACK_DIR "/library.svpack");
    ASSERT_TRUE(pack) << pack.error().detail;
    mPack.emplace(std::move(*pack));
}

RenderedFrame frameOf(Result<RenderedFrame> rendered) {
    EXPECT_TRUE(rendered) << rendered.error().detail;
    return rendered ? std::move(*rendered) : RenderedFrame{};
}

std::vector<std::string> sceneFiles(const std::string& folder) {
    std::vector<std::string> scenes;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::string(VARC_TEST_SCENE_DIR) + "/" + folder)) {
        if (entry.path().extension() == ".json") scenes.push_back(entry.path().string());
    }
    return scenes;
}

std::string sceneFile(const std::string& folder, const std::string& name) {
    return std::string(VARC_TEST_SCENE_DIR) + "/" + folder + "/" + name;
}

float rgbSum(const image::Image& image) {
    float total = 0;
    for (uint32_t y = 0; y < image.height(); ++y) {
        for (uint32_t x = 0; x < image.width(); ++x) {
            std::array<float, 4> p = image.pixelFloat(x, y);
            total += p[0] + p[1] + p[2];
        }
    }
    return total;
}

float maxRgbDifference(const image::Image& a, const image::Image& b) {
    float worst = 0;
    for (uint32_t y = 0; y < a.height(); ++y) {
        for (uint32_t x = 0; x < a.width(); ++x) {
            std::array<float, 4> pa = a.pixelFloat(x, y), pb = b.pixelFloat(x, y);
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(pa[c] - pb[c]));
        }
    }
    return worst;
}

namespace {

std::array<VkPipelineShaderStageCreateInfo, 2> shaderStages(const PipelineDesc& desc) {
    std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
    for (VkPipelineShaderStageCreateInfo& stage : stages) {
        stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
        stage.pName = "main";
    }
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = desc.vertex;
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = desc.fragment;
    return stages;
}

// The fixed-function state of a test pipeline. It points into itself, so it stays put.
struct FixedState {
    explicit FixedState(const PipelineDesc& desc) {
        vertexInput.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
        vertexInput.vertexBindingDescriptionCount = static_cast<uint32_t>(desc.bindings.size());
        vertexInput.pVertexBindingDescriptions = desc.bindings.data();
        vertexInput.vertexAttributeDescriptionCount = static_cast<uint32_t>(desc.attributes.size());
        vertexInput.pVertexAttributeDescriptions = desc.attributes.data();
        assembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
        assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
        viewport.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
        viewport.viewportCount = 1;
        viewport.scissorCount = 1;
        raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
        raster.polygonMode = VK_POLYGON_MODE_FILL;
        raster.cullMode = VK_CULL_MODE_NONE;
        raster.lineWidth = 1.0f;
        multisample.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
        multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
        depth.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
        depth.depthTestEnable = desc.depthTest ? VK_TRUE : VK_FALSE;
        depth.depthWriteEnable = desc.depthTest ? VK_TRUE : VK_FALSE;
        depth.depthCompareOp = VK_COMPARE_OP_LESS;
        blendAttachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                         VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
        blend.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
        blend.attachmentCount = 1;
        blend.pAttachments = &blendAttachment;
        dynamic.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO;
        dynamic.dynamicStateCount = static_cast<uint32_t>(dynamicStates.size());
        dynamic.pDynamicStates = dynamicStates.data();
    }
    FixedState(const FixedState&) = delete;
    FixedState& operator=(const FixedState&) = delete;

    VkPipelineVertexInputStateCreateInfo vertexInput{};
    VkPipelineInputAssemblyStateCreateInfo assembly{};
    VkPipelineViewportStateCreateInfo viewport{};
    VkPipelineRasterizationStateCreateInfo raster{};
    VkPipelineMultisampleStateCreateInfo multisample{};
    VkPipelineDepthStencilStateCreateInfo depth{};
    VkPipelineColorBlendAttachmentState blendAttachment{};
    VkPipelineColorBlendStateCreateInfo blend{};
    std::array<VkDynamicState, 2> dynamicStates{VK_DYNAMIC_STATE_VIEWPORT,
                                                VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{};
};

}  // namespace

Result<vulkan::UniqueHandle<VkPipeline>> createPipeline(const vulkan::VulkanContext& context,
                                                        const PipelineDesc& desc) {
    std::array<VkPipelineShaderStageCreateInfo, 2> stages = shaderStages(desc);
    FixedState fixed(desc);
    VkGraphicsPipelineCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
    info.stageCount = static_cast<uint32_t>(stages.size());
    info.pStages = stages.data();
    info.pVertexInputState = &fixed.vertexInput;
    info.pInputAssemblyState = &fixed.assembly;
    info.pViewportState = &fixed.viewport;
    info.pRasterizationState = &fixed.raster;
    info.pMultisampleState = &fixed.multisample;
    info.pDepthStencilState = &fixed.depth;
    info.pColorBlendState = &fixed.blend;
    info.pDynamicState = &fixed.dynamic;
    info.layout = desc.layout;
    info.renderPass = desc.renderPass;
    VkPipeline pipeline = VK_NULL_HANDLE;
    if (Status status = vulkan::checkVk(vkCreateGraphicsPipelines(context.device(), VK_NULL_HANDLE,
                                                                  1, &info, nullptr, &pipeline),
                                        "vkCreateGraphicsPipelines", CallSite::current());
        !status) {
        return status.error();
    }
    return vulkan::UniqueHandle<VkPipeline>(context.device(), pipeline);
}

Result<vulkan::UniqueHandle<VkPipelineLayout>> createPipelineLayout(
    const vulkan::VulkanContext& context, VkDescriptorSetLayout setLayout,
    uint32_t pushConstantBytes) {
    VkPushConstantRange range{VK_SHADER_STAGE_FRAGMENT_BIT, 0, pushConstantBytes};
    VkPipelineLayoutCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    info.setLayoutCount = setLayout != VK_NULL_HANDLE ? 1 : 0;
    info.pSetLayouts = &setLayout;
    info.pushConstantRangeCount = pushConstantBytes > 0 ? 1 : 0;
    info.pPushConstantRanges = &range;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    if (Status status =
            vulkan::checkVk(vkCreatePipelineLayout(context.device(), &info, nullptr, &layout),
                            "vkCreatePipelineLayout", CallSite::current());
        !status) {
        return status.error();
    }
    return vulkan::UniqueHandle<VkPipelineLayout>(context.device(), layout);
}

Result<TextureBinding> bindTexture(const vulkan::VulkanContext& context, VkImageView view,
                                   VkSampler sampler) {
    VkDevice device = context.device();
    TextureBinding binding;
    VkDescriptorSetLayoutBinding slot{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                      VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo layoutInfo{};
    layoutInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    layoutInfo.bindingCount = 1;
    layoutInfo.pBindings = &slot;
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    if (Status s =
            vulkan::checkVk(vkCreateDescriptorSetLayout(device, &layoutInfo, nullptr, &layout),
                            "vkCreateDescriptorSetLayout", CallSite::current());
        !s) {
        return s.error();
    }
    binding.layout = vulkan::UniqueHandle<VkDescriptorSetLayout>(device, layout);

    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
    VkDescriptorPoolCreateInfo poolInfo{};
    poolInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &size;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    if (Status s = vulkan::checkVk(vkCreateDescriptorPool(device, &poolInfo, nullptr, &pool),
                                   "vkCreateDescriptorPool", CallSite::current());
        !s) {
        return s.error();
    }
    binding.pool = vulkan::UniqueHandle<VkDescriptorPool>(device, pool);

    VkDescriptorSetAllocateInfo allocateInfo{};
    allocateInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    allocateInfo.descriptorPool = pool;
    allocateInfo.descriptorSetCount = 1;
    allocateInfo.pSetLayouts = &layout;
    if (Status s = vulkan::checkVk(vkAllocateDescriptorSets(device, &allocateInfo, &binding.set),
                                   "vkAllocateDescriptorSets", CallSite::current());
        !s) {
        return s.error();
    }
    VkDescriptorImageInfo imageInfo{sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet write{};
    write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    write.dstSet = binding.set;
    write.dstBinding = 0;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    write.pImageInfo = &imageInfo;
    vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
    return binding;
}

}  // namespace varc::render::testing
