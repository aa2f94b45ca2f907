// SPDX-License-Identifier: Apache-2.0
// ShadowSetup: shadow cameras and shadow uniforms (SHADER_ABI.md §4.7).
#include "varc/scene/ShadowSetup.h"

#include <glm/gtc/matrix_transform.hpp>

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

PointShadowCamera pointShadowCamera(const Light& light) {
    const float n = light.shadowNearPlane, f = light.range;
    const float a = f / (n - f), b = n * f / (n - f);
    // Rows of each face's clip coordinates as functions of r = p - lightPos (Vulkan's cube face
    // table: s = (sc / |ma| + 1) / 2, t = (tc / |ma| + 1) / 2, and x_ndc = 2 s - 1, y_ndc = 2 t - 1
    // with framebuffer row 0 at t = 0): x = sc, y = tc, w = |ma|, z = -a |ma| + b.
    struct Face {
        glm::vec3 sc, tc, ma;  // sc = dot(sc, r), tc = dot(tc, r), |ma| = dot(ma, r)
    };
    const Face faces[6] = {
        {{0, 0, -1}, {0, -1, 0}, {1, 0, 0}},   // +X: sc = -rz, tc = -ry
        {{0, 0, 1}, {0, -1, 0}, {-1, 0, 0}},   // -X: sc = +rz, tc = -ry
        {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},     // +Y: sc = +rx, tc = +rz
        {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},   // -Y: sc = +rx, tc = -rz
        {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}},    // +Z: sc = +rx, tc = -ry
        {{-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},  // -Z: sc = -rx, tc = -ry
    };
    PointShadowCamera camera;
    camera.resolution = light.shadowResolution;
    camera.projectionParams = glm::vec4(a, b, light.shadowBias / 10.0f, 1.0f);
    camera.bias = glm::vec4(0.0f, 0.0f, light.shadowNormalBias / 20.0f, 0.0f);
    const glm::mat4 toLight = glm::translate(glm::mat4(1.0f), -light.transform.position);
    for (size_t i = 0; i < 6; ++i) {
        const Face& face = faces[i];
        // Rows x, y, z, w of the face matrix (glm is column-major: m[column][row]).
        glm::mat4 m(0.0f);
        for (int c = 0; c < 3; ++c) {
            m[c][0] = face.sc[c];
            m[c][1] = face.tc[c];
            m[c][2] = -a * face.ma[c];
            m[c][3] = face.ma[c];
        }
        m[3][2] = b;
        camera.faceViewProjection[i] = m * toLight;
        // A camera's (x, y, w) rows (right, -up, forward) have determinant -1 in varc's
        // left-handed world; a face with +1 mirrors the image.
        camera.mirrored[i] = glm::determinant(glm::mat3(face.sc, face.tc, face.ma)) > 0.0f;
    }
    return camera;
}

glm::vec4 lightShadowData(const Light& light, const Scene& scene) {
    return glm::vec4(1.0f - light.shadowStrength, 0.0f, 5.0f / scene.shadowDistance, -4.0f);
}

glm::vec4 shadowFadeCenterAndType(const Scene& scene) {
    return glm::vec4(scene.camera.position, 0.0f);
}

}  // namespace varc::scene
