// SPDX-License-Identifier: Apache-2.0
// What the forward, deferred and single-pass renderers share: the packs and how shaders are
// found in them, the built-in textures and meshes, per-frame draw resources, the pipelines
// created so far (one per variant, resolved render state and kind of target), how errors name
// objects, and the drawing of a one-pass frame.
#pragma once

#include <array>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "Draw.h"
#include "GpuMesh.h"
#include "varc/reader/Pack.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ShaderView.h"
#include "varc/reader/VariantRequests.h"
#include "varc/reader/VariantView.h"
#include "varc/render/BuiltinTextures.h"
#include "varc/render/DrawResources.h"
#include "varc/render/Renderer.h"
#include "varc/render/ShaderValues.h"
#include "varc/render/VariantPipeline.h"
#include "varc/scene/Scene.h"
#include "varc/variants/LightKeywords.h"
#include "varc/vulkan/RenderTarget.h"
#include "varc/vulkan/Texture.h"

namespace varc::render {

// The keyword model's name for a scene light type.
variants::LightType toVariantLight(scene::LightType type);
// The keyword model's name for a light's shadow type.
variants::ShadowMode toVariantShadows(scene::ShadowType type);

// How errors name scene object |index|: `object 2 'floor' (shader "varc/Forward")` (the name in
// quotes only when the object has one).
std::string objectLabel(size_t index, const scene::Object& object);

// Storage for what one frame's draws point at. Deques: pointers stay valid as they grow.
struct FrameStorage {
    std::deque<ShaderValues> values;
    std::deque<std::map<std::string, std::string>> materialTextures;  // property -> texture name
};

// An object's material as its draws bind it (RendererBase::objectMaterial), in FrameStorage.
struct ObjectMaterial {
    const ShaderValues* values = nullptr;
    const std::map<std::string, std::string>* textureNames = nullptr;  // property -> texture
};

// One object drawn with one variant of one pass: what RendererBase::objectDraw needs.
struct ObjectDrawRequest {
    std::string what;  // how errors name the object (objectLabel)
    const reader::Pack* pack = nullptr;
    const reader::PassView* pass = nullptr;
    const reader::VariantView* variant = nullptr;
    ObjectMaterial material;
    glm::mat4 localToWorld{1.0f};  // a negative determinant culls the other side
    scene::MeshKind mesh = scene::MeshKind::Sphere;
    PipelineTarget target;
    uint32_t targetKind = 0;  // see RendererBase::pipeline
    bool mirroredView = false;  // the view mirrors the image (some cube map faces): flips it again
};

struct RendererBase {
    vulkan::VulkanContext* context = nullptr;
    std::vector<const reader::Pack*> packs;
    std::optional<BuiltinTextures> textures;
    std::optional<DrawResources> resources;
    std::map<scene::MeshKind, GpuMesh> meshes;
    VkPipelineCache pipelineCache = VK_NULL_HANDLE;  // optional, see usePipelineCache()
    reader::VariantRequests* variantRequests = nullptr;  // optional, see useVariantRequests()
    variants::SelectionPolicy missPolicy = variants::SelectionPolicy::Closest;

    // Creates the textures, draw resources and built-in meshes.
    Status init(vulkan::VulkanContext& context, std::vector<const reader::Pack*> packs);

    // The variant of |pass| for |key| (or |light| with |materialKey|) under |policy|, through
    // variantRequests when the renderer has them (Renderer::useVariantRequests); Closest means
    // missPolicy. The one way draws choose variants, so every request is recorded.
    Result<reader::VariantView> variantFor(const reader::PassView& pass,
                                           const variants::VariantKey& key,
                                           variants::SelectionPolicy policy) const;
    Result<reader::VariantView> variantFor(const reader::PassView& pass,
                                           const variants::LightDescription& light,
                                           variants::SelectionPolicy policy,
                                           const variants::VariantKey& materialKey = {}) const;

    // The shader called |name| in the first pack that has it (|owner| set to that pack).
    std::optional<reader::ShaderView> findShader(const std::string& name,
                                                 const reader::Pack** owner) const;

    // The shader of |object| (findShader); the error "<what>: no pack has this shader".
    Result<reader::ShaderView> objectShader(const std::string& what, const scene::Object& object,
                                            const reader::Pack** owner) const;

