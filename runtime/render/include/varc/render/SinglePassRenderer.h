// SPDX-License-Identifier: Apache-2.0
// Renders a single-pass forward Scene (seed 003's technique, `"path": "single_pass"`) with pack
// variants on Vulkan: one light buffer per frame holding up to 16 visible lights, and one draw
// per object (or per instanced batch) carrying the indices of the lights that touch it
// (SHADER_ABI.md §4.12; the rules are varc::scene::VisibleLights).
#pragma once

#include <memory>
#include <vector>

#include "varc/reader/Pack.h"
#include "varc/render/Renderer.h"
#include "varc/scene/Scene.h"
#include "varc/vulkan/VulkanContext.h"

namespace varc::render {

struct SinglePassOptions {
    // Objects drawn with the same shader, mesh and non-instanced material properties that are
    // touched by the same lights (same count and index lists) are drawn as one instanced batch
    // with the INSTANCING_ON variant (SHADER_ABI.md §4.10), when the shader has that keyword.
    // false: one draw per object with the variant without INSTANCING_ON.
    bool instancing = true;
};

class SinglePassRenderer final : public Renderer {
public:
    // |packs| must outlive the renderer; shaders are found by name in the first pack that has them.
    static Result<SinglePassRenderer> create(vulkan::VulkanContext& context,
                                             std::vector<const reader::Pack*> packs);

    // Draws every object with its shader's first pass, in scene order (batches at the position
    // of their first object). Errors name the object and shader: an unknown shader, a shader
    // without passes, no variant, pipeline or Vulkan failures.
    Result<RenderedFrame> render(const scene::Scene& scene, const SinglePassOptions& options);
    // render(scene, SinglePassOptions{}).
    Result<RenderedFrame> render(const scene::Scene& scene) override;

    void usePipelineCache(VkPipelineCache cache) override;
    void useVariantRequests(reader::VariantRequests* requests,
                            variants::SelectionPolicy missPolicy) override;

    SinglePassRenderer(SinglePassRenderer&&) noexcept;
    SinglePassRenderer& operator=(SinglePassRenderer&&) noexcept;
    ~SinglePassRenderer() override;

private:
    struct State;
    explicit SinglePassRenderer(std::unique_ptr<State> state);
    std::unique_ptr<State> mState;
};

}  // namespace varc::render
