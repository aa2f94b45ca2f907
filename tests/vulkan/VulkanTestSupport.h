// SPDX-License-Identifier: Apache-2.0
// Shared helpers for the lavapipe tests: a strict-validation fixture and a minimal pipeline.
#pragma once

#include <gtest/gtest.h>
#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "varc/core/Result.h"
#include "varc/runtime/vulkan/UniqueHandle.h"
#include "varc/runtime/vulkan/VulkanContext.h"

namespace varc::runtime::testing {

// Path of a test shader compiled at build time, e.g. spirvPath("flat.frag").
std::string spirvPath(const std::string& shaderName);

// Creates a context with validation on; every validation message fails the current test unless
// expectMessages() is set, and TearDown asserts that none were recorded.
class VulkanTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;

    VulkanContext& context() { return *mContext; }
    // While true, validation messages are recorded but do not fail the test.
    void expectMessages(bool expected) { mExpectMessages = expected; }

    // Declared first so it is destroyed last; tests keep their Vulkan objects in locals.
    std::optional<VulkanContext> mContext;
    bool mExpectMessages = false;
};

struct PipelineDesc {
    VkShaderModule vertex = VK_NULL_HANDLE;
    VkShaderModule fragment = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkRenderPass renderPass = VK_NULL_HANDLE;
    std::vector<VkVertexInputBindingDescription> bindings;
    std::vector<VkVertexInputAttributeDescription> attributes;
    bool depthTest = false;  // LESS test and depth writes
};

// A triangle-list pipeline with dynamic viewport and scissor, no culling and no blending.
Result<UniqueHandle<VkPipeline>> createPipeline(const VulkanContext& context,
                                                const PipelineDesc& desc);

// A layout with an optional single set layout and |pushConstantBytes| of fragment push
// constants (none when 0).
Result<UniqueHandle<VkPipelineLayout>> createPipelineLayout(const VulkanContext& context,
                                                            VkDescriptorSetLayout setLayout,
                                                            uint32_t pushConstantBytes);

// Set 0 holding one combined image sampler at binding 0 for the fragment stage.
struct TextureBinding {
    UniqueHandle<VkDescriptorSetLayout> layout;
    UniqueHandle<VkDescriptorPool> pool;
    VkDescriptorSet set = VK_NULL_HANDLE;
};
Result<TextureBinding> bindTexture(const VulkanContext& context, VkImageView view,
                                   VkSampler sampler);

}  // namespace varc::runtime::testing
