// SPDX-License-Identifier: Apache-2.0
// A small engine on an installed varc: open a pack, look a variant up by light, create its Vulkan
// pipeline on lavapipe, draw one frame of a scene and write it as a PNG.
//
//   varc_engine PACK SCENE.json OUT.png
//
// Built against the installed package only: find_package(varc) and varc::runtime (the pack
// reader) plus varc::render (varc's Vulkan renderers). See README.md beside this file.
#include <iostream>
#include <string>
#include <vector>

#include "varc/image/Png.h"
#include "varc/reader/Pack.h"
#include "varc/render/RenderStateResolver.h"
#include "varc/render/SceneRenderer.h"
#include "varc/render/VariantPipeline.h"
#include "varc/scene/Scene.h"
#include "varc/vulkan/RenderTarget.h"
#include "varc/vulkan/VulkanContext.h"

namespace {

using varc::Result;
using varc::Status;

int fail(const std::string& detail) {
    std::cerr << "varc_engine: error: " << detail << "\n";
    return 1;
}

// What the pack's light lookup needs to know about a scene light: Unity's built-in pipeline
// turns it into the keywords of the pass (DIRECTIONAL, POINT_COOKIE, SHADOWS_SCREEN, ...).
varc::variants::LightDescription describeLight(const varc::scene::Light& light, bool hdr) {
    varc::variants::LightDescription description;
    switch (light.type) {
        case varc::scene::LightType::Directional:
            description.type = varc::variants::LightType::Directional;
            break;
        case varc::scene::LightType::Point:
            description.type = varc::variants::LightType::Point;
            break;
        case varc::scene::LightType::Spot:
            description.type = varc::variants::LightType::Spot;
            break;
    }
    description.cookie = light.cookie != "none";
    description.shadows =
        light.shadows == varc::scene::ShadowType::None   ? varc::variants::ShadowMode::None
        : light.shadows == varc::scene::ShadowType::Hard ? varc::variants::ShadowMode::Hard
                                                         : varc::variants::ShadowMode::Soft;
    description.hdr = hdr;
    return description;
}

// The variant the ForwardBase pass of the first object's shader draws the scene's first light
// with: the lookup an engine does per object and light, without any Vulkan.
Result<varc::reader::VariantView> lookUpMainVariant(const varc::reader::Pack& pack,
                                                    const varc::scene::Scene& scene) {
    using varc::ErrorCode;
    if (scene.objects.empty() || scene.lights.empty())
        return varc::makeError(ErrorCode::InvalidInput, "the scene needs an object and a light");
    const std::string& shaderName = scene.objects.front().material.shader;
    std::optional<varc::reader::ShaderView> shader = pack.findShader(shaderName);
    if (!shader) return varc::makeError(ErrorCode::NotFound, "no shader '" + shaderName + "'");
    std::optional<varc::reader::PassView> pass = shader->pass("ForwardBase");
    if (!pass) return varc::makeError(ErrorCode::NotFound, shaderName + " has no ForwardBase pass");
    return pass->lookup(describeLight(scene.lights.front(), scene.camera.hdr),
                        varc::variants::SelectionPolicy::Closest);
}

// A graphics pipeline for |variant| and an offscreen target of the scene's size: SPIR-V from the
// pack, descriptor layouts from its reflection, the pass's render state.
Status createPipeline(varc::vulkan::VulkanContext& context,
                      const varc::reader::VariantView& variant, const varc::scene::Scene& scene) {
    varc::vulkan::RenderTargetDesc desc;
    desc.width = scene.camera.width;
    desc.height = scene.camera.height;
    auto target = varc::vulkan::RenderTarget::create(context, desc);
    if (!target) return target.error();
    varc::render::ShaderValues material;  // no properties: the state's defaults
    auto state = varc::render::resolveRenderState(variant.renderState(), material);
    auto pipeline =
        varc::render::VariantPipeline::create(context, variant, state, {target->renderPass()});
    if (!pipeline) return pipeline.error();
    std::cout << "pipeline: " << pipeline->description() << "\n";
    return varc::Ok{};
}

// Draws the whole scene (every object, every light, as Unity's forward, deferred or single-pass
// path does; the renderer looks each variant up as above) and writes the frame to |pngPath|.
Status drawFrame(varc::vulkan::VulkanContext& context, const varc::reader::Pack& pack,
                 const varc::scene::Scene& scene, const std::string& pngPath) {
    auto renderer = varc::render::SceneRenderer::create(context, {&pack});
    if (!renderer) return renderer.error();
    auto frame = renderer->render(scene);
    if (!frame) return frame.error();
    std::cout << "frame: " << frame->draws << " draws\n";
    // HDR frames are floats: tone-mapped as `varc render` does.
    varc::image::Image image = frame->image.isFloat()
                                   ? frame->image.toRgba8(varc::image::Tonemap::Reinhard)
                                   : frame->image;
    return varc::image::writePng(pngPath, image);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: varc_engine PACK SCENE.json OUT.png\n";
        return 2;
    }
    auto pack = varc::reader::Pack::open(argv[1]);
    if (!pack) return fail(pack.error().detail);
    auto scene = varc::scene::loadScene(argv[2]);
    if (!scene) return fail(scene.error().detail);

    auto variant = lookUpMainVariant(*pack, *scene);
    if (!variant) return fail(variant.error().detail);
    std::cout << "variant: " << variant->describe() << "\n";

    auto context = varc::vulkan::VulkanContext::create();  // lavapipe unless told otherwise
    if (!context) return fail(context.error().detail);
    std::cout << "device: " << context->deviceName() << "\n";
    if (Status created = createPipeline(*context, *variant, *scene); !created)
        return fail(created.error().detail);
    if (Status drawn = drawFrame(*context, *pack, *scene, argv[3]); !drawn)
        return fail(drawn.error().detail);
    std::cout << "wrote " << argv[3] << "\n";
    return 0;
}
