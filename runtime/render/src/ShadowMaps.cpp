// SPDX-License-Identifier: Apache-2.0
// ShadowMaps: depth maps and depth cube maps rendered with the objects' ShadowCaster passes.
#include "ShadowMaps.h"

#include "varc/reader/PassView.h"
#include "varc/reader/ShaderView.h"
#include "varc/render/SceneValues.h"
#include "varc/vulkan/Sampler.h"

namespace varc::render {

namespace {

// Pipelines for shadow maps: an RGBA8 colour attachment the casters' `return 0` goes to, and a
// D32S8 (or D24S8) depth/stencil attachment that is the map.
constexpr uint32_t kShadowTargetKind = 100;

constexpr VkImageAspectFlags kDepthStencil = VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
constexpr VkPipelineStageFlags kDepthStages =
    VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
constexpr VkAccessFlags kDepthAccess =
    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;

vulkan::LayoutTransition depthTo(VkImageLayout layout, VkPipelineStageFlags stages,
                                 VkAccessFlags access) {
    return {VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, layout, kDepthStages,
            VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, stages, access};
}

vulkan::LayoutTransition backToDepth(VkImageLayout layout, VkPipelineStageFlags stages) {
    return {layout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, stages, 0, kDepthStages,
            kDepthAccess};
}

// The caster pass's camera: |matrices| seen from the light, and the light for the normal offset.
ShaderValues casterValues(const scene::Scene& scene, const scene::Light& light,
                          const scene::CameraMatrices& matrices, uint32_t resolution,
                          const glm::vec4& bias) {
    scene::Scene lightView = scene;
    lightView.camera.position = light.transform.position;
    lightView.camera.nearPlane = light.shadowNearPlane;
    lightView.camera.farPlane = light.range;
    lightView.camera.width = lightView.camera.height = resolution;
    ShaderValues values = cameraValues(lightView, matrices);
    values.merge(forwardLightValues(&light));
    values.set("unity_LightShadowBias", bias);
    return values;
}

// Camera matrices for a cube face: only the view-projection is a real camera's.
scene::CameraMatrices faceMatrices(const glm::mat4& viewProjection, const glm::vec3& lightPos) {
    scene::CameraMatrices m;
    m.cameraToWorld = glm::mat4(1.0f);
    m.cameraToWorld[3] = glm::vec4(lightPos, 1.0f);
    m.worldToCamera = glm::inverse(m.cameraToWorld);
    m.view = m.worldToCamera;
    m.viewProjection = viewProjection;
    m.projection = viewProjection * m.cameraToWorld;
    m.glProjection = m.projection;
    return m;
}

}  // namespace

Status ShadowMaps::render(RendererBase& renderer, const scene::Scene& scene,
                          std::vector<std::string>& drawn) {
    mRendered.clear();
    mDrawn = &drawn;
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const scene::Light& light = scene.lights[i];
        if (light.shadows == scene::ShadowType::None) continue;
        Status rendered = light.type == scene::LightType::Spot
                              ? renderSpot(renderer, scene, i, mMaps[i])
                          : light.type == scene::LightType::Point
                              ? renderPoint(renderer, scene, i, mMaps[i])
                              : renderDirectional(renderer, scene, i, mMaps[i]);
        if (!rendered) {
            return makeError(rendered.error().code, "shadow map of light " + std::to_string(i) +
                                                        ": " + rendered.error().detail);
        }
        mRendered[i] = true;
    }
    return Ok{};
}

Status ShadowMaps::prepare(RendererBase& renderer, uint32_t resolution, bool cube, LightMap& map) {
    if (!mNearest) {
        auto sampler = createShadowSampler(*renderer.context, "shadow map sampler");
        if (!sampler) return sampler.error();
        mNearest = std::move(*sampler);
    }
    if (map.target && map.target->width() == resolution && map.cube.has_value() == cube)
        return Ok{};
    vulkan::RenderTargetDesc desc;
    desc.width = desc.height = resolution;
    desc.sampledDepth = !cube;
    desc.copyableDepth = cube;
    desc.name = cube ? "shadow cube face" : "shadow map";
    auto target = vulkan::RenderTarget::create(*renderer.context, desc);
    if (!target) return target.error();
    map.target.emplace(std::move(*target));
    map.sampledBefore = false;
    map.cube.reset();
    if (!cube) return Ok{};
    vulkan::DeviceImageDesc cubeDesc;
    cubeDesc.format = map.target->depthStencilFormat();
    cubeDesc.width = cubeDesc.height = resolution;
    cubeDesc.cube = true;
    cubeDesc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    cubeDesc.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;  // the view samples depth only
    auto image = vulkan::createDeviceImage(*renderer.context, cubeDesc, "shadow cube map");
    if (!image) return image.error();
    map.cube.emplace(std::move(*image));
    return Ok{};
}

