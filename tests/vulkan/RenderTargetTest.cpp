// SPDX-License-Identifier: Apache-2.0
// RenderTarget on lavapipe: draws into LDR, sRGB and HDR targets and reads exact pixels back.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "VulkanTestSupport.h"
#include "varc/image/Png.h"
#include "varc/vulkan/Buffer.h"
#include "varc/vulkan/RenderTarget.h"
#include "varc/vulkan/ShaderModule.h"

namespace varc::render {

// Names parameterized tests' formats in test output and CTest names.
void PrintTo(vulkan::ColorFormat format, std::ostream* out) { *out << toString(format); }

namespace {

struct Vertex {
    std::array<float, 3> position;  // clip space
    std::array<float, 4> color;
};

using Color = std::array<float, 4>;
using Rgba8 = std::array<uint8_t, 4>;

// A triangle around the centre of the target at depth |z|; it misses every corner.
std::vector<Vertex> centreTriangle(float z, Color color, float dx = 0.0f) {
    return {{{-0.5f + dx, -0.5f, z}, color},
            {{0.5f + dx, -0.5f, z}, color},
            {{0.0f + dx, 0.5f, z}, color}};
}

class RenderTargetTest : public testing::VulkanTest {
protected:
    void SetUp() override {
        VulkanTest::SetUp();
        if (HasFatalFailure()) return;
        Result<vulkan::UniqueHandle<VkShaderModule>> vertex =
            loadShaderModule(context(), testing::spirvPath("triangle.vert"));
        ASSERT_TRUE(vertex.ok()) << vertex.error().detail;
        mVertex = std::move(*vertex);
        Result<vulkan::UniqueHandle<VkShaderModule>> fragment =
            loadShaderModule(context(), testing::spirvPath("flat.frag"));
        ASSERT_TRUE(fragment.ok()) << fragment.error().detail;
        mFragment = std::move(*fragment);
        Result<vulkan::UniqueHandle<VkPipelineLayout>> layout =
            testing::createPipelineLayout(context(), VK_NULL_HANDLE, 0);
        ASSERT_TRUE(layout.ok()) << layout.error().detail;
        mLayout = std::move(*layout);
    }

    void TearDown() override {
        mPipeline.reset();
        mLayout.reset();
        mFragment.reset();
        mVertex.reset();
        VulkanTest::TearDown();
    }

    vulkan::RenderTarget makeTarget(vulkan::ColorFormat format, Color clear, uint32_t size = 64) {
        vulkan::RenderTargetDesc desc;
        desc.width = size;
        desc.height = size;
        desc.color = format;
        desc.clearColor = clear;
        Result<vulkan::RenderTarget> target = vulkan::RenderTarget::create(context(), desc);
        VARC_CHECK(target.ok()) << target.error().detail;
        return std::move(*target);
    }

    // Draws |vertices| (a triangle list) into |target| in one render pass with |op|.
    void draw(vulkan::RenderTarget& target, std::span<const Vertex> vertices, vulkan::LoadOp op,
              bool depthTest = false) {
        if (!mPipeline || depthTest != mPipelineDepthTest) {
            testing::PipelineDesc desc;
            desc.vertex = mVertex.get();
            desc.fragment = mFragment.get();
            desc.layout = mLayout.get();
            desc.renderPass = target.renderPass(vulkan::LoadOp::Clear);
            desc.bindings = {{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX}};
            desc.attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
                               {1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(Vertex, color)}};
            desc.depthTest = depthTest;
            Result<vulkan::UniqueHandle<VkPipeline>> pipeline =
                testing::createPipeline(context(), desc);
            ASSERT_TRUE(pipeline.ok()) << pipeline.error().detail;
            mPipeline = std::move(*pipeline);
            mPipelineDepthTest = depthTest;
        }
        Result<vulkan::Buffer> buffer = vulkan::Buffer::createWithData(
            context(), std::as_bytes(vertices), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "vertices");
        ASSERT_TRUE(buffer.ok()) << buffer.error().detail;
        Status drawn = context().submitAndWait([&](VkCommandBuffer commands) {
            target.begin(commands, op);
            vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.get());
            VkViewport viewport = target.viewport();
            VkRect2D scissor = target.area();
            vkCmdSetViewport(commands, 0, 1, &viewport);
            vkCmdSetScissor(commands, 0, 1, &scissor);
            VkBuffer handle = buffer->handle();
            VkDeviceSize offset = 0;
            vkCmdBindVertexBuffers(commands, 0, 1, &handle, &offset);
            vkCmdDraw(commands, static_cast<uint32_t>(vertices.size()), 1, 0, 0);
            target.end(commands);
        });
        ASSERT_TRUE(drawn.ok()) << drawn.error().detail;
    }

    image::Image readback(const vulkan::RenderTarget& target) {
        Result<image::Image> image = target.readback(context());
        VARC_CHECK(image.ok()) << image.error().detail;
        return std::move(*image);
    }

