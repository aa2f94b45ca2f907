// SPDX-License-Identifier: Apache-2.0
// ShadowMaps: depth maps rendered with the objects' ShadowCaster passes.
#include "ShadowMaps.h"

#include "Draw.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ShaderView.h"
#include "varc/render/SceneValues.h"
#include "varc/vulkan/Sampler.h"

namespace varc::runtime {

namespace {

// Pipelines for shadow maps: an RGBA8 colour attachment the casters' `return 0` goes to, and a
// D32S8 (or D24S8) depth/stencil attachment that is the map.
constexpr uint32_t kShadowTargetKind = 100;

constexpr VkImageAspectFlags kDepthStencil = VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
constexpr VkPipelineStageFlags kDepthStages =
    VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;

LayoutTransition depthToSampled() {
    return {VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
            VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, kDepthStages,
            VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
            VK_ACCESS_SHADER_READ_BIT};
}

LayoutTransition sampledToDepth() {
    return {VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
            VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
            0, kDepthStages,
            VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT};
}

// The caster pass's camera: the light's shadow camera, and the light for the normal offset.
ShaderValues casterValues(const scene::Scene& scene, const scene::Light& light,
                          const scene::ShadowCamera& shadow) {
    scene::Scene lightView = scene;
    lightView.camera.position = light.transform.position;
    lightView.camera.nearPlane = light.shadowNearPlane;
    lightView.camera.farPlane = light.range;
    lightView.camera.width = lightView.camera.height = shadow.resolution;
    ShaderValues values = cameraValues(lightView, shadow.matrices);
    ShaderValues lightValues = forwardLightValues(&light);
    values.merge(lightValues);
    values.set("unity_LightShadowBias", shadow.bias);
    return values;
}

}  // namespace

Status ShadowMaps::render(RendererBase& renderer, const scene::Scene& scene) {
    mRendered.clear();
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const scene::Light& light = scene.lights[i];
        if (light.shadows == scene::ShadowType::None || light.type != scene::LightType::Spot)
            continue;
        if (Status rendered = renderSpot(renderer, scene, i, mMaps[i]); !rendered) {
            return makeError(rendered.error().code, "shadow map of light " + std::to_string(i) +
                                                        ": " + rendered.error().detail);
        }
        mRendered[i] = true;
    }
    return Ok{};
}

Status ShadowMaps::renderSpot(RendererBase& renderer, const scene::Scene& scene, size_t index,
                              LightMap& map) {
    const scene::Light& light = scene.lights[index];
    map.camera = scene::spotShadowCamera(light);
    if (!map.target || map.target->width() != map.camera.resolution) {
        RenderTargetDesc desc;
        desc.width = desc.height = map.camera.resolution;
        desc.sampledDepth = true;
        desc.name = "shadow map";
        auto target = RenderTarget::create(*renderer.context, desc);
        if (!target) return target.error();
        map.target.emplace(std::move(*target));
        map.sampledBefore = false;
    }
    if (!mNearest) {
        SamplerDesc nearest;
        nearest.filter = VK_FILTER_NEAREST;
        nearest.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        nearest.addressMode = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        nearest.name = "shadow map sampler";
        auto sampler = createSampler(*renderer.context, nearest);
        if (!sampler) return sampler.error();
        mNearest = std::move(*sampler);
    }

    FrameStorage storage;
    const ShaderValues& camera = storage.values.emplace_back(casterValues(scene, light, map.camera));
    std::vector<Draw> draws;
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const scene::Object& object = scene.objects[o];
        const std::string what = objectLabel(o, object);
        const Pack* pack = nullptr;
        auto shader = renderer.objectShader(what, object, &pack);
        if (!shader) return shader.error();
        std::optional<PassView> pass = shader->pass(std::string_view("ShadowCaster"));
        if (!pass) continue;  // casts no shadow
        auto variant = pass->lookup(std::vector<std::string>{"SHADOWS_DEPTH"},
                                    variants::SelectionPolicy::Closest);
        if (!variant) return makeError(variant.error().code, what + ": " + variant.error().detail);
        auto material = renderer.objectMaterial(what, object.material, shader->properties(), storage);
        if (!material) return material.error();
        const ShaderValues& objectLayer = storage.values.emplace_back(
            objectValues(scene, object, map.camera.matrices, scene::ForwardLightAssignment{}));
        auto draw = renderer.objectDraw({what, pack, &*pass, &*variant, *material,
                                         object.transform.localToWorld(), object.mesh,
                                         {map.target->renderPass(LoadOp::Clear), true, 1},
                                         kShadowTargetKind});
        if (!draw) return draw.error();
        draw->layers[1] = &objectLayer;
        draw->layers[3] = &camera;
        draws.push_back(std::move(*draw));
    }

    Status bound = Ok{};
    uint32_t drawCount = 0;
    const RenderTarget& target = *map.target;
    Status submitted = renderer.context->submitAndWait([&](VkCommandBuffer commands) {
        if (map.sampledBefore) transitionLayout(commands, target.depthImage(), kDepthStencil, sampledToDepth());
        target.begin(commands, LoadOp::Clear);
        VkViewport viewport = target.viewport();
        VkRect2D area = target.area();
        vkCmdSetViewport(commands, 0, 1, &viewport);
        vkCmdSetScissor(commands, 0, 1, &area);
        bound = recordDraws(commands, *renderer.resources, draws, drawCount);
        target.end(commands);
        transitionLayout(commands, target.depthImage(), kDepthStencil, depthToSampled());
    });
    map.sampledBefore = true;
    if (Status reset = renderer.resources->reset(); !reset) return reset.error();
    if (!bound) return bound.error();
    return submitted;
}

std::optional<TextureBinding> ShadowMaps::map(size_t light) const {
    if (!mRendered.count(light)) return std::nullopt;
    const LightMap& map = mMaps.at(light);
    return TextureBinding{map.target->depthSampleView(), mNearest.get(),
                          VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL};
}

void ShadowMaps::addReceiverValues(const scene::Scene& scene, size_t light,
                                   ShaderValues& values) const {
    if (!mRendered.count(light)) return;
    const LightMap& map = mMaps.at(light);
    std::vector<glm::mat4> worldToShadow(4, map.camera.worldToShadow);
    values.setArray("unity_WorldToShadow", worldToShadow);
    values.set("_LightShadowData", scene::lightShadowData(scene.lights[light], scene));
    values.set("unity_ShadowFadeCenterAndType", scene::shadowFadeCenterAndType(scene));
    auto size = static_cast<float>(map.camera.resolution);
    values.set("_ShadowMapTexture_TexelSize", glm::vec4(1.0f / size, 1.0f / size, size, size));
}

}  // namespace varc::runtime
