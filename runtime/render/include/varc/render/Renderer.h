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
#include "varc/scene/Scene.h"

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
};

}  // namespace varc::render
