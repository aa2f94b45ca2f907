// SPDX-License-Identifier: Apache-2.0
// Texture and Sampler on lavapipe: 2D, float, mipmapped and cube textures sampled exactly.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "VulkanTestSupport.h"
#include "varc/vulkan/RenderTarget.h"
#include "varc/vulkan/Sampler.h"
#include "varc/vulkan/ShaderModule.h"
#include "varc/vulkan/Texture.h"

namespace varc::render {
namespace {

using Rgba8 = std::array<uint8_t, 4>;

class TextureTest : public testing::VulkanTest {
protected:
    // Renders |fragmentShader| over the whole of a new |width| x |height| target with |texture|
    // bound through a nearest (or |filter|) sampler, pushing |lod|, and reads it back.
    image::Image render(const vulkan::Texture& texture, const std::string& fragmentShader,
                        uint32_t width, uint32_t height,
                        vulkan::ColorFormat format = vulkan::ColorFormat::Rgba8Unorm,
                        float lod = 0.0f, VkFilter filter = VK_FILTER_NEAREST) {
        vulkan::SamplerDesc samplerDesc;
        samplerDesc.filter = filter;
        samplerDesc.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        samplerDesc.addressMode = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        Result<vulkan::UniqueHandle<VkSampler>> sampler = createSampler(context(), samplerDesc);
        VARC_CHECK(sampler.ok()) << sampler.error().detail;
        Result<testing::TextureBinding> binding =
            testing::bindTexture(context(), texture.view(), sampler->get());
        VARC_CHECK(binding.ok()) << binding.error().detail;
        Result<vulkan::UniqueHandle<VkPipelineLayout>> layout = testing::createPipelineLayout(
            context(), binding->layout.get(), static_cast<uint32_t>(sizeof(float)));
        VARC_CHECK(layout.ok()) << layout.error().detail;
        Result<vulkan::UniqueHandle<VkShaderModule>> vertex =
            loadShaderModule(context(), testing::spirvPath("fullscreen.vert"));
        Result<vulkan::UniqueHandle<VkShaderModule>> fragment =
            loadShaderModule(context(), testing::spirvPath(fragmentShader));
        VARC_CHECK(vertex.ok() && fragment.ok()) << "test shaders missing";

        vulkan::RenderTargetDesc targetDesc;
        targetDesc.width = width;
        targetDesc.height = height;
        targetDesc.color = format;
        targetDesc.depthStencil = false;
        Result<vulkan::RenderTarget> target = vulkan::RenderTarget::create(context(), targetDesc);
        VARC_CHECK(target.ok()) << target.error().detail;
        testing::PipelineDesc pipelineDesc;
        pipelineDesc.vertex = vertex->get();
        pipelineDesc.fragment = fragment->get();
        pipelineDesc.layout = layout->get();
        pipelineDesc.renderPass = target->renderPass();
        Result<vulkan::UniqueHandle<VkPipeline>> pipeline =
            testing::createPipeline(context(), pipelineDesc);
        VARC_CHECK(pipeline.ok()) << pipeline.error().detail;

        Status drawn = context().submitAndWait([&](VkCommandBuffer commands) {
            target->begin(commands);
            vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline->get());
            vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, layout->get(), 0, 1,
                                    &binding->set, 0, nullptr);
            vkCmdPushConstants(commands, layout->get(), VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                               sizeof(float), &lod);
            VkViewport viewport = target->viewport();
            VkRect2D scissor = target->area();
            vkCmdSetViewport(commands, 0, 1, &viewport);
            vkCmdSetScissor(commands, 0, 1, &scissor);
            vkCmdDraw(commands, 3, 1, 0, 0);
            target->end(commands);
        });
        VARC_CHECK(drawn.ok()) << drawn.error().detail;
        Result<image::Image> image = target->readback(context());
        VARC_CHECK(image.ok()) << image.error().detail;
        return std::move(*image);
    }
};

TEST_F(TextureTest, Samples2DTexelsExactly) {
    image::Image source(2, 2, image::PixelFormat::Rgba8);
    source.setPixel8(0, 0, {255, 0, 0, 255});
    source.setPixel8(1, 0, {0, 255, 0, 255});
    source.setPixel8(0, 1, {0, 0, 255, 255});
    source.setPixel8(1, 1, {10, 20, 30, 40});
    Result<vulkan::Texture> texture = vulkan::Texture::create2D(context(), source);
    ASSERT_TRUE(texture.ok()) << texture.error().detail;
    EXPECT_EQ(texture->format(), VK_FORMAT_R8G8B8A8_UNORM);
    image::Image image = render(*texture, "texture2d.frag", 64, 64);
    EXPECT_EQ(image.pixel8(16, 16), (Rgba8{255, 0, 0, 255}));
    EXPECT_EQ(image.pixel8(48, 16), (Rgba8{0, 255, 0, 255}));
    EXPECT_EQ(image.pixel8(16, 48), (Rgba8{0, 0, 255, 255}));
    EXPECT_EQ(image.pixel8(48, 48), (Rgba8{10, 20, 30, 40}));
}

