// SPDX-License-Identifier: Apache-2.0
// CameraMatrices: a scene camera's view and projection matrices in the conventions of
// SHADER_ABI.md §2 and §4.2.
#pragma once

#include <glm/glm.hpp>

#include "varc/scene/Scene.h"

namespace varc::scene {

struct CameraMatrices {
    glm::mat4 cameraToWorld;   // camera local (+z forward, y up, LH) -> world (unity_CameraToWorld)
    glm::mat4 worldToCamera;
    glm::mat4 view;            // unity_MatrixV = diag(1,1,-1,1) * worldToCamera (RH, looks down -z)
    glm::mat4 projection;      // glstate_matrix_projection: view -> Vulkan clip (y down, z in [0,w])
    glm::mat4 viewProjection;  // projection * view
    glm::mat4 glProjection;    // unity_CameraProjection (GL style, y up, z in [-w, w])
};

// Look-at from camera.position to camera.target with world up (0,1,0) (up (0,0,1) when looking
// straight up/down); aspect = width/height. Clip space: x_clip = x_v / (aspect·tan(fov/2)),
// y_clip = -y_v / tan(fov/2), w = -z_v, z_clip/w = 0 at the near plane and 1 at the far plane.
// Framebuffer coordinates: ((x/w + 1)/2 · width, (y/w + 1)/2 · height), row 0 at the top.
CameraMatrices cameraMatrices(const Camera& camera);

}  // namespace varc::scene
