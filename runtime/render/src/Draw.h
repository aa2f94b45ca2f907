// SPDX-License-Identifier: Apache-2.0
// Draw: one indexed draw of a pack variant as the renderers record it, and the loop that records
// a list of them into a render pass that has already begun.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "GpuMesh.h"
#include "varc/render/DrawResources.h"
#include "varc/render/VariantPipeline.h"

namespace varc::render {

// Everything DrawResources::bind() and vkCmdDrawIndexed need for one draw.
struct Draw {
    const VariantPipeline* pipeline = nullptr;
    const GpuMesh* mesh = nullptr;
    uint32_t instances = 1;  // drawn with firstInstance 0: gl_InstanceIndex indexes the arrays
    // The value layers, most specific first (ValueLayers); unused entries stay null and are
    // skipped. Forward and deferred: light, object, material, camera. Single pass:
    // instances/object, draw lights, material, light buffer, camera.
    std::array<const ShaderValues*, 5> layers{};
    TextureLookup textures;
};

// Records |draws| on |commands| in order: binds each pipeline, its descriptor sets through
// |resources|, the mesh's vertex and index buffers, then draws indexed; adds one to |drawCount|
// per draw recorded. Stops at the first bind error and returns it (the draws before it stay
// recorded); the caller still ends the render pass and resets |resources| after the submit.
Status recordDraws(VkCommandBuffer commands, DrawResources& resources,
                   const std::vector<Draw>& draws, uint32_t& drawCount);

}  // namespace varc::render
