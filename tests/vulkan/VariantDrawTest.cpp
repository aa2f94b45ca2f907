// SPDX-License-Identifier: Apache-2.0
// Every variant of every pass in the test packs (the seed fixtures and varc's shader library,
// built by the CTest fixture `vulkan.build_packs`) gets a pipeline and a draw on lavapipe: no
// validation message, no NaN or infinity in the float target, and samples that pass the depth
// and stencil tests (an occlusion query, so coverage does not depend on what the shader outputs).
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "VulkanTestSupport.h"
#include "varc/reader/Pack.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ProgramView.h"
#include "varc/reader/ShaderView.h"
#include "varc/render/DrawResources.h"
#include "varc/render/RenderStateResolver.h"
#include "varc/render/VariantPipeline.h"
#include "varc/render/VertexLayout.h"
#include "varc/vulkan/Buffer.h"
#include "varc/vulkan/CheckVk.h"
#include "varc/vulkan/RenderTarget.h"
#include "varc/vulkan/Sampler.h"
#include "varc/vulkan/Texture.h"

namespace varc::render {
namespace {

// A quad covering the middle of clip space at depth 0.5 (identity matrices), in both windings so
// that it shows under Cull Back, Front and Off alike.
std::vector<MeshVertex> doubleSidedQuad() {
    auto vertex = [](float x, float y) {
        return MeshVertex{{x, y, 0.5f},
                          {0, 0, -1},
                          {1, 0, 0, 1},
                          {x * 0.5f + 0.5f, y * 0.5f + 0.5f},
                          {1, 1, 1, 1}};
    };
    MeshVertex a = vertex(-0.8f, -0.8f), b = vertex(0.8f, -0.8f), c = vertex(0.8f, 0.8f),
               d = vertex(-0.8f, 0.8f);
    return {a, b, c, a, c, d, a, c, b, a, d, c};
}

// Plausible non-zero values for the built-ins the forward, deferred and single-pass shaders read,
// so light and ambient terms are exercised (SHADER_ABI.md §4).
ShaderValues drawValues() {
    ShaderValues values;
    glm::mat4 identity(1.0f);
    for (const char* name :
         {"unity_ObjectToWorld", "unity_WorldToObject", "unity_MatrixVP", "unity_MatrixV",
          "unity_MatrixInvV", "glstate_matrix_projection", "unity_CameraToWorld",
          "unity_WorldToCamera", "unity_WorldToLight", "varc_ModelViewProjectionMatrix",
          "varc_ModelViewMatrix", "varc_ProjectionMatrix", "_Object2World", "_World2Object"}) {
        values.set(name, identity);
    }
    values.set("_WorldSpaceCameraPos", glm::vec4(0, 0, -2, 1));
    values.set("_WorldSpaceLightPos0", glm::vec4(0.3f, 0.8f, -0.5f, 0.0f));
    values.set("_LightColor0", glm::vec4(1, 0.9f, 0.8f, 1));
    values.set("_LightColor", glm::vec4(1, 0.9f, 0.8f, 1));
    values.set("_LightPos", glm::vec4(0, 0, -1, 0.1f));
    values.set("_LightDir", glm::vec4(0, 0, 1, 0));
    values.set("_ProjectionParams", glm::vec4(1, 0.1f, 100, 0.01f));
    values.set("_ZBufferParams", glm::vec4(-999, 1000, -9.99f, 10));
    values.set("_Tint", glm::vec4(1, 1, 1, 1));
    values.set("_Color", glm::vec4(1, 1, 1, 1));
    values.set("unity_SHAr", glm::vec4(0, 0, 0, 0.2f));
    values.set("unity_SHAg", glm::vec4(0, 0, 0, 0.2f));
    values.set("unity_SHAb", glm::vec4(0, 0, 0, 0.2f));
    values.set("unity_SHC", glm::vec4(0, 0, 0, 1));
    values.set("_Smoothness", 0.5f);
    values.set("_TessellationUniform", 1.0f);  // a tessellation factor of 0 would cull every patch
    values.set("unity_LightIndicesOffsetAndCount", glm::vec4(0, 1, 0, 0));
    std::vector<glm::vec4> lightColors(16, glm::vec4(1, 1, 1, 0));
    values.setArray("_VisibleLightColors", lightColors);
    // GPU instancing (SHADER_ABI.md §4.10): per-instance matrices and colours.
    std::vector<glm::mat4> matrices(2, identity);
    values.setArray("unity_ObjectToWorldArray", matrices);
    values.setArray("unity_WorldToObjectArray", matrices);
    std::vector<glm::vec4> colors(2, glm::vec4(1.0f));
    values.setArray("_ColorArray", colors);
    return values;
}

class VariantDrawTest : public testing::VulkanTest {
protected:
    void SetUp() override {
        VulkanTest::SetUp();
        if (HasFatalFailure()) return;
        image::Image white(1, 1, image::PixelFormat::Rgba8);
        white.setPixel8(0, 0, {255, 255, 255, 255});
        auto white2D = vulkan::Texture::create2D(context(), white);
        ASSERT_TRUE(white2D) << white2D.error().detail;
        mWhite2D.emplace(std::move(*white2D));
        std::vector<image::Image> faces(6, white);
        auto whiteCube = vulkan::Texture::createCube(context(), faces);
        ASSERT_TRUE(whiteCube) << whiteCube.error().detail;
        mWhiteCube.emplace(std::move(*whiteCube));
        std::vector<image::Image> slices(2, white);
        auto white3D = vulkan::Texture::createVolume(context(), slices);
        ASSERT_TRUE(white3D) << white3D.error().detail;
        mWhite3D.emplace(std::move(*white3D));
        auto sampler = createSampler(context());
        ASSERT_TRUE(sampler) << sampler.error().detail;
        mSampler = std::move(*sampler);
    }

