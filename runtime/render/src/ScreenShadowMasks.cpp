// SPDX-License-Identifier: Apache-2.0
// ScreenShadowMasks: camera depth from the casters, then the collector per directional light.
#include "ScreenShadowMasks.h"

#include "FullScreenQuad.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ShaderView.h"
#include "varc/render/DeferredValues.h"
#include "varc/render/RenderStateResolver.h"
#include "varc/render/SceneValues.h"

namespace varc::render {

namespace {

constexpr uint32_t kCameraDepthKind = 100;  // RGBA8 + depth/stencil, as shadow maps
constexpr uint32_t kMaskKind = 101;         // one Rgba32Float attachment, no depth

constexpr VkImageAspectFlags kDepthStencil = VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
constexpr VkPipelineStageFlags kDepthStages =
    VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;

// The collector variant for a light: cascades, fit and filter.
std::vector<std::string> collectorKeywords(const scene::Light& light,
                                           const scene::DirectionalShadowSetup& setup) {
    std::vector<std::string> keywords;
    if (setup.cascades == 1) keywords.emplace_back("SHADOWS_SINGLE_CASCADE");
    if (setup.stableFit) keywords.emplace_back("SHADOWS_SPLIT_SPHERES");
    if (light.shadows == scene::ShadowType::Soft) keywords.emplace_back("SHADOWS_SOFT");
    return keywords;
}

}  // namespace

Status ScreenShadowMasks::prepare(RendererBase& renderer, const scene::Camera& camera,
                                  const std::vector<size_t>& lights) {
    if (!mNearest) {
        auto sampler = createShadowSampler(*renderer.context, "screen shadow sampler");
        if (!sampler) return sampler.error();
        mNearest = std::move(*sampler);
    }
    const bool sameSize = mDepth && mDepth->width() == camera.width &&
                          mDepth->height() == camera.height;
    bool sameLights = sameSize && mMasks.size() == lights.size();
    for (size_t light : lights) sameLights = sameLights && mMasks.count(light);
    if (sameLights) return Ok{};
    vulkan::RenderTargetDesc depth;
    depth.width = camera.width;
    depth.height = camera.height;
    depth.sampledDepth = true;
    depth.name = "camera depth texture";
    auto depthTarget = vulkan::RenderTarget::create(*renderer.context, depth);
    if (!depthTarget) return depthTarget.error();
    mDepth.emplace(std::move(*depthTarget));
    mMasks.clear();
    for (size_t light : lights) {
        vulkan::RenderTargetDesc mask;
        mask.width = camera.width;
        mask.height = camera.height;
        mask.color = vulkan::ColorFormat::Rgba32Float;
        mask.depthStencil = false;
        mask.clearColor = {1.0f, 1.0f, 1.0f, 1.0f};
        mask.name = "screen shadow mask";
        auto target = vulkan::RenderTarget::create(*renderer.context, mask);
        if (!target) return target.error();
        mMasks.emplace(light, std::move(*target));
    }
    mSampledBefore = false;
    return Ok{};
}

// Records the camera depth pass, then each light's collector draw into its mask, with the
// layout transitions between them; the first failure to bind a draw, or Ok.
Status ScreenShadowMasks::recordMasks(VkCommandBuffer commands, RendererBase& renderer,
                                      const std::vector<Draw>& depthDraws,
                                      const std::map<size_t, Draw>& collectorDraws,
                                      uint32_t& drawCount) {
    if (mSampledBefore) {
        vulkan::transitionLayout(commands, mDepth->depthImage(), kDepthStencil,
                                 {VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
                                  VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                                  VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, kDepthStages,
                                  VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                                      VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT});
        for (auto& [light, mask] : mMasks) {
            vulkan::transitionLayout(commands, mask.colorImage(), VK_IMAGE_ASPECT_COLOR_BIT,
                                     {VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                      VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0,
                                      VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                                      VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT});
        }
    }
    VkViewport viewport = mDepth->viewport();
    VkRect2D area = mDepth->area();
    mDepth->begin(commands, vulkan::LoadOp::Clear);
    vkCmdSetViewport(commands, 0, 1, &viewport);
    vkCmdSetScissor(commands, 0, 1, &area);
    Status bound = recordDraws(commands, *renderer.resources, depthDraws, drawCount);
    mDepth->end(commands);
    vulkan::transitionLayout(
        commands, mDepth->depthImage(), kDepthStencil,
        {VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
         VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, kDepthStages,
         VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
         VK_ACCESS_SHADER_READ_BIT});
    for (auto& [light, mask] : mMasks) {
        mask.begin(commands, vulkan::LoadOp::Clear);
        vkCmdSetViewport(commands, 0, 1, &viewport);
        vkCmdSetScissor(commands, 0, 1, &area);
        if (bound) {
            bound = recordDraws(commands, *renderer.resources, {collectorDraws.at(light)},
                                drawCount);
        }
        mask.end(commands);
        vulkan::transitionLayout(
            commands, mask.colorImage(), VK_IMAGE_ASPECT_COLOR_BIT,
            {VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
             VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
             VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
             VK_ACCESS_SHADER_READ_BIT});
    }
    return bound;
}

Status ScreenShadowMasks::render(RendererBase& renderer, const scene::Scene& scene,
                                 const ShadowMaps& shadows, const scene::CameraMatrices& matrices,
                                 std::vector<std::string>& drawn) {
    mRendered.clear();
    std::vector<size_t> lights;
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        if (shadows.isDirectional(i) && shadows.map(i)) lights.push_back(i);
    }
    if (lights.empty()) return Ok{};
    const reader::Pack* pack = nullptr;
    std::optional<reader::ShaderView> collector = renderer.findShader(kScreenShadowShader, &pack);
    std::optional<reader::PassView> pass = collector ? collector->pass(size_t{0}) : std::nullopt;
    if (!pass) {
        return makeError(ErrorCode::NotFound,
                         std::string("directional shadows need the shader \"") +
                             kScreenShadowShader + "\" (shaders/internal) in a pack");
    }
    if (Status ready = prepare(renderer, scene.camera, lights); !ready) return ready;