    // The material an object's draws bind: |material|'s values completed with the shader's
    // Properties |defaults|, then with |engineDefaults| (values the engine supplies when the
    // material does not set them, e.g. a stencil bit), and the shader's |dynamicKeywords|
    // (ShaderView::dynamicKeywords) set from the material's keywords (setDynamicBranchValues);
    // its PNG textures loaded. Stored in |frame|. Errors, prefixed with |what|: a texture file
    // that cannot be read.
    Result<ObjectMaterial> objectMaterial(
        const std::string& what, const scene::Material& material,
        const std::vector<pack::ShaderProperty>& defaults,
        const std::vector<std::string>& dynamicKeywords, FrameStorage& frame,
        const std::vector<std::pair<std::string, float>>& engineDefaults = {});

    // The per-object step of every renderer: resolves the pass's render state with the material
    // and mirrors it for the transform, gets the pipeline, and returns a Draw of the object's
    // mesh with that pipeline, the material as its material layer (layers[2]) and the material's
    // textures as its texture lookup (unset textures are white). Errors, prefixed with
    // |request.what|: pipeline creation.
    Result<Draw> objectDraw(const ObjectDrawRequest& request);

    // The pipeline of |variant| with |state| for |target|, created on first use. Pipelines are
    // reused for any render pass compatible with the one they were made for; |targetKind| tells
    // apart targets whose formats differ (HDR/LDR, G-buffer/light/decode passes).
    Result<const VariantPipeline*> pipeline(const reader::Pack* pack,
                                            const reader::VariantView& variant,
                                            const pack::PackRenderState& state,
                                            const PipelineTarget& target, uint32_t targetKind);

    // Records |draws| into one cleared render pass of |target| (viewport and scissor: the whole
    // target), submits and waits, resets the draw resources, then reads the colour back into
    // |frame|.image; adds the draws recorded to |frame|.draws. Errors, first that applies: the
    // reset's, the first bind error (recordDraws), the submit's, the readback's.
    Status drawFrame(const vulkan::RenderTarget& target, const std::vector<Draw>& draws,
                     RenderedFrame& frame);

    // Loads each PNG file among |textureNames| (scene::isTextureFile) once per renderer, as an
    // sRGB texture without mipmaps, sampled linear with repeat. Errors name the file.
    Status loadTextureFiles(const std::map<std::string, std::string>& textureNames);

    // The texture a material property names: a built-in texture (BuiltinTextures::named) or a
    // PNG file loaded by loadTextureFiles (2D only); nullopt for anything else.
    std::optional<TextureBinding> materialTexture(const std::string& name,
                                                  pack::ResourceDim dim) const;

    // Loads the PNG cookie of each light that names one (scene::isTextureFile; its alpha is the
    // cookie, stored linear; the scene parser allows them on spot and directional lights only).
    // Errors: an unreadable file.
    Status loadCookieFiles(const std::vector<scene::Light>& lights);

    // The lightmap textures of |object| (SHADER_ABI.md §4.13, §6) for |name|: unity_Lightmap,
    // unity_DynamicLightmap, unity_LightmapInd, unity_DynamicDirectionality, unity_ShadowMask;
    // 1x1 linear float textures of its lightmap's colours, its PNG files (lightmapFile), or the
    // defaults (white; direction (0.5, 0.5, 1, 1)) where it has none. nullopt for any other
    // name. Created on first use; errors: an unreadable PNG (named), Vulkan.
    Result<std::optional<TextureBinding>> lightmapTexture(const scene::Object& object,
                                                          std::string_view name);
    // The lightmap PNG at |path|, loaded once as R8G8B8A8_UNORM (linear), sampled linear with
    // clamp to edge.
    Result<std::optional<TextureBinding>> lightmapFile(const std::string& path);

    // _LightTexture0 for |light| when it has a PNG cookie: clamped for spot lights, repeating for
    // directional ones; nullopt otherwise (the default cookies come from BuiltinTextures).
    std::optional<TextureBinding> cookieFile(const scene::Light& light) const;

private:
    struct CachedPipeline {
        const reader::Pack* pack;
        std::string variant;  // VariantView::describe()
        pack::PackRenderState state;
        uint32_t targetKind;
        VariantPipeline pipeline;
    };
    std::deque<CachedPipeline> mPipelines;         // a deque: returned pointers stay valid
    std::map<std::string, vulkan::Texture> mTextureFiles;  // material PNGs (sRGB), by path
    std::map<std::string, vulkan::Texture> mCookieFiles;   // cookie PNGs (UNORM), by path
    std::map<std::array<float, 4>, vulkan::Texture>
        mLightmaps;                                         // 1x1 float lightmap texels, by value
    std::map<std::string, vulkan::Texture> mLightmapFiles;  // lightmap PNGs (UNORM), by path
};

}  // namespace varc::render
