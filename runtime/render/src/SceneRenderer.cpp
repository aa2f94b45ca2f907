// SPDX-License-Identifier: Apache-2.0
// SceneRenderer: one renderer per camera path behind the Renderer interface.
#include "varc/render/SceneRenderer.h"

#include <utility>

namespace varc::render {

SceneRenderer::SceneRenderer(ForwardRenderer forward, SinglePassRenderer singlePass,
                             DeferredRenderer deferred)
    : mForward(std::move(forward)),
      mSinglePass(std::move(singlePass)),
      mDeferred(std::move(deferred)) {}

Result<SceneRenderer> SceneRenderer::create(vulkan::VulkanContext& context,
                                            std::vector<const reader::Pack*> packs) {
    auto forward = ForwardRenderer::create(context, packs);
    if (!forward) return forward.error();
    auto singlePass = SinglePassRenderer::create(context, packs);
    if (!singlePass) return singlePass.error();
    auto deferred = DeferredRenderer::create(context, std::move(packs));
    if (!deferred) return deferred.error();
    return SceneRenderer(std::move(*forward), std::move(*singlePass), std::move(*deferred));
}

Renderer& SceneRenderer::rendererFor(scene::RenderPath path) {
    switch (path) {
        case scene::RenderPath::SinglePass:
            return mSinglePass;
        case scene::RenderPath::Deferred:
            return mDeferred;
        case scene::RenderPath::Forward:
            break;
    }
    return mForward;
}

Result<RenderedFrame> SceneRenderer::render(const scene::Scene& scene) {
    return rendererFor(scene.camera.path).render(scene);
}

void SceneRenderer::usePipelineCache(VkPipelineCache cache) {
    mForward.usePipelineCache(cache);
    mSinglePass.usePipelineCache(cache);
    mDeferred.usePipelineCache(cache);
}

void SceneRenderer::useVariantRequests(reader::VariantRequests* requests,
                                       variants::SelectionPolicy missPolicy) {
    mForward.useVariantRequests(requests, missPolicy);
    mSinglePass.useVariantRequests(requests, missPolicy);
    mDeferred.useVariantRequests(requests, missPolicy);
}

}  // namespace varc::render
