// SPDX-License-Identifier: Apache-2.0
// GpuMesh: a scene mesh uploaded as MeshVertex (VertexLayout.h) and uint32 index buffers; shared
// by the forward and deferred renderers.
#pragma once

#include <cstdint>

#include "varc/scene/Mesh.h"
#include "varc/vulkan/Buffer.h"

namespace varc::render {

struct GpuMesh {
    vulkan::Buffer vertices;
    vulkan::Buffer indices;
    uint32_t indexCount = 0;
};

// Uploads |mesh| (positions, normals, tangents, uv0; colour white). Errors: those of Buffer.
Result<GpuMesh> uploadMesh(vulkan::VulkanContext& context, const scene::Mesh& mesh);

}  // namespace varc::render
