// SPDX-License-Identifier: Apache-2.0
// CameraMatrices: look-at frame and the Vulkan / GL projections of SHADER_ABI.md §2, §4.2.
#include "varc/scene/CameraMatrices.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace varc::scene {

CameraMatrices cameraMatrices(const Camera& camera) {
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    glm::vec3 worldUp(0.0f, 1.0f, 0.0f);
    if (std::abs(glm::dot(forward, worldUp)) > 0.9999f) worldUp = glm::vec3(0.0f, 0.0f, 1.0f);
    // Left-handed, y up, z forward: right = up x forward (the cross product's formula does not
    // depend on handedness; (0,1,0) x (0,0,1) = (1,0,0)).
    const glm::vec3 right = glm::normalize(glm::cross(worldUp, forward));
    const glm::vec3 up = glm::cross(forward, right);

    CameraMatrices m;
    m.cameraToWorld = glm::mat4(glm::vec4(right, 0.0f), glm::vec4(up, 0.0f),
                                glm::vec4(forward, 0.0f), glm::vec4(camera.position, 1.0f));
    m.worldToCamera = glm::inverse(m.cameraToWorld);
    m.view = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 1.0f, -1.0f)) * m.worldToCamera;

    const float aspect = static_cast<float>(camera.width) / static_cast<float>(camera.height);
    const float tanHalf = std::tan(glm::radians(camera.fovY) * 0.5f);
    const float n = camera.nearPlane, f = camera.farPlane;
    // View space looks down -z; w = -z_v; z_clip / w is 0 at z_v = -n and 1 at z_v = -f:
    // z_clip = A z_v + B with A = f / (n - f), B = n f / (n - f). y is flipped (Vulkan y down).
    glm::mat4 p(0.0f);
    p[0][0] = 1.0f / (aspect * tanHalf);
    p[1][1] = -1.0f / tanHalf;
    p[2][2] = f / (n - f);
    p[2][3] = -1.0f;
    p[3][2] = n * f / (n - f);
    m.projection = p;
    m.viewProjection = m.projection * m.view;
    m.glProjection = glm::perspectiveRH_NO(glm::radians(camera.fovY), aspect, n, f);
    return m;
}

}  // namespace varc::scene
