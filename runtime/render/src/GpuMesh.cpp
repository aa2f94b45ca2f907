// SPDX-License-Identifier: Apache-2.0
#include "GpuMesh.h"

#include <span>
#include <vector>

#include "varc/render/VertexLayout.h"

namespace varc::render {

Result<GpuMesh> uploadMesh(vulkan::VulkanContext& context, const scene::Mesh& mesh) {
    std::vector<MeshVertex> vertices(mesh.positions.size());
    for (size_t i = 0; i < vertices.size(); ++i) {
        MeshVertex& v = vertices[i];
        v = MeshVertex{
            {mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z},
            {mesh.normals[i].x, mesh.normals[i].y, mesh.normals[i].z},
            {mesh.tangents[i].x, mesh.tangents[i].y, mesh.tangents[i].z, mesh.tangents[i].w},
            {mesh.uvs[i].x, mesh.uvs[i].y},
            {1.0f, 1.0f, 1.0f, 1.0f}};
    }
    GpuMesh gpu;
    auto vertexBuffer =
        vulkan::Buffer::createWithData(context, std::as_bytes(std::span(vertices)),
                                       VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "mesh vertices");
    if (!vertexBuffer) return vertexBuffer.error();
    auto indexBuffer =
        vulkan::Buffer::createWithData(context, std::as_bytes(std::span(mesh.indices)),
                                       VK_BUFFER_USAGE_INDEX_BUFFER_BIT, "mesh indices");
    if (!indexBuffer) return indexBuffer.error();
    gpu.vertices = std::move(*vertexBuffer);
    gpu.indices = std::move(*indexBuffer);
    gpu.indexCount = static_cast<uint32_t>(mesh.indices.size());
    return gpu;
}

}  // namespace varc::render
