// SPDX-License-Identifier: Apache-2.0
#include "varc/render/ForwardRenderer.h"

#include <deque>

#include "CameraTargetCache.h"
#include "Draw.h"
#include "GpuMesh.h"
#include "RendererBase.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ShaderView.h"
#include "varc/render/RenderStateResolver.h"
#include "varc/render/SceneValues.h"
#include "varc/render/VertexLayout.h"
#include "varc/scene/Mesh.h"
#include "varc/variants/LightKeywords.h"
#include "varc/vulkan/RenderTarget.h"

namespace varc::runtime {

struct ForwardRenderer::State : RendererBase {
    CameraTargetCache<RenderTarget> targets;
};

ForwardRenderer::ForwardRenderer(std::unique_ptr<State> state) : mState(std::move(state)) {}
ForwardRenderer::ForwardRenderer(ForwardRenderer&&) noexcept = default;
ForwardRenderer& ForwardRenderer::operator=(ForwardRenderer&&) noexcept = default;
ForwardRenderer::~ForwardRenderer() = default;

Result<ForwardRenderer> ForwardRenderer::create(VulkanContext& context,
                                                std::vector<const Pack*> packs) {
    auto state = std::make_unique<State>();
    if (Status ready = state->init(context, std::move(packs)); !ready) return ready.error();
    return ForwardRenderer(std::move(state));
}

Result<RenderedFrame> ForwardRenderer::render(const scene::Scene& scene) {
    State& s = *mState;
    auto target = s.targets.get(scene.camera, [&](const scene::Camera& camera) {
        return createCameraTarget(*s.context, camera, "forward target");
    });
    if (!target) return target.error();
    scene::CameraMatrices matrices = scene::cameraMatrices(scene.camera);
    ShaderValues camera = cameraValues(scene, matrices);
    const BuiltinTextures& builtin = *s.textures;
    if (Status cookies = s.loadCookieFiles(scene.lights); !cookies) return cookies.error();

    // Stable storage for the values the draws point at.
    std::deque<ShaderValues> values;
    std::deque<std::map<std::string, std::string>> materialTextures;
    std::vector<Draw> draws;
    RenderedFrame frame;
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const scene::Object& object = scene.objects[o];
        std::string what = objectLabel(o, object);
        const Pack* pack = nullptr;
        std::optional<ShaderView> shader = s.findShader(object.material.shader, &pack);
        if (!shader) return makeError(ErrorCode::NotFound, what + ": no pack has this shader");
        scene::ForwardLightAssignment assignment = scene::assignForwardLights(scene, object);
        const ShaderValues& objectValues_ =
            values.emplace_back(objectValues(scene, object, matrices, assignment));
        std::map<std::string, std::string>& textureNames = materialTextures.emplace_back();
        const ShaderValues& material = values.emplace_back(materialValues(
            withPropertyDefaults(object.material, shader->properties()), textureNames));
        if (Status loaded = s.loadTextureFiles(textureNames); !loaded)
            return makeError(loaded.error().code, what + ": " + loaded.error().detail);

        auto addDraw = [&](const char* lightMode, const scene::Light* light) -> Status {
            std::optional<PassView> pass = shader->pass(std::string_view(lightMode));
            if (!pass)
                return makeError(ErrorCode::NotFound,
                                 what + ": the shader has no " + lightMode + " pass");
            variants::LightDescription description;
            description.type =
                light ? toVariantLight(light->type) : variants::LightType::Directional;
            description.cookie = light && light->hasCookie();
            description.vertexLightCount = static_cast<int>(assignment.vertexLights.size());
            description.hdr = scene.camera.hdr;
            description.lightProbes = true;
            auto variant = pass->lookup(description, variants::SelectionPolicy::Closest);
            if (!variant)
                return makeError(variant.error().code, what + ": " + variant.error().detail);
            pack::PackRenderState state = forObjectTransform(
                resolveRenderState(pass->renderState(), material), object.transform.localToWorld());
            auto pipeline =
                s.pipeline(pack, *variant, state, {(*target)->renderPass(LoadOp::Clear), true, 1},
                           scene.camera.hdr ? 1u : 0u);
            if (!pipeline)
                return makeError(pipeline.error().code, what + ": " + pipeline.error().detail);
            const ShaderValues& lightValues = values.emplace_back(forwardLightValues(light));
            Draw draw;
            draw.pipeline = *pipeline;
            draw.mesh = &s.meshes.at(object.mesh);
            draw.layers = {&lightValues, &objectValues_, &material, &camera};
            scene::LightType type = light ? light->type : scene::LightType::Directional;
            bool cookie = light && light->cookie != "none";
            draw.textures = [&s, &builtin, &textureNames, light, type, cookie](
                                std::string_view name,
                                pack::ResourceDim dim) -> std::optional<TextureBinding> {
                if (light && name == "_LightTexture0") {
                    if (auto file = s.cookieFile(*light)) return file;
                }
                if (auto texture = builtin.lightTexture(name, dim, type, cookie, false))
                    return texture;
                auto it = textureNames.find(std::string(name));
                // Unset textures default to white, as Unity's Properties defaults mostly do.
                return s.materialTexture(it == textureNames.end() ? "white" : it->second, dim);
            };
            draws.push_back(std::move(draw));
            frame.variants.push_back(variant->describe());
            return Ok{};
        };
        const scene::Light* main =
            assignment.mainDirectional >= 0
                ? &scene.lights[static_cast<size_t>(assignment.mainDirectional)]
                : nullptr;
        if (Status added = addDraw("ForwardBase", main); !added) return added.error();
        for (int index : assignment.addLights) {
            if (Status added = addDraw("ForwardAdd", &scene.lights[static_cast<size_t>(index)]);
                !added) {
                return added.error();
            }
        }
    }

    if (Status drawn = s.drawFrame(**target, draws, frame); !drawn) return drawn.error();
    return frame;
}

void ForwardRenderer::usePipelineCache(VkPipelineCache cache) { mState->pipelineCache = cache; }

}  // namespace varc::runtime