    void TearDown() override {
        mWhite2D.reset();
        mWhiteCube.reset();
        mWhite3D.reset();
        mSampler.reset();
        VulkanTest::TearDown();
    }

    void drawEveryVariant(const std::string& packPath, size_t& drawn, StageMask& stagesSeen);

    TextureLookup whiteTextures() const {
        return [this](std::string_view, pack::ResourceDim dim) -> std::optional<TextureBinding> {
            const vulkan::Texture& texture = dim == pack::ResourceDim::Cube    ? *mWhiteCube
                                             : dim == pack::ResourceDim::Dim3D ? *mWhite3D
                                                                               : *mWhite2D;
            return TextureBinding{texture.view(), mSampler.get()};
        };
    }

    // Declared after the context (in VulkanTest) so they are destroyed first.
    std::optional<vulkan::Texture> mWhite2D, mWhiteCube, mWhite3D;
    vulkan::UniqueHandle<VkSampler> mSampler;
};

struct DrawOutcome {
    uint64_t samplesPassed = 0;
    bool finite = true;
};

// Draws every variant of the pack at |packPath| (see the file comment); |drawn| counts them,
// |stagesSeen| ORs the stages of every variant drawn.
void VariantDrawTest::drawEveryVariant(const std::string& packPath, size_t& drawn,
                                       StageMask& stagesSeen) {
    auto pack = reader::Pack::open(packPath);
    ASSERT_TRUE(pack) << pack.error().detail;

    vulkan::RenderTargetDesc desc;
    desc.width = desc.height = 32;
    desc.color = vulkan::ColorFormat::Rgba32Float;
    desc.clearColor = {0.25f, 0.5f, 0.75f, 1.0f};
    auto single = vulkan::RenderTarget::create(context(), desc);
    ASSERT_TRUE(single) << single.error().detail;
    desc.extraColors.assign(3, vulkan::ColorFormat::Rgba32Float);  // a G-buffer's four outputs
    auto gbuffer = vulkan::RenderTarget::create(context(), desc);
    ASSERT_TRUE(gbuffer) << gbuffer.error().detail;
    std::vector<MeshVertex> quad = doubleSidedQuad();
    auto vertices = vulkan::Buffer::createWithData(context(), std::as_bytes(std::span(quad)),
                                                   VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    ASSERT_TRUE(vertices) << vertices.error().detail;
    auto resources = DrawResources::create(context(), 1u << 20, 64);
    ASSERT_TRUE(resources) << resources.error().detail;
    VkQueryPoolCreateInfo queryInfo{};
    queryInfo.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
    queryInfo.queryType = VK_QUERY_TYPE_OCCLUSION;
    queryInfo.queryCount = 1;
    VkQueryPool rawPool = VK_NULL_HANDLE;
    ASSERT_TRUE(vulkan::checkVk(
        vkCreateQueryPool(context().device(), &queryInfo, nullptr, &rawPool), "vkCreateQueryPool"));
    vulkan::UniqueHandle<VkQueryPool> queries(context().device(), rawPool);

    ShaderValues values = drawValues();
    const ShaderValues* layers[] = {&values};
    for (size_t s = 0; s < pack->shaderCount(); ++s) {
        reader::ShaderView shader = pack->shader(s);
        for (size_t p = 0; p < shader.passCount(); ++p) {
            reader::PassView pass = *shader.pass(p);
            pack::PackRenderState state = resolveRenderState(pass.renderState(), values);
            for (size_t v = 0; v < pass.variantCount(); ++v) {
                reader::VariantView variant = pass.variant(v);
                SCOPED_TRACE(variant.describe());
                size_t outputs = variant.program(Stage::Fragment)->reflection().outputs.size();
                const vulkan::RenderTarget* target = outputs > 1 ? &*gbuffer : &*single;
                auto pipeline = VariantPipeline::create(context(), variant, state,
                                                        {target->renderPass(vulkan::LoadOp::Clear),
                                                         true, target->colorAttachmentCount()});
                ASSERT_TRUE(pipeline) << pipeline.error().detail;
                Status recorded = Ok{};
                Status submitted = context().submitAndWait([&](VkCommandBuffer commands) {
                    vkCmdResetQueryPool(commands, queries.get(), 0, 1);
                    target->begin(commands, vulkan::LoadOp::Clear);
                    VkViewport viewport = target->viewport();
                    VkRect2D area = target->area();
                    vkCmdSetViewport(commands, 0, 1, &viewport);
                    vkCmdSetScissor(commands, 0, 1, &area);
                    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS,
                                      pipeline->pipeline());
                    recorded = resources->bind(commands, *pipeline, layers, whiteTextures());
                    VkBuffer buffer = vertices->handle();
                    VkDeviceSize offset = 0;
                    vkCmdBindVertexBuffers(commands, 0, 1, &buffer, &offset);
                    vkCmdBeginQuery(commands, queries.get(), 0, 0);
                    if (recorded) vkCmdDraw(commands, static_cast<uint32_t>(quad.size()), 1, 0, 0);
                    vkCmdEndQuery(commands, queries.get(), 0);
                    target->end(commands);
                });
                ASSERT_TRUE(recorded) << recorded.error().detail;
                ASSERT_TRUE(submitted) << submitted.error().detail;
                ASSERT_TRUE(resources->reset());
                DrawOutcome outcome;
                ASSERT_TRUE(vulkan::checkVk(
                    vkGetQueryPoolResults(context().device(), queries.get(), 0, 1, sizeof(uint64_t),
                                          &outcome.samplesPassed, sizeof(uint64_t),
                                          VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                    "vkGetQueryPoolResults"));
                auto image = target->readback(context());
                ASSERT_TRUE(image) << image.error().detail;
                for (float f : image->floats()) outcome.finite = outcome.finite && std::isfinite(f);
                EXPECT_GT(outcome.samplesPassed, 0u) << "no coverage";
                EXPECT_TRUE(outcome.finite) << "NaN or infinity in the output";
                for (Stage stage : kStages) {
                    if (variant.program(stage)) stagesSeen |= stageBit(stage);
                }
                ++drawn;
            }
        }
    }
}

TEST_F(VariantDrawTest, EveryVariantOfTheTestPacksDraws) {
    size_t drawn = 0;
    StageMask stages = 0;
    drawEveryVariant(VARC_TEST_PACK_DIR "/library.svpack", drawn, stages);
    // The fixtures alone have 34 variants; the library adds its own.
    EXPECT_GT(drawn, 34u);
}

// Real third-party shaders with geometry and tessellation stages (from ../shared/compat, built
// by `vulkan.build_packs`): pipelines with those stages draw on lavapipe too.
TEST_F(VariantDrawTest, GeometryAndTessellationVariantsOfRealShadersDraw) {
    // These shaders write vertex outputs their next stage does not read: legal, and a
    // performance note about the shader rather than about the runtime.
    tolerate("UNASSIGNED-CoreValidation-Shader-OutputNotConsumed");
    size_t drawn = 0;
    StageMask stages = 0;
    drawEveryVariant(VARC_TEST_PACK_DIR "/compat-stages.svpack", drawn, stages);
    EXPECT_GE(drawn, 9u);
    EXPECT_TRUE(stages & stageBit(Stage::Geometry));
    EXPECT_TRUE(stages & stageBit(Stage::Hull));
    EXPECT_TRUE(stages & stageBit(Stage::Domain));
}

}  // namespace
}  // namespace varc::render
