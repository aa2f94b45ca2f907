// SPDX-License-Identifier: Apache-2.0
// Shared helpers for the lavapipe tests: a strict-validation fixture, fixtures for the renderers
// on the library pack, image measures and a minimal pipeline.
#pragma once

#include <gtest/gtest.h>
#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "varc/core/Result.h"
#include "varc/image/Image.h"
#include "varc/reader/Pack.h"
#include "varc/render/ForwardRenderer.h"
#include "varc/vulkan/UniqueHandle.h"
#include "varc/vulkan/VulkanContext.h"

namespace varc::render::testing {

// Path of a test shader compiled at build time, e.g. spirvPath("flat.frag").
std::string spirvPath(const std::string& shaderName);

// Creates a context with validation on; every validation message fails the current test unless
// expectMessages() is set, and TearDown asserts that none were recorded.
class VulkanTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;

    vulkan::VulkanContext& context() { return *mContext; }
    // While true, validation messages are recorded but do not fail the test.
    void expectMessages(bool expected) { mExpectMessages = expected; }
    // Messages with this id (e.g. "UNASSIGNED-CoreValidation-Shader-OutputNotConsumed") do not
    // fail the test; every other message still does.
    void tolerate(std::string idName) { mTolerated.insert(std::move(idName)); }

    // Declared first so it is destroyed last; tests keep their Vulkan objects in locals.
    std::optional<vulkan::VulkanContext> mContext;
    bool mExpectMessages = false;
    std::set<std::string> mTolerated;
    size_t mToleratedCount = 0;
};

// A VulkanTest that also opens the library pack, which the vulkan.build_packs test builds from
// ../shared/fixtures and shaders/; a pack that does not open fails the test.
class PackTest : public VulkanTest {
protected:
    void SetUp() override;

    std::optional<reader::Pack> mPack;
};

// The frame in |rendered|, or an empty frame after failing the current test with the error.
RenderedFrame frameOf(Result<RenderedFrame> rendered);

// A PackTest with a |Renderer| (ForwardRenderer, DeferredRenderer, SinglePassRenderer) created on
// the library pack; a renderer that cannot be created fails the test. The renderer is destroyed
// before the context.
template <typename Renderer>
class RendererTest : public PackTest {
protected:
    void SetUp() override {
        PackTest::SetUp();
        if (HasFatalFailure()) return;
        auto renderer = Renderer::create(context(), {&*mPack});
        ASSERT_TRUE(renderer) << renderer.error().detail;
        mRenderer.emplace(std::move(*renderer));
    }
    void TearDown() override {
        mRenderer.reset();
        PackTest::TearDown();
    }

    // The renderer's frame of |scene|; a render error fails the test and gives an empty frame.
    RenderedFrame render(const scene::Scene& scene) { return frameOf(mRenderer->render(scene)); }

    std::optional<Renderer> mRenderer;
};

// The paths of the scene files (*.json) in VARC_TEST_SCENE_DIR/|folder|, e.g. "forward".
std::vector<std::string> sceneFiles(const std::string& folder);
// The path of scene |name| in tests/scenes/|folder|.
std::string sceneFile(const std::string& folder, const std::string& name);

// The sum of R, G and B over all pixels (8-bit channels as value / 255).
float rgbSum(const image::Image& image);

// The largest R, G or B difference between two images of one size (8-bit channels as value /
// 255, so an Rgba8 and a float image compare too).
float maxRgbDifference(const image::Image& a, const image::Image& b);

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
Result<vulkan::UniqueHandle<VkPipeline>> createPipeline(const vulkan::VulkanContext& context,
                                                        const PipelineDesc& desc);

// A layout with an optional single set layout and |pushConstantBytes| of fragment push
// constants (none when 0).
Result<vulkan::UniqueHandle<VkPipelineLayout>> createPipelineLayout(
    const vulkan::VulkanContext& context, VkDescriptorSetLayout setLayout,
    uint32_t pushConstantBytes);

// Set 0 holding one combined image sampler at binding 0 for the fragment stage.
struct TextureBinding {
    vulkan::UniqueHandle<VkDescriptorSetLayout> layout;
    vulkan::UniqueHandle<VkDescriptorPool> pool;
    VkDescriptorSet set = VK_NULL_HANDLE;
};
Result<TextureBinding> bindTexture(const vulkan::VulkanContext& context, VkImageView view,
                                   VkSampler sampler);

}  // namespace varc::render::testing
