// SPDX-License-Identifier: Apache-2.0
#include "varc/render/ForwardRenderer.h"

#include <deque>
#include <map>

#include "CameraTargetCache.h"
#include "Draw.h"
#include "GpuMesh.h"
#include "RendererBase.h"
#include "ScreenShadowMasks.h"
#include "ShadowMaps.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ShaderView.h"
#include "varc/render/RenderStateResolver.h"
#include "varc/render/SceneValues.h"
#include "varc/render/VertexLayout.h"
#include "varc/scene/Mesh.h"
#include "varc/scene/ObjectLightmaps.h"
#include "varc/variants/LightKeywords.h"
#include "varc/vulkan/RenderTarget.h"

namespace varc::render {

struct ForwardRenderer::State : RendererBase {
    CameraTargetCache<vulkan::RenderTarget> targets;
    ShadowMaps shadows;
    ScreenShadowMasks screenShadows;  // directional lights' masks (SHADOWS_SCREEN)

    using LightmapBindings = std::map<std::string, TextureBinding, std::less<>>;

    Status addObjectDraws(const scene::Scene& scene, size_t index,
                          const vulkan::RenderTarget& target, FrameStorage& storage,
                          const ShaderValues& camera, const scene::CameraMatrices& matrices,
                          std::vector<Draw>& draws, RenderedFrame& frame);
    // The lightmap textures |object| (named |what| in errors) binds, by shader name.
    Result<LightmapBindings> lightmapBindings(const scene::Object& object,
                                              const std::string& what);
    // The shadow texture |light| (index |lightIndex|; nullptr: none) is drawn with: directional
    // lights read their screen-space mask, the others their map; nullopt without one.
    std::optional<TextureBinding> shadowTexture(const scene::Light* light, size_t lightIndex);
};

ForwardRenderer::ForwardRenderer(std::unique_ptr<State> state) : mState(std::move(state)) {}
ForwardRenderer::ForwardRenderer(ForwardRenderer&&) noexcept = default;
ForwardRenderer& ForwardRenderer::operator=(ForwardRenderer&&) noexcept = default;
ForwardRenderer::~ForwardRenderer() = default;

Result<ForwardRenderer> ForwardRenderer::create(vulkan::VulkanContext& context,
                                                std::vector<const reader::Pack*> packs) {
    auto state = std::make_unique<State>();
    if (Status ready = state->init(context, std::move(packs)); !ready) return ready.error();
    return ForwardRenderer(std::move(state));
}

namespace {

// The variant a forward pass draws for |light| (nullptr: the base pass without a main light);
// |shadowed| when the light's shadow map was rendered this frame.
variants::LightDescription forwardLight(const scene::Scene& scene, const scene::Object& object,
                                        const scene::Light* light,
                                        const scene::ForwardLightAssignment& assignment,
                                        bool shadowed) {
    variants::LightDescription description;
    if (light && shadowed) description.shadows = toVariantShadows(light->shadows);
    description.type = light ? toVariantLight(light->type) : variants::LightType::Directional;
    description.cookie = light && light->hasCookie();
    description.vertexLightCount = static_cast<int>(assignment.vertexLights.size());
    description.hdr = scene.camera.hdr;
    const scene::ObjectLightmaps lightmaps = scene::objectLightmaps(scene, object);
    description.lightProbes = lightmaps.lightProbes;
    description.lightmap = lightmaps.lightmap;
    description.dirLightmap = lightmaps.dirLightmap;
    description.dynamicLightmap = lightmaps.dynamicLightmap;
    description.shadowmask = lightmaps.shadowmask;
    description.shadowMixing = lightmaps.shadowMixing;
    return description;
}

}  // namespace

Result<ForwardRenderer::State::LightmapBindings> ForwardRenderer::State::lightmapBindings(
    const scene::Object& object, const std::string& what) {
    LightmapBindings lightmaps;
    for (const char* name : {"unity_Lightmap", "unity_LightmapInd", "unity_DynamicLightmap",
                             "unity_DynamicDirectionality", "unity_ShadowMask"}) {
        auto texture = lightmapTexture(object, name);
        if (!texture) return makeError(texture.error().code, what + ": " + texture.error().detail);
        lightmaps.emplace(name, **texture);
    }
    return lightmaps;
}

std::optional<TextureBinding> ForwardRenderer::State::shadowTexture(const scene::Light* light,
                                                                    size_t lightIndex) {
    std::optional<TextureBinding> shadowMap;
    if (light && light->type == scene::LightType::Directional) {
        shadowMap = screenShadows.mask(lightIndex);
    } else if (light) {
        shadowMap = shadows.map(lightIndex);
    }
    return shadowMap;
}

// One object's draws: ForwardBase with the main directional light (if any), then one ForwardAdd
// per add light.
Status ForwardRenderer::State::addObjectDraws(const scene::Scene& scene, size_t index,
                                              const vulkan::RenderTarget& target,
                                              FrameStorage& storage, const ShaderValues& camera,
                                              const scene::CameraMatrices& matrices,
                                              std::vector<Draw>& draws, RenderedFrame& frame) {
    const scene::Object& object = scene.objects[index];
    const std::string what = objectLabel(index, object);
    const reader::Pack* pack = nullptr;
    auto shader = objectShader(what, object, &pack);
    if (!shader) return shader.error();
    // A shader with a ShadowCaster pass and no ForwardBase pass (varc's built-in fallbacks used
    // directly) draws into the shadow maps only, as in Unity.
    if (!shader->pass(std::string_view("ForwardBase")) &&
        shader->pass(std::string_view("ShadowCaster"))) {
        return Ok{};
    }
    const scene::ForwardLightAssignment assignment = scene::assignForwardLights(scene, object);
    const ShaderValues& objectLayer =
        storage.values.emplace_back(objectValues(scene, object, matrices, assignment));
    auto material = objectMaterial(what, object.material, shader->properties(),
                                   shader->dynamicKeywords(), storage);
    if (!material) return material.error();
    auto lightmapsFound = lightmapBindings(object, what);
    if (!lightmapsFound) return lightmapsFound.error();
    const LightmapBindings lightmaps = std::move(*lightmapsFound);

    auto addDraw = [&](const char* lightMode, const scene::Light* light) -> Status {
        std::optional<reader::PassView> pass = shader->pass(std::string_view(lightMode));
        if (!pass)
            return makeError(ErrorCode::NotFound,
                             what + ": the shader has no " + lightMode + " pass");
        const size_t lightIndex = light ? static_cast<size_t>(light - scene.lights.data()) : 0;
        const std::optional<TextureBinding> shadowMap = shadowTexture(light, lightIndex);
        // The light's keywords and the material's (shader_feature variants, e.g. _DETAIL).
        auto variant =
            variantFor(*pass, forwardLight(scene, object, light, assignment, shadowMap.has_value()),
                       variants::SelectionPolicy::Closest, pass->keyOf(object.material.keywords));
        if (!variant) return makeError(variant.error().code, what + ": " + variant.error().detail);
        auto draw = objectDraw({what,
                                pack,
                                &*pass,
                                &*variant,
                                *material,
                                object.transform.localToWorld(),
                                object.mesh,
                                {target.renderPass(vulkan::LoadOp::Clear), true, 1},
                                scene.camera.hdr ? 1u : 0u});
        if (!draw) return draw.error();
        ShaderValues& lightLayer = storage.values.emplace_back(forwardLightValues(light));
        if (light) shadows.addReceiverValues(scene, lightIndex, lightLayer);
        draw->layers[0] = &lightLayer;
        draw->layers[1] = &objectLayer;
        draw->layers[3] = &camera;
        const scene::LightType type = light ? light->type : scene::LightType::Directional;
        const bool cookie = light && light->cookie != "none";
        draw->textures = [this, light, type, cookie, shadowMap, lightmaps,
                          material = std::move(draw->textures)](
                             std::string_view name,
                             pack::ResourceDim dim) -> std::optional<TextureBinding> {
            if (shadowMap && name == "_ShadowMapTexture") return shadowMap;
            if (auto lightmap = lightmaps.find(name);
                lightmap != lightmaps.end() && dim == pack::ResourceDim::Dim2D) {
                return lightmap->second;
            }
            if (light && name == "_LightTexture0") {
                if (auto file = cookieFile(*light)) return file;
                if (light->cookie == "white") return textures->named("white", dim);
            }
            if (auto texture = textures->lightTexture(name, dim, type, cookie, false))
                return texture;
            return material(name, dim);
        };
        draws.push_back(std::move(*draw));
        frame.variants.push_back(variant->describe());
        return Ok{};
    };
    const scene::Light* main = assignment.mainDirectional >= 0
                                   ? &scene.lights[static_cast<size_t>(assignment.mainDirectional)]
                                   : nullptr;
    if (Status added = addDraw("ForwardBase", main); !added) return added;
    for (int light : assignment.addLights) {
        if (Status added = addDraw("ForwardAdd", &scene.lights[static_cast<size_t>(light)]); !added)
            return added;
    }
    return Ok{};
}

Result<RenderedFrame> ForwardRenderer::render(const scene::Scene& scene) {
    State& s = *mState;
    auto target = s.targets.get(scene.camera, [&](const scene::Camera& camera) {
        return createCameraTarget(*s.context, camera, "forward target");
    });
    if (!target) return target.error();
    const scene::CameraMatrices matrices = scene::cameraMatrices(scene.camera);
    const ShaderValues camera = cameraValues(scene, matrices);
    if (Status cookies = s.loadCookieFiles(scene.lights); !cookies) return cookies.error();
    RenderedFrame frame;
    if (Status shadowMaps = s.shadows.render(s, scene, frame.variants); !shadowMaps)
        return shadowMaps.error();
    if (Status masks = s.screenShadows.render(s, scene, s.shadows, matrices, frame.variants); !masks)
        return masks.error();
    FrameStorage storage;
    std::vector<Draw> draws;
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        Status added =
            s.addObjectDraws(scene, o, **target, storage, camera, matrices, draws, frame);
        if (!added) return added.error();
    }
    if (Status drawn = s.drawFrame(**target, draws, frame); !drawn) return drawn.error();
    return frame;
}

void ForwardRenderer::usePipelineCache(VkPipelineCache cache) { mState->pipelineCache = cache; }

void ForwardRenderer::useVariantRequests(reader::VariantRequests* requests,
                                         variants::SelectionPolicy missPolicy) {
    mState->variantRequests = requests;
    mState->missPolicy = missPolicy;
}

}  // namespace varc::render
