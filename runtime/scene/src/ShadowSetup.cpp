// SPDX-License-Identifier: Apache-2.0
// ShadowSetup: shadow cameras and shadow uniforms (SHADER_ABI.md §4.7).
#include "varc/scene/ShadowSetup.h"

namespace varc::scene {

ShadowCamera spotShadowCamera(const Light& light) {
    Camera camera;
    camera.position = light.transform.position;
    camera.target = light.transform.position + light.forward();
    camera.fovY = light.spotAngle;
    camera.nearPlane = light.shadowNearPlane;
    camera.farPlane = light.range;
    camera.width = camera.height = light.shadowResolution;

    ShadowCamera shadow;
    shadow.matrices = cameraMatrices(camera);
    shadow.resolution = light.shadowResolution;
    // Clip x, y in [-w, w] -> [0, w]; z (already [0, w] in Vulkan) kept.
    glm::mat4 toTexture(1.0f);
    toTexture[0][0] = 0.5f;
    toTexture[1][1] = 0.5f;
    toTexture[3][0] = 0.5f;
    toTexture[3][1] = 0.5f;
    shadow.worldToShadow = toTexture * shadow.matrices.viewProjection;
    shadow.bias = glm::vec4(light.shadowBias / 100.0f, 0.0f, light.shadowNormalBias / 20.0f, 0.0f);
    return shadow;
}

glm::vec4 lightShadowData(const Light& light, const Scene& scene) {
    return glm::vec4(1.0f - light.shadowStrength, 0.0f, 5.0f / scene.shadowDistance, -4.0f);
}

glm::vec4 shadowFadeCenterAndType(const Scene& scene) {
    return glm::vec4(scene.camera.position, 0.0f);
}

}  // namespace varc::scene
