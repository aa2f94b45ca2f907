// SPDX-License-Identifier: Apache-2.0
// QuadDrawTest: one variant of the helpers pack drawn over a full-target quad.
#include "QuadDrawTest.h"

#include <span>
#include <utility>

#include "varc/render/RenderStateResolver.h"
#include "varc/render/VariantPipeline.h"

namespace varc::render::testing {

std::vector<MeshVertex> fullTargetQuad() {
    auto vertex = [](float x, float y) {
        return MeshVertex{{x, y, 0.5f},
                          {0, 0, 1},
                          {1, 0, 0, 1},
                          {x * 0.5f + 0.5f, y * 0.5f + 0.5f},
                          {1, 1, 1, 1}};
    };
    MeshVertex a = vertex(-1, -1), b = vertex(1, -1), c = vertex(1, 1), d = vertex(-1, 1);
    return {a, b, c, a, c, d};
}

void QuadDrawTest::SetUp() {
    VulkanTest::SetUp();
    if (HasFatalFailure()) return;
    auto pack = reader::Pack::open(VARC_TEST_PACK_DIR "/helpers.svpack");
    ASSERT_TRUE(pack) << pack.error().detail;
    mPack.emplace(std::move(*pack));
    vulkan::RenderTargetDesc desc;
    desc.width = desc.height = mSize;
    desc.color = vulkan::ColorFormat::Rgba32Float;
    auto target = vulkan::RenderTarget::create(context(), desc);
    ASSERT_TRUE(target) << target.error().detail;
    mTarget.emplace(std::move(*target));
    auto textures = BuiltinTextures::create(context());
    ASSERT_TRUE(textures) << textures.error().detail;
    mTextures.emplace(std::move(*textures));
    auto resources = DrawResources::create(context(), 1u << 20, 16);
    ASSERT_TRUE(resources) << resources.error().detail;
    mResources.emplace(std::move(*resources));
    std::vector<MeshVertex> quad = fullTargetQuad();
    auto vertices = vulkan::Buffer::createWithData(context(), std::as_bytes(std::span(quad)),
                                                   VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    ASSERT_TRUE(vertices) << vertices.error().detail;
    mQuad.emplace(std::move(*vertices));
}

void QuadDrawTest::TearDown() {
    mQuad.reset();
    mResources.reset();
    mTextures.reset();
    mTarget.reset();
    VulkanTest::TearDown();
}

image::Image QuadDrawTest::drawQuad(const reader::PassView& pass,
                                    const std::vector<std::string>& keywords,
                                    const ShaderValues& values, const TextureLookup& textures) {
    auto variant = pass.lookup(keywords, variants::SelectionPolicy::Exact);
    EXPECT_TRUE(variant) << variant.error().detail;
    if (!variant) return {};
    auto pipeline =
        VariantPipeline::create(context(), *variant, resolveRenderState(pass.renderState(), values),
                                {mTarget->renderPass(vulkan::LoadOp::Clear), true, 1});
    EXPECT_TRUE(pipeline) << pipeline.error().detail;
    if (!pipeline) return {};
    const ShaderValues* layers[] = {&values};
    Status bound = Ok{};
    Status submitted = context().submitAndWait([&](VkCommandBuffer commands) {
        mTarget->begin(commands, vulkan::LoadOp::Clear);
        VkViewport viewport = mTarget->viewport();
        VkRect2D area = mTarget->area();
        vkCmdSetViewport(commands, 0, 1, &viewport);
        vkCmdSetScissor(commands, 0, 1, &area);
        vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline->pipeline());
        bound = mResources->bind(commands, *pipeline, layers, textures);
        VkBuffer buffer = mQuad->handle();
        VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(commands, 0, 1, &buffer, &offset);
        if (bound) vkCmdDraw(commands, 6, 1, 0, 0);
        mTarget->end(commands);
    });
    EXPECT_TRUE(bound) << bound.error().detail;
    EXPECT_TRUE(submitted) << submitted.error().detail;
    EXPECT_TRUE(mResources->reset());
    auto image = mTarget->readback(context());
    EXPECT_TRUE(image) << image.error().detail;
    return image ? std::move(*image) : image::Image{};
}

void QuadDrawTest::expectPassFormula(const std::string& shader, const std::string& keyword,
                                     const ShaderValues& values, const TextureLookup& textures,
                                     const PixelFormula& formula, int channels, double absolute,
                                     double relative, double minLargest) {
    std::optional<reader::ShaderView> view = mPack->findShader(shader);
    ASSERT_TRUE(view) << shader;
    image::Image image = drawQuad(*view->pass(0), {keyword}, values, textures);
    ASSERT_EQ(image.width(), mSize) << keyword;
    FormulaComparison result = compareWithFormula(image, formula, channels, absolute, relative);
    EXPECT_LE(result.worst, 1.0) << keyword << ": worst " << result.where;
    EXPECT_GT(result.largest, minLargest) << keyword;
}

TextureLookup QuadDrawTest::whiteTextures() const {
    const BuiltinTextures& builtin = *mTextures;
    return
        [&builtin](std::string_view, pack::ResourceDim dim) { return builtin.named("white", dim); };
}

}  // namespace varc::render::testing
