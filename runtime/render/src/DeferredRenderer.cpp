// SPDX-License-Identifier: Apache-2.0
#include "varc/render/DeferredRenderer.h"

#include <deque>
#include <map>
#include <optional>

#include "CameraTargetCache.h"
#include "DeferredTargets.h"
#include "Draw.h"
#include "FullScreenQuad.h"
#include "GpuMesh.h"
#include "RendererBase.h"
#include "ScreenShadowMasks.h"
#include "ShadowMaps.h"
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

namespace varc::render {

namespace {

// The stencil bit the G-buffer pass writes and the light and decode passes test (the shaders'
// Properties default; resolveRenderState only sees what the material sets).
constexpr float kStencilNonBackground = 128.0f;

enum class Phase { GBuffer, Light, Decode };

}  // namespace

// Everything one frame's draws point at, kept alive until the frame is submitted.
struct DeferredFrame {
    FrameStorage storage;
    const ShaderValues* camera = nullptr;
    const ShaderValues* quadLayer = nullptr;
    const ShaderValues* lightMaterial = nullptr;
    std::optional<GpuMesh> quad;
    std::vector<Draw> gbufferDraws, lightDraws, decodeDraws;
    RenderedFrame frame;
};

struct DeferredRenderer::State : RendererBase {
    std::string lightShader;
    vulkan::UniqueHandle<VkSampler> nearest;
    std::optional<GpuMesh> sphereVolume, pyramidVolume;
    CameraTargetCache<DeferredTargets> targets;
    ShadowMaps shadows;
    ScreenShadowMasks screenShadows;  // directional lights' masks (SHADOWS_SCREEN)

    // The pass and formats a pipeline of |phase| renders into, and its RendererBase target kind.
    static PipelineTarget pipelineTarget(Phase phase, const DeferredTargets& target);
    static uint32_t targetKind(Phase phase, bool hdr);

    // The G-buffer as the light pass samples it.
    struct GBufferBindings {
        TextureBinding depth, diffuse, specular, normal;
    };

