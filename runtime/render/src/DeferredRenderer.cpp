// SPDX-License-Identifier: Apache-2.0
#include "varc/render/DeferredRenderer.h"

#include <deque>
#include <map>
#include <optional>

#include "CameraTargetCache.h"
#include "DeferredTargets.h"
#include "Draw.h"
#include "GpuMesh.h"
#include "RendererBase.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ShaderView.h"
#include "varc/render/BuiltinTextures.h"
#include "varc/render/DeferredValues.h"
#include "varc/render/DrawResources.h"
#include "varc/render/LightVolume.h"
#include "varc/render/RenderStateResolver.h"
#include "varc/render/SceneValues.h"
#include "varc/render/VertexLayout.h"
#include "varc/scene/ForwardLights.h"
#include "varc/variants/LightKeywords.h"
#include "varc/variants/RuntimeKeywords.h"
#include "varc/vulkan/Sampler.h"

namespace varc::runtime {

namespace {

// The stencil bit the G-buffer pass writes and the light and decode passes test (the shaders'
// Properties default; resolveRenderState only sees what the material sets).
constexpr float kStencilNonBackground = 128.0f;

enum class Phase { GBuffer, Light, Decode };

Result<GpuMesh> uploadQuad(VulkanContext& context, const scene::CameraMatrices& camera) {
    scene::Mesh mesh;
    for (const QuadCorner& corner : fullScreenQuad(camera)) {
        mesh.positions.push_back(corner.position);
        mesh.normals.push_back(corner.ray);
        mesh.tangents.emplace_back(1.0f, 0.0f, 0.0f, 1.0f);
        mesh.uvs.push_back(corner.uv);
    }
    mesh.indices = {0, 1, 2, 0, 2, 3};
    return uploadMesh(context, mesh);
}

}  // namespace

struct DeferredRenderer::State : RendererBase {
    std::string lightShader;
    UniqueHandle<VkSampler> nearest;
    std::optional<GpuMesh> sphereVolume, pyramidVolume;
    CameraTargetCache<DeferredTargets> targets;