    vulkan::UniqueHandle<VkShaderModule> mVertex;
    vulkan::UniqueHandle<VkShaderModule> mFragment;
    vulkan::UniqueHandle<VkPipelineLayout> mLayout;
    vulkan::UniqueHandle<VkPipeline> mPipeline;
    bool mPipelineDepthTest = false;
};

TEST_F(RenderTargetTest, DrawsATriangleIntoAnLdrTarget) {
    // 0.2, 0.4, 0.6 * 255 = 51, 102, 153; the triangle's 0.25 * 255 = 63.75 rounds to 64.
    vulkan::RenderTarget target =
        makeTarget(vulkan::ColorFormat::Rgba8Unorm, {0.2f, 0.4f, 0.6f, 1.0f});
    ASSERT_NO_FATAL_FAILURE(
        draw(target, centreTriangle(0.5f, {1.0f, 0.0f, 0.25f, 1.0f}), vulkan::LoadOp::Clear));
    image::Image image = readback(target);
    ASSERT_EQ(image.format(), image::PixelFormat::Rgba8);
    ASSERT_EQ(image.width(), 64u);
    EXPECT_EQ(image.pixel8(32, 32), (Rgba8{255, 0, 64, 255}));
    EXPECT_EQ(image.pixel8(0, 0), (Rgba8{51, 102, 153, 255}));
    EXPECT_EQ(image.pixel8(63, 63), (Rgba8{51, 102, 153, 255}));
}

class HdrRenderTargetTest : public RenderTargetTest,
                            public ::testing::WithParamInterface<vulkan::ColorFormat> {};

TEST_P(HdrRenderTargetTest, KeepsValuesOutsideZeroToOneExactly) {
    // Every value is exact in binary16, so both float formats must return them unchanged.
    vulkan::RenderTarget target = makeTarget(GetParam(), {0.5f, -2.0f, 1000.0f, 1.0f});
    ASSERT_NO_FATAL_FAILURE(
        draw(target, centreTriangle(0.5f, {2.5f, 0.125f, 16.0f, 0.75f}), vulkan::LoadOp::Clear));
    image::Image image = readback(target);
    ASSERT_EQ(image.format(), image::PixelFormat::RgbaFloat);
    EXPECT_EQ(image.pixelFloat(32, 32), (Color{2.5f, 0.125f, 16.0f, 0.75f}));
    EXPECT_EQ(image.pixelFloat(0, 0), (Color{0.5f, -2.0f, 1000.0f, 1.0f}));
}

INSTANTIATE_TEST_SUITE_P(Formats, HdrRenderTargetTest,
                         ::testing::Values(vulkan::ColorFormat::Rgba16Float,
                                           vulkan::ColorFormat::Rgba32Float),
                         [](const ::testing::TestParamInfo<vulkan::ColorFormat>& format) {
                             return std::string(toString(format.param));
                         });

TEST_F(RenderTargetTest, SrgbTargetStoresEncodedValues) {
    // Linear 0.5 encodes to 0.7354 (187.5); Vulkan allows +-1 in the conversion.
    vulkan::RenderTarget target =
        makeTarget(vulkan::ColorFormat::Rgba8Srgb, {0.5f, 0.0f, 1.0f, 1.0f}, 16);
    image::Image image = readback(target);
    Rgba8 corner = image.pixel8(0, 0);
    EXPECT_NEAR(corner[0], 188, 1);
    EXPECT_EQ(corner[1], 0);
    EXPECT_EQ(corner[2], 255);
    EXPECT_EQ(corner[3], 255);
}

TEST_F(RenderTargetTest, DepthTestKeepsTheNearerTriangle) {
    std::vector<Vertex> vertices = centreTriangle(0.2f, {1.0f, 0.0f, 0.0f, 1.0f});
    std::vector<Vertex> far = centreTriangle(0.8f, {0.0f, 1.0f, 0.0f, 1.0f});
    vertices.insert(vertices.end(), far.begin(), far.end());
    vulkan::RenderTarget target =
        makeTarget(vulkan::ColorFormat::Rgba8Unorm, {0.0f, 0.0f, 0.0f, 1.0f});
    EXPECT_NE(target.depthStencilFormat(), VK_FORMAT_UNDEFINED);
    ASSERT_NO_FATAL_FAILURE(draw(target, vertices, vulkan::LoadOp::Clear, /*depthTest=*/true));
    EXPECT_EQ(readback(target).pixel8(32, 32), (Rgba8{255, 0, 0, 255}));
}

