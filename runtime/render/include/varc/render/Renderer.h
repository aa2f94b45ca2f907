// SPDX-License-Identifier: Apache-2.0
// What every renderer does: draw a Scene with pack variants on Vulkan and read the frame back.
// ForwardRenderer, DeferredRenderer and SinglePassRenderer implement it; SceneRenderer picks
// one by the scene's camera path.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "varc/core/Result.h"
#include "varc/image/Image.h"
#include "varc/reader/VariantRequests.h"
#include "varc/scene/Scene.h"
#include "varc/variants/VariantSelector.h"

namespace varc::render {

struct RenderedFrame {
    image::Image image;                 // Rgba8 (LDR: RGBA8_UNORM) or RgbaFloat (HDR: RGBA16F)
    std::vector<std::string> variants;  // VariantView::describe() of every draw, in draw order
    uint32_t draws = 0;
};

class Renderer {
public:
    virtual ~Renderer() = default;

    // Draws |scene| and reads the colour target back. Errors name the object or light and its
    // shader: an unknown shader, a pass the shader lacks, no variant, a texture file that cannot
    // be read, pipeline or Vulkan failures.
    virtual Result<RenderedFrame> render(const scene::Scene& scene) = 0;

    // Creates every later pipeline through |cache| (e.g. PipelineCacheFile::handle()), which must
    // outlive the renderer; VK_NULL_HANDLE (the default) uses none.
    virtual void usePipelineCache(VkPipelineCache cache) = 0;

    // Resolves every later draw's variant through |requests| (which must outlive the renderer;
    // nullptr, the default, looks variants up directly), so misses are reported once and the
    // requests can be written as a usage log. |missPolicy| replaces Closest (the default) for
    // the variants materials and lights choose: Strict makes any miss a render error naming the
    // variant. Draws of varc's own shaders that need one exact variant stay Exact.
    virtual void useVariantRequests(reader::VariantRequests* requests,
                                    variants::SelectionPolicy missPolicy) = 0;
};

}  // namespace varc::render