    Result<const VariantPipeline*> pipeline(const Pack* pack, const VariantView& variant,
                                            const pack::PackRenderState& state, Phase phase,
                                            const DeferredTargets& target, bool hdr);
};

Result<const VariantPipeline*> DeferredRenderer::State::pipeline(
    const Pack* pack, const VariantView& variant, const pack::PackRenderState& state, Phase phase,
    const DeferredTargets& target, bool hdr) {
    PipelineTarget pipelineTarget;
    switch (phase) {
        case Phase::GBuffer:
            pipelineTarget = {target.gbuffer().renderPass(LoadOp::Clear), true,
                              target.gbuffer().colorAttachmentCount()};
            break;
        case Phase::Light:
            pipelineTarget = {target.lightPass(), true, 1};
            break;
        case Phase::Decode:
            pipelineTarget = {target.decodePass(), true, 1};
            break;
    }
    uint32_t targetKind = static_cast<uint32_t>(phase) * 2 + (hdr ? 1u : 0u);
    return RendererBase::pipeline(pack, variant, state, pipelineTarget, targetKind);
}

DeferredRenderer::DeferredRenderer(std::unique_ptr<State> state) : mState(std::move(state)) {}
DeferredRenderer::DeferredRenderer(DeferredRenderer&&) noexcept = default;
DeferredRenderer& DeferredRenderer::operator=(DeferredRenderer&&) noexcept = default;
DeferredRenderer::~DeferredRenderer() = default;

Result<DeferredRenderer> DeferredRenderer::create(VulkanContext& context,
                                                  std::vector<const Pack*> packs,
                                                  std::string lightShader) {
    auto state = std::make_unique<State>();
    if (Status ready = state->init(context, std::move(packs)); !ready) return ready.error();
    state->lightShader = std::move(lightShader);
    SamplerDesc nearest;
    nearest.filter = VK_FILTER_NEAREST;
    nearest.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    nearest.addressMode = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    nearest.maxLod = 0.0f;
    nearest.name = "deferred G-buffer sampler";
    auto sampler = createSampler(context, nearest);
    if (!sampler) return sampler.error();
    state->nearest = std::move(*sampler);
    auto sphere = uploadMesh(context, unitSphereVolume());
    if (!sphere) return sphere.error();
    state->sphereVolume.emplace(std::move(*sphere));
    auto pyramid = uploadMesh(context, unitPyramidVolume());
    if (!pyramid) return pyramid.error();
    state->pyramidVolume.emplace(std::move(*pyramid));
    return DeferredRenderer(std::move(state));
}

namespace {

// Everything one frame's draws point at, kept alive until the frame is submitted.
struct FrameData {
    std::deque<ShaderValues> values;
    std::deque<std::map<std::string, std::string>> materialTextures;
    std::optional<GpuMesh> quad;
    std::vector<Draw> gbufferDraws, lightDraws, decodeDraws;
};

ShaderValues lightPassMaterial(bool hdr) {
    ShaderValues material;
    // Unity's BlendMode numbers: Zero 0, One 1, DstColor 2.
    material.set("_SrcBlend", hdr ? 1.0f : 2.0f);
    material.set("_DstBlend", hdr ? 1.0f : 0.0f);
    material.set("_StencilNonBackground", kStencilNonBackground);
    return material;
}

// The faces and depth test a light volume is drawn with (LightVolume.h); the engine's choice, as
// in Unity, which overrides the light pass's own Cull and ZTest for volumes.
void applyVolumeState(LightVolumeDraw draw, pack::PackRenderState& state) {
    switch (draw) {
        case LightVolumeDraw::FullScreenQuad:
            break;
        case LightVolumeDraw::FrontFaces:
            state.cull.value = pack::CullMode::Back;
            state.zTest.value = pack::CompareFunction::LessEqual;
            break;
        case LightVolumeDraw::BackFaces:
            state.cull.value = pack::CullMode::Front;
            state.zTest.value = pack::CompareFunction::GreaterEqual;
            break;
    }
}

}  // namespace

Result<RenderedFrame> DeferredRenderer::render(const scene::Scene& scene) {
    State& s = *mState;
    if (scene.camera.path != scene::RenderPath::Deferred) {
        return makeError(ErrorCode::InvalidInput,
                         "DeferredRenderer renders scenes with camera path 'deferred'");
    }
    auto target = s.targets.get(scene.camera, [&](const scene::Camera& camera) {
        return DeferredTargets::create(*s.context, camera);
    });
    if (!target) return target.error();
    const DeferredTargets& targets = **target;
    const bool hdr = scene.camera.hdr;
    scene::CameraMatrices matrices = scene::cameraMatrices(scene.camera);
    const BuiltinTextures& builtin = *s.textures;
    FrameData frameData;
    const ShaderValues& camera = frameData.values.emplace_back(cameraValues(scene, matrices));
    RenderedFrame frame;

    // G-buffer pass: every object, SH = the flat ambient (all lights are deferred lights).
    const scene::ForwardLightAssignment noLights;
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const scene::Object& object = scene.objects[o];
        std::string what = objectLabel(o, object);
        const Pack* pack = nullptr;
        std::optional<ShaderView> shader = s.findShader(object.material.shader, &pack);
        if (!shader) return makeError(ErrorCode::NotFound, what + ": no pack has this shader");
        std::optional<PassView> pass = shader->pass(std::string_view("Deferred"));
        if (!pass)
            return makeError(ErrorCode::NotFound, what + ": the shader has no Deferred pass");
        std::vector<std::string> keywords;
        if (hdr) keywords.push_back(variants::kHdrKeyword);
        auto variant = pass->lookup(keywords, variants::SelectionPolicy::Closest);
        if (!variant) return makeError(variant.error().code, what + ": " + variant.error().detail);
        std::map<std::string, std::string>& textureNames =
            frameData.materialTextures.emplace_back();
        ShaderValues& material = frameData.values.emplace_back(materialValues(
            withPropertyDefaults(object.material, shader->properties()), textureNames));
        if (Status loaded = s.loadTextureFiles(textureNames); !loaded)
            return makeError(loaded.error().code, what + ": " + loaded.error().detail);
        if (!material.find("_StencilNonBackground"))
            material.set("_StencilNonBackground", kStencilNonBackground);
        pack::PackRenderState state = forObjectTransform(
            resolveRenderState(pass->renderState(), material), object.transform.localToWorld());
        auto pipeline = s.pipeline(pack, *variant, state, Phase::GBuffer, targets, hdr);
        if (!pipeline)
            return makeError(pipeline.error().code, what + ": " + pipeline.error().detail);
        const ShaderValues& objectLayer =
            frameData.values.emplace_back(objectValues(scene, object, matrices, noLights));
        Draw draw;
        draw.pipeline = *pipeline;
        draw.mesh = &s.meshes.at(object.mesh);
        draw.layers = {nullptr, &objectLayer, &material, &camera};
        draw.textures = [&s, &textureNames](
                            std::string_view name,
                            pack::ResourceDim dim) -> std::optional<TextureBinding> {
            auto it = textureNames.find(std::string(name));
            return s.materialTexture(it == textureNames.end() ? "white" : it->second, dim);
        };
        frameData.gbufferDraws.push_back(std::move(draw));
        frame.variants.push_back(variant->describe());
    }

