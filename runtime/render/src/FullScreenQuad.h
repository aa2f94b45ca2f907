// SPDX-License-Identifier: Apache-2.0
// The full-screen quad of DeferredValues.h (fullScreenQuad) as a GPU mesh, for passes that
// shade every pixel: the deferred light and decode passes, the shadow collector.
#pragma once

#include "GpuMesh.h"
#include "varc/scene/CameraMatrices.h"
#include "varc/vulkan/VulkanContext.h"

namespace varc::render {

// The quad's NDC positions, its rays as NORMALs and its screen uvs, as two triangles.
Result<GpuMesh> uploadFullScreenQuad(vulkan::VulkanContext& context,
                                     const scene::CameraMatrices& camera);

}  // namespace varc::render