TEST_F(TextureTest, FloatTexturesKeepHdrValues) {
    image::Image source(1, 1, image::PixelFormat::RgbaFloat);
    source.setPixelFloat(0, 0, {2.5f, -1.0f, 0.125f, 1.0f});
    Result<vulkan::Texture> texture = vulkan::Texture::create2D(context(), source);
    ASSERT_TRUE(texture.ok()) << texture.error().detail;
    EXPECT_EQ(texture->format(), VK_FORMAT_R16G16B16A16_SFLOAT);
    image::Image image = render(*texture, "texture2d.frag", 8, 8, vulkan::ColorFormat::Rgba32Float);
    EXPECT_EQ(image.pixelFloat(4, 4), (std::array<float, 4>{2.5f, -1.0f, 0.125f, 1.0f}));
}

TEST_F(TextureTest, GeneratesAMipChain) {
    // Left half black, right half white: level 1 keeps the halves, level 2 averages them.
    image::Image source(4, 4, image::PixelFormat::Rgba8);
    for (uint32_t y = 0; y < 4; ++y) {
        for (uint32_t x = 0; x < 4; ++x) {
            uint8_t v = x < 2 ? 0 : 255;
            source.setPixel8(x, y, {v, v, v, 255});
        }
    }
    vulkan::TextureOptions options;
    options.mipmaps = true;
    Result<vulkan::Texture> texture = vulkan::Texture::create2D(context(), source, options);
    ASSERT_TRUE(texture.ok()) << texture.error().detail;
    EXPECT_EQ(texture->mipLevels(), 3u);
    image::Image level1 =
        render(*texture, "texture2d.frag", 8, 8, vulkan::ColorFormat::Rgba8Unorm, 1.0f);
    EXPECT_EQ(level1.pixel8(1, 4), (Rgba8{0, 0, 0, 255}));
    EXPECT_EQ(level1.pixel8(6, 4), (Rgba8{255, 255, 255, 255}));
    image::Image level2 =
        render(*texture, "texture2d.frag", 8, 8, vulkan::ColorFormat::Rgba8Unorm, 2.0f);
    Rgba8 average = level2.pixel8(4, 4);
    EXPECT_NEAR(average[0], 128, 1);
    EXPECT_EQ(average[3], 255);
}

TEST_F(TextureTest, CubeFacesFollowVulkanLayerOrder) {
    std::vector<image::Image> faces;
    for (uint8_t face = 0; face < 6; ++face) {
        image::Image image(1, 1, image::PixelFormat::Rgba8);
        image.setPixel8(
            0, 0, {static_cast<uint8_t>(40 * face), static_cast<uint8_t>(200 - face), 7, 255});
        faces.push_back(image);
    }
    Result<vulkan::Texture> texture = vulkan::Texture::createCube(context(), faces);
    ASSERT_TRUE(texture.ok()) << texture.error().detail;
    EXPECT_TRUE(texture->isCube());
    image::Image image = render(*texture, "cube.frag", 6, 1);
    for (uint32_t face = 0; face < 6; ++face) {
        EXPECT_EQ(image.pixel8(face, 0), faces[face].pixel8(0, 0)) << "face " << face;
    }
}

TEST_F(TextureTest, RejectsMismatchedCubeFaces) {
    std::vector<image::Image> faces(6, image::Image(2, 2, image::PixelFormat::Rgba8));
    faces[3] = image::Image(4, 4, image::PixelFormat::Rgba8);
    Result<vulkan::Texture> texture = vulkan::Texture::createCube(context(), faces);
    ASSERT_FALSE(texture.ok());
    EXPECT_EQ(texture.error().code, ErrorCode::InvalidInput);
    Result<vulkan::Texture> five =
        vulkan::Texture::createCube(context(), std::span(faces).first(5));
    ASSERT_FALSE(five.ok());
    EXPECT_EQ(five.error().code, ErrorCode::InvalidInput);
}

}  // namespace
}  // namespace varc::render
