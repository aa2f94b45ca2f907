// SPDX-License-Identifier: Apache-2.0
// The full-screen quad as a GPU mesh.
#include "FullScreenQuad.h"

#include "varc/render/DeferredValues.h"
#include "varc/scene/Mesh.h"

namespace varc::render {

Result<GpuMesh> uploadFullScreenQuad(vulkan::VulkanContext& context,
                                     const scene::CameraMatrices& camera) {
    scene::Mesh mesh;
    for (const QuadCorner& corner : fullScreenQuad(camera)) {
        mesh.positions.push_back(corner.position);
        mesh.normals.push_back(corner.ray);
        mesh.tangents.emplace_back(1.0f, 0.0f, 0.0f, 1.0f);
        mesh.uvs.push_back(corner.uv);
    }
    mesh.indices = {0, 1, 2, 0, 2, 3};
    return uploadMesh(context, mesh);
}

}  // namespace varc::render