    // The frame's phases, in order: each adds its draws to |frame|.
    Status gbufferPhase(const scene::Scene& scene, const scene::CameraMatrices& matrices,
                        const DeferredTargets& target, DeferredFrame& frame);
    Status lightPhase(const scene::Scene& scene, const std::optional<reader::ShaderView>& shader,
                      const reader::Pack* pack, const scene::CameraMatrices& matrices,
                      const DeferredTargets& target, DeferredFrame& frame);
    Status lightDraw(const scene::Scene& scene, size_t index, const reader::ShaderView& shader,
                     const reader::Pack* pack, const scene::CameraMatrices& matrices,
                     const DeferredTargets& target, const GBufferBindings& gbuffer,
                     DeferredFrame& frame);
    Status decodePhase(const std::optional<reader::ShaderView>& shader, const reader::Pack* pack,
                       const DeferredTargets& target, DeferredFrame& frame);
    // Records the three passes, submits, waits and reads the frame back.
    Status submit(const DeferredTargets& target, bool hdr, DeferredFrame& frame);
};

PipelineTarget DeferredRenderer::State::pipelineTarget(Phase phase, const DeferredTargets& target) {
    switch (phase) {
        case Phase::GBuffer:
            return {target.gbuffer().renderPass(vulkan::LoadOp::Clear), true,
                    target.gbuffer().colorAttachmentCount()};
        case Phase::Light:
            return {target.lightPass(), true, 1};
        case Phase::Decode:
            return {target.decodePass(), true, 1};
    }
    return {};
}

uint32_t DeferredRenderer::State::targetKind(Phase phase, bool hdr) {
    return static_cast<uint32_t>(phase) * 2 + (hdr ? 1u : 0u);
}

DeferredRenderer::DeferredRenderer(std::unique_ptr<State> state) : mState(std::move(state)) {}
DeferredRenderer::DeferredRenderer(DeferredRenderer&&) noexcept = default;
DeferredRenderer& DeferredRenderer::operator=(DeferredRenderer&&) noexcept = default;
DeferredRenderer::~DeferredRenderer() = default;

Result<DeferredRenderer> DeferredRenderer::create(vulkan::VulkanContext& context,
                                                  std::vector<const reader::Pack*> packs,
                                                  std::string lightShader) {
    auto state = std::make_unique<State>();
    if (Status ready = state->init(context, std::move(packs)); !ready) return ready.error();
    state->lightShader = std::move(lightShader);
    vulkan::SamplerDesc nearest;
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

Status DeferredRenderer::State::gbufferPhase(const scene::Scene& scene,
                                             const scene::CameraMatrices& matrices,
                                             const DeferredTargets& target, DeferredFrame& frame) {
    const bool hdr = scene.camera.hdr;
    std::vector<std::string> keywords;
    if (hdr) keywords.push_back(variants::kHdrKeyword);
    // SH = the flat ambient: every light is a deferred light.
    const scene::ForwardLightAssignment noLights;
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const scene::Object& object = scene.objects[o];
        const std::string what = objectLabel(o, object);
        const reader::Pack* pack = nullptr;
        auto shader = objectShader(what, object, &pack);
        if (!shader) return shader.error();
        std::optional<reader::PassView> pass = shader->pass(std::string_view("Deferred"));
        if (!pass)
            return makeError(ErrorCode::NotFound, what + ": the shader has no Deferred pass");
        // The camera's keyword and the material's (shader_feature variants).
        auto variant =
            variantFor(*pass, pass->keyOf(keywords) | pass->keyOf(object.material.keywords),
                       variants::SelectionPolicy::Closest);
        if (!variant) return makeError(variant.error().code, what + ": " + variant.error().detail);
        auto material = objectMaterial(what, object.material, shader->properties(),
                                       shader->dynamicKeywords(), frame.storage,
                                       {{"_StencilNonBackground", kStencilNonBackground}});
        if (!material) return material.error();
        auto draw = objectDraw(
            {what, pack, &*pass, &*variant, *material, object.transform.localToWorld(), object.mesh,
             pipelineTarget(Phase::GBuffer, target), targetKind(Phase::GBuffer, hdr)});
        if (!draw) return draw.error();
        const ShaderValues& objectLayer =
            frame.storage.values.emplace_back(objectValues(scene, object, matrices, noLights));
        draw->layers = {nullptr, &objectLayer, material->values, frame.camera};
        frame.gbufferDraws.push_back(std::move(*draw));
        frame.frame.variants.push_back(variant->describe());
    }
    return Ok{};
}

Status DeferredRenderer::State::lightDraw(const scene::Scene& scene, size_t index,
                                          const reader::ShaderView& shader,
                                          const reader::Pack* pack,
                                          const scene::CameraMatrices& matrices,
                                          const DeferredTargets& target,
                                          const GBufferBindings& gbuffer, DeferredFrame& frame) {
    const scene::Light& light = scene.lights[index];
    const bool hdr = scene.camera.hdr;
    const std::string what =
        "light " + std::to_string(index) + " (shader \"" + std::string(shader.name()) + "\")";
    std::optional<reader::PassView> pass = shader.pass(size_t{0});
    if (!pass) return makeError(ErrorCode::NotFound, what + ": the shader has no pass 0");
    variants::LightDescription description;
    description.type = toVariantLight(light.type);
    description.cookie = light.hasCookie();
    description.hdr = hdr;
    // Directional lights read their screen-space mask, the others their map.
    const std::optional<TextureBinding> shadowMap = light.type == scene::LightType::Directional
                                                        ? screenShadows.mask(index)
                                                        : shadows.map(index);
    if (shadowMap) description.shadows = toVariantShadows(light.shadows);
    auto variant = variantFor(*pass, description, variants::SelectionPolicy::Closest);
    if (!variant) return makeError(variant.error().code, what + ": " + variant.error().detail);
    pack::PackRenderState state = resolveRenderState(pass->renderState(), *frame.lightMaterial);
    const LightVolume volume = chooseLightVolume(light, scene.camera, matrices);
    applyVolumeState(volume.draw, state);
    auto created = pipeline(pack, *variant, state, pipelineTarget(Phase::Light, target),
                            targetKind(Phase::Light, hdr));
    if (!created) return makeError(created.error().code, what + ": " + created.error().detail);
    const bool asQuad = volume.draw == LightVolumeDraw::FullScreenQuad;
    ShaderValues& lightLayer = frame.storage.values.emplace_back(deferredLightValues(light, asQuad));
    shadows.addReceiverValues(scene, index, lightLayer);
    Draw draw;
    draw.pipeline = *created;
    if (asQuad) {
        draw.mesh = &*frame.quad;
        draw.layers = {&lightLayer, frame.quadLayer, frame.lightMaterial, frame.camera};
    } else {
        draw.mesh = volume.mesh == &unitSphereVolume() ? &*sphereVolume : &*pyramidVolume;
        const ShaderValues& volumeLayer =
            frame.storage.values.emplace_back(lightVolumeValues(volume.objectToWorld));
        draw.layers = {&lightLayer, &volumeLayer, frame.lightMaterial, frame.camera};
    }
    const bool cookie = light.cookie != "none";
    draw.textures = [this, &light, cookie, gbuffer, shadowMap](
                        std::string_view name,
                        pack::ResourceDim dim) -> std::optional<TextureBinding> {
        if (shadowMap && name == "_ShadowMapTexture") return shadowMap;
        if (name == "_LightTexture0") {
            if (auto file = cookieFile(light)) return file;
            if (light.cookie == "white") return textures->named("white", dim);
        }
        if (name == "_CameraDepthTexture") return gbuffer.depth;
        if (name == "_CameraGBufferTexture0") return gbuffer.diffuse;
        if (name == "_CameraGBufferTexture1") return gbuffer.specular;
        if (name == "_CameraGBufferTexture2") return gbuffer.normal;
        if (auto texture = textures->lightTexture(name, dim, light.type, cookie, true))
            return texture;
        return textures->named("white", dim);
    };
    frame.lightDraws.push_back(std::move(draw));
    frame.frame.variants.push_back(variant->describe());
    return Ok{};
}

Status DeferredRenderer::State::lightPhase(const scene::Scene& scene,
                                           const std::optional<reader::ShaderView>& shader,
                                           const reader::Pack* pack,
                                           const scene::CameraMatrices& matrices,
                                           const DeferredTargets& target, DeferredFrame& frame) {
    const vulkan::RenderTarget& g = target.gbuffer();
    const GBufferBindings gbuffer{
        {g.depthSampleView(), nearest.get(), VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL},
        {g.colorView(kGBufferDiffuse), nearest.get()},
        {g.colorView(kGBufferSpecular), nearest.get()},
        {g.colorView(kGBufferNormal), nearest.get()}};
    if (Status cookies = loadCookieFiles(scene.lights); !cookies) return cookies;
    for (size_t l = 0; l < scene.lights.size(); ++l) {
        Status drawn = lightDraw(scene, l, *shader, pack, matrices, target, gbuffer, frame);
        if (!drawn) return drawn;
    }
    return Ok{};
}

Status DeferredRenderer::State::decodePhase(const std::optional<reader::ShaderView>& shader,
                                            const reader::Pack* pack, const DeferredTargets& target,
                                            DeferredFrame& frame) {
    std::optional<reader::PassView> pass = shader->pass(size_t{1});
    if (!pass)
        return makeError(ErrorCode::NotFound,
                         "deferred light shader \"" + std::string(shader->name()) + "\" has no pass 1");
    auto variant = variantFor(*pass, variants::VariantKey{}, variants::SelectionPolicy::Closest);
    if (!variant) return makeError(variant.error().code, "LDR decode: " + variant.error().detail);
    pack::PackRenderState state = resolveRenderState(pass->renderState(), *frame.lightMaterial);
    // The decoded alpha is −log2(1) = 0 (the light buffer's alpha stays 1): keep the clear alpha.
    state.colorMask.value = pack::kColorWriteRed | pack::kColorWriteGreen | pack::kColorWriteBlue;
    auto created = pipeline(pack, *variant, state, pipelineTarget(Phase::Decode, target),
                            targetKind(Phase::Decode, false));
    if (!created) return makeError(created.error().code, "LDR decode: " + created.error().detail);
    Draw draw;
    draw.pipeline = *created;
    draw.mesh = &*frame.quad;
    draw.layers = {nullptr, frame.quadLayer, frame.lightMaterial, frame.camera};
    TextureBinding lightBuffer{target.gbuffer().colorView(kGBufferLight), nearest.get()};
    draw.textures = [this, lightBuffer](std::string_view name,
                                        pack::ResourceDim dim) -> std::optional<TextureBinding> {
        if (name == "_LightBuffer") return lightBuffer;
        return textures->named("white", dim);
    };
    frame.decodeDraws.push_back(std::move(draw));
    frame.frame.variants.push_back(variant->describe());
    return Ok{};
}

Status DeferredRenderer::State::submit(const DeferredTargets& target, bool hdr,
                                       DeferredFrame& frame) {
    const vulkan::RenderTarget& g = target.gbuffer();
    Status bound = Ok{};
    // Records each pass's draws; after a bind error the later passes stay empty.
    auto record = [&](VkCommandBuffer commands, const std::vector<Draw>& draws) {
        if (bound) bound = recordDraws(commands, *resources, draws, frame.frame.draws);
    };
    Status submitted = context->submitAndWait([&](VkCommandBuffer commands) {
        VkViewport viewport = g.viewport();
        VkRect2D area = g.area();
        g.begin(commands, vulkan::LoadOp::Clear);
        vkCmdSetViewport(commands, 0, 1, &viewport);
        vkCmdSetScissor(commands, 0, 1, &area);
        record(commands, frame.gbufferDraws);
        g.end(commands);
        target.toLighting(commands);
        target.beginLightPass(commands);
        vkCmdSetViewport(commands, 0, 1, &viewport);
        vkCmdSetScissor(commands, 0, 1, &area);
        record(commands, frame.lightDraws);
        vkCmdEndRenderPass(commands);
        if (!hdr) {
            target.toDecode(commands);
            target.beginDecodePass(commands);
            vkCmdSetViewport(commands, 0, 1, &viewport);
            vkCmdSetScissor(commands, 0, 1, &area);
            record(commands, frame.decodeDraws);
            vkCmdEndRenderPass(commands);
            target.fromDecode(commands);
        }
        target.fromLighting(commands);
    });
    if (Status reset = resources->reset(); !reset) return reset;
    if (!bound) return bound;
    if (!submitted) return submitted;
    auto image = hdr ? g.readback(*context, kGBufferLight) : target.output()->readback(*context);
    if (!image) return image.error();
    frame.frame.image = std::move(*image);
    return Ok{};
}

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
    const scene::CameraMatrices matrices = scene::cameraMatrices(scene.camera);
    DeferredFrame frame;
    if (Status shadowMaps = s.shadows.render(s, scene, frame.frame.variants); !shadowMaps)
        return shadowMaps.error();
    // The masks come from their own camera depth of the casters, as in forward (Unity's
    // deferred path reads the G-buffer's depth: the same wherever every object casts).
    if (Status masks = s.screenShadows.render(s, scene, s.shadows, matrices, frame.frame.variants);
        !masks) {
        return masks.error();
    }
    frame.camera = &frame.storage.values.emplace_back(cameraValues(scene, matrices));
    if (Status drawn = s.gbufferPhase(scene, matrices, targets, frame); !drawn)
        return drawn.error();

