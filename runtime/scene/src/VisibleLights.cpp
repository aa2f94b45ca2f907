// SPDX-License-Identifier: Apache-2.0
// VisibleLights: light-buffer selection and per-object light lists of the single-pass forward
// path (docs/LIGHTING.md §9.3).
#include "varc/scene/VisibleLights.h"

#include <algorithm>
#include <array>

#include "varc/scene/CameraMatrices.h"
#include "varc/scene/ForwardLights.h"
#include "varc/scene/LightImportance.h"

namespace varc::scene {
namespace {

// Whether the sphere (|centre|, |radius|) intersects the frustum of |viewProjection| (Vulkan
// clip space: -w <= x, y <= w, 0 <= z <= w). Planes from the matrix rows (Gribb & Hartmann);
// conservative near the frustum's corners, as such tests are.
bool sphereInFrustum(const glm::mat4& viewProjection, const glm::vec3& centre, float radius) {
    const glm::mat4 m = glm::transpose(viewProjection);  // m[i] = row i of the matrix
    const std::array<glm::vec4, 6> planes = {m[3] + m[0], m[3] - m[0], m[3] + m[1],
                                             m[3] - m[1], m[2],        m[3] - m[2]};
    for (const glm::vec4& plane : planes) {
        const float distance = glm::dot(glm::vec3(plane), centre) + plane.w;
        if (distance < -radius * glm::length(glm::vec3(plane))) return false;
    }
    return true;
}

}  // namespace

VisibleLightSet selectVisibleLights(const Scene& scene) {
    const glm::mat4 viewProjection = cameraMatrices(scene.camera).viewProjection;
    std::vector<RankedLight> visible;
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        if (light.type != LightType::Directional &&
            !sphereInFrustum(viewProjection, light.transform.position, light.range)) {
            continue;
        }
        visible.push_back(rankLight(static_cast<int>(i), light, scene.camera.position));
    }
    sortByImportance(visible);
    VisibleLightSet out;
    for (const RankedLight& light : visible) {
        auto& list = out.slots.size() < kMaxVisibleLights ? out.slots : out.dropped;
        list.push_back(light.index);
    }
    return out;
}

ObjectLightList objectLightList(const Scene& scene, const VisibleLightSet& visible,
                                const Object& object) {
    const BoundingSphere bounds = worldBounds(object);
    std::vector<RankedLight> touching;
    for (size_t slot = 0; slot < visible.slots.size(); ++slot) {
        const Light& light = scene.lights[static_cast<size_t>(visible.slots[slot])];
        if (lightReaches(light, bounds))
            touching.push_back(rankLight(static_cast<int>(slot), light, bounds.centre));
    }
    sortByImportance(touching);
    ObjectLightList out;
    out.count = static_cast<int>(touching.size());
    for (size_t k = 0; k < touching.size() && k < kMaxLightsPerObject; ++k) {
        out.slots.push_back(touching[k].index);
    }
    return out;
}

}  // namespace varc::scene
