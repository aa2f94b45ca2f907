// SPDX-License-Identifier: Apache-2.0
// Draw: the draw-record loop the forward, deferred and single-pass renderers share.
#include "Draw.h"

namespace varc::render {

Status recordDraws(VkCommandBuffer commands, DrawResources& resources,
                   const std::vector<Draw>& draws, uint32_t& drawCount) {
    for (const Draw& draw : draws) {
        vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.pipeline->pipeline());
        if (Status bound = resources.bind(commands, *draw.pipeline, draw.layers, draw.textures);
            !bound) {
            return bound;
        }
        VkBuffer vertexBuffer = draw.mesh->vertices.handle();
        VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(commands, 0, 1, &vertexBuffer, &offset);
        vkCmdBindIndexBuffer(commands, draw.mesh->indices.handle(), 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexed(commands, draw.mesh->indexCount, draw.instances, 0, 0, 0);
        ++drawCount;
    }
    return Ok{};
}

}  // namespace varc::render