TEST_F(RenderTargetTest, ExtraAttachmentsClearToTheirOwnColours) {
    vulkan::RenderTargetDesc desc;
    desc.width = desc.height = 8;
    desc.color = vulkan::ColorFormat::Rgba8Unorm;
    desc.extraColors = {vulkan::ColorFormat::Rgba8Unorm, vulkan::ColorFormat::Rgba16Float,
                        vulkan::ColorFormat::Rgba8Unorm};
    desc.extraClearColors = {{1.0f, 0.0f, 0.0f, 1.0f}, {0.5f, -2.0f, 3.0f, 1.0f}};  // the third: 0
    desc.clearColor = {0.0f, 0.0f, 1.0f, 1.0f};
    Result<vulkan::RenderTarget> target = vulkan::RenderTarget::create(context(), desc);
    ASSERT_TRUE(target) << target.error().detail;
    EXPECT_EQ(target->attachmentFormat(2), vulkan::ColorFormat::Rgba16Float);
    EXPECT_EQ(target->readback(context(), 0)->pixel8(3, 3), (Rgba8{0, 0, 255, 255}));
    EXPECT_EQ(target->readback(context(), 1)->pixel8(3, 3), (Rgba8{255, 0, 0, 255}));
    EXPECT_EQ(target->readback(context(), 2)->pixelFloat(3, 3), (Color{0.5f, -2.0f, 3.0f, 1.0f}));
    EXPECT_EQ(target->readback(context(), 3)->pixel8(3, 3), (Rgba8{0, 0, 0, 0}));
}

TEST_F(RenderTargetTest, SampledDepthHasADepthOnlyView) {
    vulkan::RenderTargetDesc desc;
    desc.width = desc.height = 8;
    Result<vulkan::RenderTarget> plain = vulkan::RenderTarget::create(context(), desc);
    ASSERT_TRUE(plain) << plain.error().detail;
    EXPECT_EQ(plain->depthSampleView(), VK_NULL_HANDLE);
    desc.sampledDepth = true;
    Result<vulkan::RenderTarget> sampled = vulkan::RenderTarget::create(context(), desc);
    ASSERT_TRUE(sampled) << sampled.error().detail;
    EXPECT_NE(sampled->depthSampleView(), VK_NULL_HANDLE);
    EXPECT_NE(sampled->depthSampleView(), sampled->depthView());
    EXPECT_NE(sampled->depthImage(), VK_NULL_HANDLE);
}

TEST_F(RenderTargetTest, LoadPassKeepsEarlierContents) {
    vulkan::RenderTarget target =
        makeTarget(vulkan::ColorFormat::Rgba8Unorm, {0.0f, 0.0f, 0.0f, 1.0f});
    ASSERT_NO_FATAL_FAILURE(draw(target, centreTriangle(0.5f, {1.0f, 0.0f, 0.0f, 1.0f}, -0.45f),
                                 vulkan::LoadOp::Clear));
    ASSERT_NO_FATAL_FAILURE(
        draw(target, centreTriangle(0.5f, {0.0f, 0.0f, 1.0f, 1.0f}, 0.45f), vulkan::LoadOp::Load));
    image::Image image = readback(target);
    EXPECT_EQ(image.pixel8(18, 32), (Rgba8{255, 0, 0, 255}));  // left triangle, first pass
    EXPECT_EQ(image.pixel8(46, 32), (Rgba8{0, 0, 255, 255}));  // right triangle, second pass
    EXPECT_EQ(image.pixel8(0, 0), (Rgba8{0, 0, 0, 255}));
}

TEST_F(RenderTargetTest, ReadbackWritesAPngThatReadsBackEqual) {
    vulkan::RenderTarget target =
        makeTarget(vulkan::ColorFormat::Rgba8Unorm, {0.2f, 0.4f, 0.6f, 1.0f});
    ASSERT_NO_FATAL_FAILURE(
        draw(target, centreTriangle(0.5f, {1.0f, 0.0f, 0.25f, 1.0f}), vulkan::LoadOp::Clear));
    image::Image image = readback(target);
    std::string path = ::testing::TempDir() + "varc_render_roundtrip.png";
    ASSERT_TRUE(writePng(path, image).ok());
    Result<image::Image> loaded = image::readPng(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().detail;
    EXPECT_EQ(loaded->width(), image.width());
    EXPECT_TRUE(std::equal(image.bytes().begin(), image.bytes().end(), loaded->bytes().begin()));
}

TEST_F(RenderTargetTest, OversizedTargetIsUnsupported) {
    vulkan::RenderTargetDesc desc;
    desc.width = context().properties().limits.maxFramebufferWidth + 1;
    desc.height = 4;
    Result<vulkan::RenderTarget> target = vulkan::RenderTarget::create(context(), desc);
    ASSERT_FALSE(target.ok());
    EXPECT_EQ(target.error().code, ErrorCode::Unsupported);
}

TEST_F(RenderTargetTest, ShaderFilesAreCheckedBeforeUse) {
    Result<vulkan::UniqueHandle<VkShaderModule>> missing =
        loadShaderModule(context(), testing::spirvPath("no-such-shader"));
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, ErrorCode::IoError);

    std::string path = ::testing::TempDir() + "varc_not_spirv.spv";
    ASSERT_TRUE(writePng(path, image::Image(1, 1, image::PixelFormat::Rgba8))
                    .ok());  // any non-SPIR-V bytes
    Result<std::vector<uint32_t>> words = vulkan::readSpirvFile(path);
    ASSERT_FALSE(words.ok());
    EXPECT_EQ(words.error().code, ErrorCode::InvalidInput);
    std::vector<uint32_t> garbage{1, 2, 3};
    EXPECT_EQ(createShaderModule(context(), garbage).error().code, ErrorCode::InvalidInput);
}

}  // namespace
}  // namespace varc::render
