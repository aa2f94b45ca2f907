// SPDX-License-Identifier: Apache-2.0
// Renders a forward Scene with pack variants on Vulkan, with Unity's built-in forward rules
// (docs/KEYWORDS.md §9, docs/LIGHTING.md §9): per object one ForwardBase draw (main directional
// light, vertex lights, SH) and one additive ForwardAdd draw per extra pixel light, each with the
// variant its light selects through the pack's lookup.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "varc/image/Image.h"
#include "varc/reader/Pack.h"
#include "varc/render/BuiltinTextures.h"
#include "varc/render/DrawResources.h"
#include "varc/render/Renderer.h"
#include "varc/render/VariantPipeline.h"
#include "varc/scene/Scene.h"
#include "varc/vulkan/Buffer.h"

namespace varc::render {

class ForwardRenderer final : public Renderer {
public:
    // |packs| must outlive the renderer; shaders are found by name in the first pack that has them.
    static Result<ForwardRenderer> create(vulkan::VulkanContext& context,
                                          std::vector<const reader::Pack*> packs);

    // Errors name the object and shader: an unknown shader, a pass the shader lacks
    // (ForwardBase is required; ForwardAdd only when add lights exist), no variant for the light,
    // pipeline or Vulkan failures.
    Result<RenderedFrame> render(const scene::Scene& scene) override;

    void usePipelineCache(VkPipelineCache cache) override;
    void useVariantRequests(reader::VariantRequests* requests,
                            variants::SelectionPolicy missPolicy) override;

    ForwardRenderer(ForwardRenderer&&) noexcept;
    ForwardRenderer& operator=(ForwardRenderer&&) noexcept;
    ~ForwardRenderer() override;

private:
    struct State;
    explicit ForwardRenderer(std::unique_ptr<State> state);
    std::unique_ptr<State> mState;
};

}  // namespace varc::render