    FrameStorage storage;
    // The camera depth texture: the casters from the camera, without shadow bias.
    ShaderValues& camera = storage.values.emplace_back(cameraValues(scene, matrices));
    camera.set("unity_LightShadowBias", glm::vec4(0.0f));
    std::vector<Draw> depthDraws;
    if (Status made = appendCasterDraws(renderer, scene, matrices, camera, "SHADOWS_DEPTH", false,
                                        *mDepth, storage, depthDraws, drawn);
        !made) {
        return makeError(made.error().code, "camera depth texture: " + made.error().detail);
    }
    auto quad = uploadFullScreenQuad(*renderer.context, matrices);
    if (!quad) return quad.error();
    const ShaderValues& quadLayer = storage.values.emplace_back(fullScreenQuadValues(matrices));
    const ShaderValues& noMaterial = storage.values.emplace_back();
    std::map<size_t, Draw> collectorDraws;
    const TextureBinding depth{mDepth->depthSampleView(), mNearest.get(),
                               VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL};
    for (size_t light : lights) {
        const scene::Light& l = scene.lights[light];
        auto variant = renderer.variantFor(
            *pass, pass->keyOf(collectorKeywords(l, shadows.directional(light))),
            variants::SelectionPolicy::Exact);
        if (!variant) return variant.error();
        const vulkan::RenderTarget& mask = mMasks.at(light);
        auto pipeline =
            renderer.pipeline(pack, *variant, resolveRenderState(pass->renderState(), noMaterial),
                              {mask.renderPass(vulkan::LoadOp::Clear), false, 1}, kMaskKind);
        if (!pipeline) return pipeline.error();
        ShaderValues& lightLayer = storage.values.emplace_back(forwardLightValues(&l));
        shadows.addReceiverValues(scene, light, lightLayer);
        Draw draw;
        draw.pipeline = *pipeline;
        draw.mesh = &*quad;
        draw.layers = {&lightLayer, &quadLayer, &noMaterial, &camera};
        const std::optional<TextureBinding> atlas = shadows.map(light);
        draw.textures = [depth, atlas](std::string_view name,
                                       pack::ResourceDim) -> std::optional<TextureBinding> {
            if (name == "_CameraDepthTexture") return depth;
            if (name == "_ShadowMapTexture") return atlas;
            return std::nullopt;
        };
        collectorDraws.emplace(light, std::move(draw));
        drawn.push_back(variant->describe());
    }

    Status bound = Ok{};
    uint32_t drawCount = 0;
    Status submitted = renderer.context->submitAndWait([&](VkCommandBuffer commands) {
        bound = recordMasks(commands, renderer, depthDraws, collectorDraws, drawCount);
    });
    mSampledBefore = true;
    if (Status reset = renderer.resources->reset(); !reset) return reset.error();
    if (!bound) return bound.error();
    if (!submitted) return submitted;
    for (size_t light : lights) mRendered[light] = true;
    return Ok{};
}

std::optional<render::TextureBinding> render::ScreenShadowMasks::mask(size_t light) const {
    if (!mRendered.count(light)) return std::nullopt;
    return render::TextureBinding{mMasks.at(light).colorView(), mNearest.get(),
                                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
}

}  // namespace varc::render
