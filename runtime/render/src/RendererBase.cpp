// SPDX-License-Identifier: Apache-2.0
#include "RendererBase.h"

#include "varc/image/Png.h"
#include "varc/reader/PassView.h"
#include "varc/render/RenderStateResolver.h"
#include "varc/render/SceneValues.h"
#include "varc/scene/Mesh.h"

namespace varc::render {

variants::ShadowMode toVariantShadows(scene::ShadowType type) {
    switch (type) {
        case scene::ShadowType::None: return variants::ShadowMode::None;
        case scene::ShadowType::Hard: return variants::ShadowMode::Hard;
        case scene::ShadowType::Soft: return variants::ShadowMode::Soft;
    }
    return variants::ShadowMode::None;
}

variants::LightType toVariantLight(scene::LightType type) {
    switch (type) {
        case scene::LightType::Directional:
            return variants::LightType::Directional;
        case scene::LightType::Point:
            return variants::LightType::Point;
        case scene::LightType::Spot:
            return variants::LightType::Spot;
    }
    return variants::LightType::Directional;
}

std::string objectLabel(size_t index, const scene::Object& object) {
    return "object " + std::to_string(index) +
           (object.name.empty() ? "" : " '" + object.name + "'") + " (shader \"" +
           object.material.shader + "\")";
}

Status RendererBase::init(vulkan::VulkanContext& vulkan,
                          std::vector<const reader::Pack*> inputPacks) {
    context = &vulkan;
    packs = std::move(inputPacks);
    auto builtin = BuiltinTextures::create(vulkan);
    if (!builtin) return builtin.error();
    textures.emplace(std::move(*builtin));
    auto drawResources = DrawResources::create(vulkan);
    if (!drawResources) return drawResources.error();
    resources.emplace(std::move(*drawResources));
    for (scene::MeshKind kind :
         {scene::MeshKind::Sphere, scene::MeshKind::Cube, scene::MeshKind::Plane}) {
        auto mesh = uploadMesh(vulkan, scene::builtinMesh(kind));
        if (!mesh) return mesh.error();
        meshes.emplace(kind, std::move(*mesh));
    }
    return Ok{};
}

Result<reader::VariantView> RendererBase::variantFor(const reader::PassView& pass,
                                                     const variants::VariantKey& key,
                                                     variants::SelectionPolicy policy) const {
    if (policy == variants::SelectionPolicy::Closest) policy = missPolicy;
    if (variantRequests) return variantRequests->resolve(pass, key, policy);
    return pass.lookup(key, policy);
}

Result<reader::VariantView> RendererBase::variantFor(
    const reader::PassView& pass, const variants::LightDescription& light,
    variants::SelectionPolicy policy, const variants::VariantKey& materialKey) const {
    if (policy == variants::SelectionPolicy::Closest) policy = missPolicy;
    if (variantRequests) return variantRequests->resolve(pass, light, policy, materialKey);
    return pass.lookup(light, policy, materialKey);
}

std::optional<reader::ShaderView> RendererBase::findShader(const std::string& name,
                                                           const reader::Pack** owner) const {
    for (const reader::Pack* pack : packs) {
        if (auto shader = pack->findShader(name)) {
            *owner = pack;
            return shader;
        }
    }
    return std::nullopt;
}

Result<reader::ShaderView> RendererBase::objectShader(const std::string& what,
                                                      const scene::Object& object,
                                                      const reader::Pack** owner) const {
    std::optional<reader::ShaderView> shader = findShader(object.material.shader, owner);
    if (!shader) return makeError(ErrorCode::NotFound, what + ": no pack has this shader");
    return *shader;
}

Result<ObjectMaterial> RendererBase::objectMaterial(
    const std::string& what, const scene::Material& material,
    const std::vector<pack::ShaderProperty>& defaults,
    const std::vector<std::string>& dynamicKeywords, FrameStorage& frame,
    const std::vector<std::pair<std::string, float>>& engineDefaults) {
    std::map<std::string, std::string>& textureNames = frame.materialTextures.emplace_back();
    ShaderValues& values = frame.values.emplace_back(
        materialValues(withPropertyDefaults(material, defaults), textureNames));
    for (const auto& [name, value] : engineDefaults) {
        if (!values.find(name)) values.set(name, value);
    }
    setDynamicBranchValues(values, dynamicKeywords, material.keywords);
    if (Status loaded = loadTextureFiles(textureNames); !loaded)
        return makeError(loaded.error().code, what + ": " + loaded.error().detail);
    return ObjectMaterial{&values, &textureNames};
}

Result<Draw> RendererBase::objectDraw(const ObjectDrawRequest& request) {
    const ShaderValues& material = *request.material.values;
    // A mirroring view turns the winding around once more: the same flip a mirrored object gets.
    glm::mat4 handedness(1.0f);
    if (request.mirroredView) handedness[0][0] = -1.0f;
    pack::PackRenderState state =
        forObjectTransform(resolveRenderState(request.pass->renderState(), material),
                           request.localToWorld * handedness);
    auto created =
        pipeline(request.pack, *request.variant, state, request.target, request.targetKind);
    if (!created)
        return makeError(created.error().code, request.what + ": " + created.error().detail);
    Draw draw;
    draw.pipeline = *created;
    draw.mesh = &meshes.at(request.mesh);
    draw.layers[2] = &material;
    draw.textures = [this, textureNames = request.material.textureNames](
                        std::string_view name,
                        pack::ResourceDim dim) -> std::optional<TextureBinding> {
        auto it = textureNames->find(std::string(name));
        return materialTexture(it == textureNames->end() ? "white" : it->second, dim);
    };
    return draw;
}

Result<const VariantPipeline*> RendererBase::pipeline(const reader::Pack* pack,
                                                      const reader::VariantView& variant,
                                                      const pack::PackRenderState& state,
                                                      const PipelineTarget& target,
                                                      uint32_t targetKind) {
    std::string name = variant.describe();
    for (const CachedPipeline& cached : mPipelines) {
        if (cached.pack == pack && cached.targetKind == targetKind && cached.variant == name &&
            cached.state == state) {
            return &cached.pipeline;
        }
    }
    auto created = VariantPipeline::create(*context, variant, state, target, pipelineCache);
    if (!created) return created.error();
    mPipelines.push_back({pack, name, state, targetKind, std::move(*created)});
    return &mPipelines.back().pipeline;
}

Status RendererBase::drawFrame(const vulkan::RenderTarget& target, const std::vector<Draw>& draws,
                               RenderedFrame& frame) {
    Status bound = Ok{};
    Status submitted = context->submitAndWait([&](VkCommandBuffer commands) {
        target.begin(commands, vulkan::LoadOp::Clear);
        VkViewport viewport = target.viewport();
        VkRect2D area = target.area();
        vkCmdSetViewport(commands, 0, 1, &viewport);
        vkCmdSetScissor(commands, 0, 1, &area);
        bound = recordDraws(commands, *resources, draws, frame.draws);
        target.end(commands);
    });
    if (Status reset = resources->reset(); !reset) return reset.error();
    if (!bound) return bound.error();
    if (!submitted) return submitted.error();
    auto image = target.readback(*context);
    if (!image) return image.error();
    frame.image = std::move(*image);
    return Ok{};
}

Status RendererBase::loadTextureFiles(const std::map<std::string, std::string>& textureNames) {
    for (const auto& [property, name] : textureNames) {
        if (!scene::isTextureFile(name) || mTextureFiles.count(name)) continue;
        auto image = image::readPng(name);
        if (!image) {
            return makeError(image.error().code,
                             "texture " + property + " = '" + name + "': " + image.error().detail);
        }
        vulkan::TextureOptions options;
        options.srgb = true;  // colour textures hold sRGB-encoded values, as Unity imports them
        options.name = name;
        auto texture = vulkan::Texture::create2D(*context, *image, options);
        if (!texture) return texture.error();
        mTextureFiles.emplace(name, std::move(*texture));
    }
    return Ok{};
}

std::optional<TextureBinding> RendererBase::materialTexture(const std::string& name,
                                                            pack::ResourceDim dim) const {
    if (auto builtin = textures->named(name, dim)) return builtin;
    auto file = mTextureFiles.find(name);
    if (file == mTextureFiles.end() || dim != pack::ResourceDim::Dim2D) return std::nullopt;
    return TextureBinding{file->second.view(), textures->repeatSampler()};
}

Status RendererBase::loadCookieFiles(const std::vector<scene::Light>& lights) {
    for (const scene::Light& light : lights) {
        if (!scene::isTextureFile(light.cookie) || mCookieFiles.count(light.cookie)) continue;
        auto image = image::readPng(light.cookie);
        if (!image) return makeError(image.error().code, "cookie: " + image.error().detail);
        vulkan::TextureOptions options;  // UNORM: a cookie's alpha is an attenuation, not a colour
        options.name = light.cookie;
        auto texture = vulkan::Texture::create2D(*context, *image, options);
        if (!texture) return texture.error();
        mCookieFiles.emplace(light.cookie, std::move(*texture));
    }
    return Ok{};
}

Result<std::optional<TextureBinding>> RendererBase::lightmapTexture(const scene::Object& object,
                                                                   std::string_view name) {
    const scene::Lightmap lightmap = object.lightmap.value_or(scene::Lightmap{});
    const glm::vec4 defaultDirection(0.5f, 0.5f, 1.0f, 1.0f);
    glm::vec4 texel(1.0f);
    const std::string* file = nullptr;
    if (name == "unity_Lightmap") {
        texel = glm::vec4(lightmap.baked.value_or(glm::vec3(1.0f)), 1.0f);
        file = &lightmap.bakedFile;
    } else if (name == "unity_DynamicLightmap") {
        texel = glm::vec4(lightmap.realtime.value_or(glm::vec3(1.0f)), 1.0f);
        file = &lightmap.realtimeFile;
    } else if (name == "unity_LightmapInd" || name == "unity_DynamicDirectionality") {
        texel = defaultDirection;
        if (lightmap.directional) {
            texel = glm::vec4(glm::vec3(*lightmap.directional) * 0.5f + 0.5f,
                              lightmap.directional->w);
        }
        file = &lightmap.directionalFile;
    } else if (name == "unity_ShadowMask") {
        texel = lightmap.shadowmask;
        file = &lightmap.shadowmaskFile;
    } else {
        return std::optional<TextureBinding>();
    }
    if (!file->empty()) return lightmapFile(*file);
    const std::array<float, 4> key{texel.r, texel.g, texel.b, texel.a};
    auto found = mLightmaps.find(key);
    if (found == mLightmaps.end()) {
        image::Image image(1, 1, image::PixelFormat::RgbaFloat);
        image.setPixelFloat(0, 0, key);
        vulkan::TextureOptions options;
        options.name = std::string(name);
        auto texture = vulkan::Texture::create2D(*context, image, options);
        if (!texture) return texture.error();
        found = mLightmaps.emplace(key, std::move(*texture)).first;
    }
    return std::optional<TextureBinding>(
        TextureBinding{found->second.view(), textures->clampSampler()});
}

Result<std::optional<TextureBinding>> RendererBase::lightmapFile(const std::string& path) {
    auto found = mLightmapFiles.find(path);
    if (found == mLightmapFiles.end()) {
        auto image = image::readPng(path);
        if (!image) return makeError(image.error().code, "lightmap: " + image.error().detail);
        vulkan::TextureOptions options;  // UNORM: the values as stored, linear
        options.name = path;
        auto texture = vulkan::Texture::create2D(*context, *image, options);
        if (!texture) return texture.error();
        found = mLightmapFiles.emplace(path, std::move(*texture)).first;
    }
    return std::optional<TextureBinding>(
        TextureBinding{found->second.view(), textures->clampSampler()});
}

std::optional<TextureBinding> RendererBase::cookieFile(const scene::Light& light) const {
    if (!scene::isTextureFile(light.cookie)) return std::nullopt;
    auto file = mCookieFiles.find(light.cookie);
    if (file == mCookieFiles.end()) return std::nullopt;
    VkSampler sampler =
        light.type == scene::LightType::Spot ? textures->clampSampler() : textures->repeatSampler();
    return TextureBinding{file->second.view(), sampler};
}

}  // namespace varc::render