    auto quad = uploadQuad(*s.context, matrices);
    if (!quad) return quad.error();
    frameData.quad.emplace(std::move(*quad));
    const ShaderValues& quadLayer = frameData.values.emplace_back(fullScreenQuadValues(matrices));
    const ShaderValues& lightMaterial = frameData.values.emplace_back(lightPassMaterial(hdr));
    const Pack* lightPack = nullptr;
    std::optional<ShaderView> lightShader = s.findShader(s.lightShader, &lightPack);
    if (!lightShader && (!scene.lights.empty() || !hdr)) {
        return makeError(ErrorCode::NotFound,
                         "deferred light shader \"" + s.lightShader + "\": no pack has it");
    }
    const RenderTarget& g = targets.gbuffer();
    TextureBinding depth{g.depthSampleView(), s.nearest.get(),
                         VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL};
    TextureBinding gbuffer0{g.colorView(kGBufferDiffuse), s.nearest.get()};
    TextureBinding gbuffer1{g.colorView(kGBufferSpecular), s.nearest.get()};
    TextureBinding gbuffer2{g.colorView(kGBufferNormal), s.nearest.get()};
    if (Status cookies = s.loadCookieFiles(scene.lights); !cookies) return cookies.error();
    for (size_t l = 0; l < scene.lights.size(); ++l) {
        const scene::Light& light = scene.lights[l];
        std::string what = "light " + std::to_string(l) + " (shader \"" + s.lightShader + "\")";
        std::optional<PassView> pass = lightShader->pass(size_t{0});
        if (!pass) return makeError(ErrorCode::NotFound, what + ": the shader has no pass 0");
        variants::LightDescription description;
        description.type = toVariantLight(light.type);
        description.cookie = light.hasCookie();
        description.hdr = hdr;
        auto variant = pass->lookup(description, variants::SelectionPolicy::Closest);
        if (!variant) return makeError(variant.error().code, what + ": " + variant.error().detail);
        pack::PackRenderState state = resolveRenderState(pass->renderState(), lightMaterial);
        const LightVolume volume = chooseLightVolume(light, scene.camera, matrices);
        applyVolumeState(volume.draw, state);
        auto pipeline = s.pipeline(lightPack, *variant, state, Phase::Light, targets, hdr);
        if (!pipeline)
            return makeError(pipeline.error().code, what + ": " + pipeline.error().detail);
        const bool asQuad = volume.draw == LightVolumeDraw::FullScreenQuad;
        const ShaderValues& lightLayer =
            frameData.values.emplace_back(deferredLightValues(light, asQuad));
        Draw draw;
        draw.pipeline = *pipeline;
        if (asQuad) {
            draw.mesh = &*frameData.quad;
            draw.layers = {&lightLayer, &quadLayer, &lightMaterial, &camera};
        } else {
            draw.mesh = volume.mesh == &unitSphereVolume() ? &*s.sphereVolume : &*s.pyramidVolume;
            const ShaderValues& volumeLayer =
                frameData.values.emplace_back(lightVolumeValues(volume.objectToWorld));
            draw.layers = {&lightLayer, &volumeLayer, &lightMaterial, &camera};
        }
        scene::LightType type = light.type;
        bool cookie = light.cookie != "none";
        draw.textures = [&s, &builtin, &light, type, cookie, depth, gbuffer0, gbuffer1, gbuffer2](
                            std::string_view name,
                            pack::ResourceDim dim) -> std::optional<TextureBinding> {
            if (name == "_LightTexture0") {
                if (auto file = s.cookieFile(light)) return file;
            }
            if (name == "_CameraDepthTexture") return depth;
            if (name == "_CameraGBufferTexture0") return gbuffer0;
            if (name == "_CameraGBufferTexture1") return gbuffer1;
            if (name == "_CameraGBufferTexture2") return gbuffer2;
            if (auto texture = builtin.lightTexture(name, dim, type, cookie, true)) return texture;
            return builtin.named("white", dim);
        };
        frameData.lightDraws.push_back(std::move(draw));
        frame.variants.push_back(variant->describe());
    }