Result<vulkan::UniqueHandle<VkSampler>> createShadowSampler(const vulkan::VulkanContext& context,
                                                            const std::string& name) {
    vulkan::SamplerDesc nearest;
    nearest.filter = VK_FILTER_NEAREST;
    nearest.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    nearest.addressMode = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    nearest.name = name;
    return vulkan::createSampler(context, nearest);
}

Status appendCasterDraws(RendererBase& renderer, const scene::Scene& scene,
                         const scene::CameraMatrices& matrices, const ShaderValues& camera,
                         const std::string& keyword, bool mirrored,
                         const vulkan::RenderTarget& target, FrameStorage& storage,
                         std::vector<Draw>& draws, std::vector<std::string>& drawn) {
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const scene::Object& object = scene.objects[o];
        const std::string what = objectLabel(o, object);
        const reader::Pack* pack = nullptr;
        auto shader = renderer.objectShader(what, object, &pack);
        if (!shader) return shader.error();
        std::optional<reader::PassView> pass = shader->pass(std::string_view("ShadowCaster"));
        if (!pass) continue;  // casts no shadow
        // The light's keyword and the material's (shader_feature variants, e.g. Standard's
        // _ALPHATEST_ON).
        std::vector<std::string> keywords = object.material.keywords;
        keywords.push_back(keyword);
        auto variant =
            renderer.variantFor(*pass, pass->keyOf(keywords), variants::SelectionPolicy::Closest);
        if (!variant) return makeError(variant.error().code, what + ": " + variant.error().detail);
        auto material =
            renderer.objectMaterial(what, object.material, shader->properties(),
                                    shader->dynamicKeywords(), storage);
        if (!material) return material.error();
        const ShaderValues& objectLayer = storage.values.emplace_back(
            objectValues(scene, object, matrices, scene::ForwardLightAssignment{}));
        ObjectDrawRequest request{what,
                                  pack,
                                  &*pass,
                                  &*variant,
                                  *material,
                                  object.transform.localToWorld(),
                                  object.mesh,
                                  {target.renderPass(vulkan::LoadOp::Clear), true, 1},
                                  kShadowTargetKind};
        request.mirroredView = mirrored;
        auto draw = renderer.objectDraw(request);
        if (!draw) return draw.error();
        draw->layers[1] = &objectLayer;
        draw->layers[3] = &camera;
        draw->textures = [dither = renderer.textures->ditherMask(),
                          material = std::move(draw->textures)](
                             std::string_view name,
                             pack::ResourceDim dim) -> std::optional<TextureBinding> {
            if (name == "_DitherMaskLOD" && dim == pack::ResourceDim::Dim3D) return dither;
            return material(name, dim);
        };
        draws.push_back(std::move(*draw));
        drawn.push_back(variant->describe());
    }
    return Ok{};
}

Status ShadowMaps::renderSpot(RendererBase& renderer, const scene::Scene& scene, size_t index,
                              LightMap& map) {
    const scene::Light& light = scene.lights[index];
    map.type = scene::LightType::Spot;
    map.spot = scene::spotShadowCamera(light);
    if (Status ready = prepare(renderer, map.spot.resolution, false, map); !ready) return ready;
    FrameStorage storage;
    const ShaderValues& camera = storage.values.emplace_back(
        casterValues(scene, light, map.spot.matrices, map.spot.resolution, map.spot.bias));
    std::vector<Draw> draws;
    if (Status made = casterDraws(renderer, scene, map.spot.matrices, camera, "SHADOWS_DEPTH",
                                  false, *map.target, storage, draws);
        !made) {
        return made;
    }
    return drawDepthPass(renderer, map, {{map.target->viewport(), map.target->area(), &draws}});
}