    auto quad = uploadFullScreenQuad(*s.context, matrices);
    if (!quad) return quad.error();
    frame.quad.emplace(std::move(*quad));
    frame.quadLayer = &frame.storage.values.emplace_back(fullScreenQuadValues(matrices));
    frame.lightMaterial = &frame.storage.values.emplace_back(lightPassMaterial(hdr));
    const reader::Pack* lightPack = nullptr;
    const std::string& lightShaderName =
        scene.camera.deferredShader.empty() ? s.lightShader : scene.camera.deferredShader;
    std::optional<reader::ShaderView> lightShader = s.findShader(lightShaderName, &lightPack);
    if (!lightShader && (!scene.lights.empty() || !hdr)) {
        return makeError(ErrorCode::NotFound,
                         "deferred light shader \"" + lightShaderName + "\": no pack has it");
    }
    if (Status lit = s.lightPhase(scene, lightShader, lightPack, matrices, targets, frame); !lit)
        return lit.error();
    if (!hdr) {
        Status decoded = s.decodePhase(lightShader, lightPack, targets, frame);
        if (!decoded) return decoded.error();
    }
    if (Status submitted = s.submit(targets, hdr, frame); !submitted) return submitted.error();
    return std::move(frame.frame);
}

void DeferredRenderer::usePipelineCache(VkPipelineCache cache) { mState->pipelineCache = cache; }

void DeferredRenderer::useVariantRequests(reader::VariantRequests* requests,
                                          variants::SelectionPolicy missPolicy) {
    mState->variantRequests = requests;
    mState->missPolicy = missPolicy;
}

}  // namespace varc::render