    if (!hdr) {
        std::optional<PassView> pass = lightShader->pass(size_t{1});
        if (!pass)
            return makeError(ErrorCode::NotFound,
                             "deferred light shader \"" + s.lightShader + "\" has no pass 1");
        auto variant = pass->lookup(std::vector<std::string>{}, variants::SelectionPolicy::Closest);
        if (!variant)
            return makeError(variant.error().code, "LDR decode: " + variant.error().detail);
        pack::PackRenderState state = resolveRenderState(pass->renderState(), lightMaterial);
        // The decoded alpha is −log2(1) = 0 (the light buffer's alpha stays 1): keep the clear
        // alpha.
        state.colorMask.value =
            pack::kColorWriteRed | pack::kColorWriteGreen | pack::kColorWriteBlue;
        auto pipeline = s.pipeline(lightPack, *variant, state, Phase::Decode, targets, hdr);
        if (!pipeline)
            return makeError(pipeline.error().code, "LDR decode: " + pipeline.error().detail);
        Draw draw;
        draw.pipeline = *pipeline;
        draw.mesh = &*frameData.quad;
        draw.layers = {nullptr, &quadLayer, &lightMaterial, &camera};
        TextureBinding lightBuffer{g.colorView(kGBufferLight), s.nearest.get()};
        draw.textures = [&builtin, lightBuffer](
                            std::string_view name,
                            pack::ResourceDim dim) -> std::optional<TextureBinding> {
            if (name == "_LightBuffer") return lightBuffer;
            return builtin.named("white", dim);
        };
        frameData.decodeDraws.push_back(std::move(draw));
        frame.variants.push_back(variant->describe());
    }

    Status bound = Ok{};
    // Records each pass's draws; after a bind error the later passes stay empty.
    auto record = [&](VkCommandBuffer commands, const std::vector<Draw>& draws) {
        if (bound) bound = recordDraws(commands, *s.resources, draws, frame.draws);
    };
    Status submitted = s.context->submitAndWait([&](VkCommandBuffer commands) {
        VkViewport viewport = g.viewport();
        VkRect2D area = g.area();
        g.begin(commands, LoadOp::Clear);
        vkCmdSetViewport(commands, 0, 1, &viewport);
        vkCmdSetScissor(commands, 0, 1, &area);
        record(commands, frameData.gbufferDraws);
        g.end(commands);
        targets.toLighting(commands);
        targets.beginLightPass(commands);
        vkCmdSetViewport(commands, 0, 1, &viewport);
        vkCmdSetScissor(commands, 0, 1, &area);
        record(commands, frameData.lightDraws);
        vkCmdEndRenderPass(commands);
        if (!hdr) {
            targets.toDecode(commands);
            targets.beginDecodePass(commands);
            vkCmdSetViewport(commands, 0, 1, &viewport);
            vkCmdSetScissor(commands, 0, 1, &area);
            record(commands, frameData.decodeDraws);
            vkCmdEndRenderPass(commands);
            targets.fromDecode(commands);
        }
        targets.fromLighting(commands);
    });
    if (Status reset = s.resources->reset(); !reset) return reset.error();
    if (!bound) return bound.error();
    if (!submitted) return submitted.error();
    auto image =
        hdr ? g.readback(*s.context, kGBufferLight) : targets.output()->readback(*s.context);
    if (!image) return image.error();
    frame.image = std::move(*image);
    return frame;
}

void DeferredRenderer::usePipelineCache(VkPipelineCache cache) { mState->pipelineCache = cache; }

}  // namespace varc::runtime