// Six faces, each drawn into the one face target and copied into its layer of the cube.
Status ShadowMaps::renderPoint(RendererBase& renderer, const scene::Scene& scene, size_t index,
                               LightMap& map) {
    const scene::Light& light = scene.lights[index];
    map.type = scene::LightType::Point;
    map.point = scene::pointShadowCamera(light);
    if (Status ready = prepare(renderer, map.point.resolution, true, map); !ready) return ready;
    FrameStorage storage;
    std::array<std::vector<Draw>, 6> faceDraws;
    for (size_t face = 0; face < 6; ++face) {
        const scene::CameraMatrices matrices =
            faceMatrices(map.point.faceViewProjection[face], light.transform.position);
        const ShaderValues& camera = storage.values.emplace_back(
            casterValues(scene, light, matrices, map.point.resolution, map.point.bias));
        if (Status made = casterDraws(renderer, scene, matrices, camera, "SHADOWS_CUBE",
                                      map.point.mirrored[face], *map.target, storage,
                                      faceDraws[face]);
            !made) {
            return made;
        }
    }
    Status bound = Ok{};
    uint32_t drawCount = 0;
    const vulkan::RenderTarget& target = *map.target;
    const VkImage cube = map.cube->image.get();
    const uint32_t size = map.point.resolution;
    Status submitted = renderer.context->submitAndWait([&](VkCommandBuffer commands) {
        // The cube is never an attachment: it is sampled in SHADER_READ_ONLY_OPTIMAL.
        const VkImageLayout cubeFrom = map.sampledBefore ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL
                                                         : VK_IMAGE_LAYOUT_UNDEFINED;
        vulkan::transitionLayout(
            commands, cube, kDepthStencil,
            {cubeFrom, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
             0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT});
        for (uint32_t face = 0; face < 6; ++face) {
            target.begin(commands, vulkan::LoadOp::Clear);
            VkViewport viewport = target.viewport();
            VkRect2D area = target.area();
            vkCmdSetViewport(commands, 0, 1, &viewport);
            vkCmdSetScissor(commands, 0, 1, &area);
            if (bound) bound = recordDraws(commands, *renderer.resources, faceDraws[face], drawCount);
            target.end(commands);
            transitionLayout(commands, target.depthImage(), kDepthStencil,
                             depthTo(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT));
            VkImageCopy copy{};
            copy.srcSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
            copy.dstSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, face, 1};
            copy.extent = {size, size, 1};
            vkCmdCopyImage(commands, target.depthImage(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           cube, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
            transitionLayout(commands, target.depthImage(), kDepthStencil,
                             backToDepth(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                         VK_PIPELINE_STAGE_TRANSFER_BIT));
        }
        vulkan::transitionLayout(
            commands, cube, kDepthStencil,
            {VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
             VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
             VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT});
    });
    map.sampledBefore = true;
    if (Status reset = renderer.resources->reset(); !reset) return reset.error();
    if (!bound) return bound.error();
    return submitted;
}

// The cascades drawn side by side into one atlas, each through its own viewport.
Status ShadowMaps::renderDirectional(RendererBase& renderer, const scene::Scene& scene,
                                     size_t index, LightMap& map) {
    const scene::Light& light = scene.lights[index];
    map.type = scene::LightType::Directional;
    map.directional = scene::directionalShadowSetup(scene, light);
    const scene::DirectionalShadowSetup& setup = map.directional;
    if (Status ready = prepare(renderer, setup.resolution, false, map); !ready) return ready;
    FrameStorage storage;
    std::array<std::vector<Draw>, 4> cascadeDraws;
    for (int c = 0; c < setup.cascades; ++c) {
        scene::CameraMatrices matrices;
        matrices.viewProjection = setup.viewProjection[static_cast<size_t>(c)];
        matrices.view = matrices.worldToCamera = glm::mat4(1.0f);
        matrices.cameraToWorld = glm::mat4(1.0f);
        matrices.projection = matrices.glProjection = matrices.viewProjection;
        const ShaderValues& camera = storage.values.emplace_back(
            casterValues(scene, light, matrices, setup.tileSize, setup.bias));
        if (Status made = casterDraws(renderer, scene, matrices, camera, "SHADOWS_DEPTH", false,
                                      *map.target, storage, cascadeDraws[static_cast<size_t>(c)]);
            !made) {
            return made;
        }
    }
    std::vector<DepthTile> tiles;
    for (int c = 0; c < setup.cascades; ++c) {
        const glm::uvec2 origin = setup.tileOrigin[static_cast<size_t>(c)];
        const auto size = static_cast<float>(setup.tileSize);
        tiles.push_back({{static_cast<float>(origin.x), static_cast<float>(origin.y), size, size,
                          0.0f, 1.0f},
                         {{static_cast<int32_t>(origin.x), static_cast<int32_t>(origin.y)},
                          {setup.tileSize, setup.tileSize}},
                         &cascadeDraws[static_cast<size_t>(c)]});
    }
    return drawDepthPass(renderer, map, tiles);
}

// One submission: the target's depth back to an attachment if it was sampled, every tile's draws
// in one cleared render pass, then the depth ready to be sampled.
Status ShadowMaps::drawDepthPass(RendererBase& renderer, LightMap& map,
                                 const std::vector<DepthTile>& tiles) {
    Status bound = Ok{};
    uint32_t drawCount = 0;
    const vulkan::RenderTarget& target = *map.target;
    Status submitted = renderer.context->submitAndWait([&](VkCommandBuffer commands) {
        if (map.sampledBefore) {
            vulkan::transitionLayout(commands, target.depthImage(), kDepthStencil,
                                     backToDepth(VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
                                                 VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT));
        }
        target.begin(commands, vulkan::LoadOp::Clear);
        for (const DepthTile& tile : tiles) {
            vkCmdSetViewport(commands, 0, 1, &tile.viewport);
            vkCmdSetScissor(commands, 0, 1, &tile.area);
            if (bound) bound = recordDraws(commands, *renderer.resources, *tile.draws, drawCount);
        }
        target.end(commands);
        vulkan::transitionLayout(
            commands, target.depthImage(), kDepthStencil,
            depthTo(VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
                    VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT));
    });
    map.sampledBefore = true;
    if (Status reset = renderer.resources->reset(); !reset) return reset.error();
    if (!bound) return bound.error();
    return submitted;
}

std::optional<TextureBinding> ShadowMaps::map(size_t light) const {
    if (!mRendered.count(light)) return std::nullopt;
    const LightMap& map = mMaps.at(light);
    if (map.cube) {
        return TextureBinding{map.cube->view.get(), mNearest.get(),
                              VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    }
    return TextureBinding{map.target->depthSampleView(), mNearest.get(),
                          VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL};
}

void ShadowMaps::addReceiverValues(const scene::Scene& scene, size_t light,
                                   ShaderValues& values) const {
    if (!mRendered.count(light)) return;
    const LightMap& map = mMaps.at(light);
    std::vector<glm::mat4> worldToShadow(4, map.spot.worldToShadow);
    if (map.type == scene::LightType::Directional) {
        const scene::DirectionalShadowSetup& setup = map.directional;
        worldToShadow.assign(setup.worldToShadow.begin(), setup.worldToShadow.end());
        values.set("_LightSplitsNear", setup.splitsNear);
        values.set("_LightSplitsFar", setup.splitsFar);
        values.setArray("unity_ShadowSplitSpheres",
                        std::vector<glm::vec4>(setup.splitSpheres.begin(), setup.splitSpheres.end()));
        values.set("unity_ShadowSplitSqRadii", setup.splitSqRadii);
    }
    values.setArray("unity_WorldToShadow", worldToShadow);
    values.set("_LightShadowData", scene::lightShadowData(scene.lights[light], scene));
    values.set("unity_ShadowFadeCenterAndType", scene::shadowFadeCenterAndType(scene));
    if (map.type == scene::LightType::Point) values.set("_LightProjectionParams", map.point.projectionParams);
    const auto size = static_cast<float>(map.type == scene::LightType::Point ? map.point.resolution
                                         : map.type == scene::LightType::Spot ? map.spot.resolution
                                                                              : map.directional.resolution);
    values.set("_ShadowMapTexture_TexelSize", glm::vec4(1.0f / size, 1.0f / size, size, size));
}

}  // namespace varc::render
