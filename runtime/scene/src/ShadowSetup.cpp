// SPDX-License-Identifier: Apache-2.0
// ShadowSetup: shadow cameras and shadow uniforms (SHADER_ABI.md §4.7).
#include "varc/scene/ShadowSetup.h"

#include <algorithm>
#include <cmath>

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

namespace {

// An orthographic camera looking along |forward| (left-handed light space: x right, y up, z
// along the light): the box [lo, hi] of light space onto Vulkan clip space (y down, z 0..1).
glm::mat4 orthoAlong(const glm::mat3& worldToLight, const glm::vec3& lo, const glm::vec3& hi) {
    glm::mat4 view(worldToLight);
    glm::mat4 projection(1.0f);
    projection[0][0] = 2.0f / (hi.x - lo.x);
    projection[1][1] = -2.0f / (hi.y - lo.y);
    projection[2][2] = 1.0f / (hi.z - lo.z);
    projection[3][0] = -(hi.x + lo.x) / (hi.x - lo.x);
    projection[3][1] = (hi.y + lo.y) / (hi.y - lo.y);
    projection[3][2] = -lo.z / (hi.z - lo.z);
    return projection * view;
}

}  // namespace

DirectionalShadowSetup directionalShadowSetup(const Scene& scene, const Light& light) {
    DirectionalShadowSetup setup;
    setup.cascades = scene.shadowCascades;
    setup.resolution = light.shadowResolution;
    setup.tileSize = setup.cascades == 1 ? setup.resolution : setup.resolution / 2;
    setup.stableFit = scene.stableFit;
    setup.bias = glm::vec4(light.shadowBias / 100.0f, 0.0f, light.shadowNormalBias / 20.0f, 0.0f);

    // Light space: rows right, up, forward (the light's direction of travel).
    const glm::vec3 forward = light.forward();
    glm::vec3 worldUp(0.0f, 1.0f, 0.0f);
    if (std::abs(glm::dot(forward, worldUp)) > 0.9999f) worldUp = glm::vec3(0.0f, 0.0f, 1.0f);
    const glm::vec3 right = glm::normalize(glm::cross(worldUp, forward));
    const glm::vec3 up = glm::cross(forward, right);
    const glm::mat3 worldToLight = glm::transpose(glm::mat3(right, up, forward));

    // The camera frustum's slices in view depth.
    const Camera& camera = scene.camera;
    const float distance = std::min(scene.shadowDistance, camera.farPlane);
    float depths[5] = {camera.nearPlane, distance, distance, distance, distance};
    if (setup.cascades == 2) depths[1] = scene.cascadeSplits.x * distance;
    if (setup.cascades == 4) {
        for (int i = 0; i < 3; ++i) depths[i + 1] = scene.cascadeSplits[i] * distance;
    }
    const CameraMatrices view = cameraMatrices(camera);
    const glm::vec3 camRight(view.cameraToWorld[0]), camUp(view.cameraToWorld[1]),
        camForward(view.cameraToWorld[2]);
    const float tanHalf = std::tan(glm::radians(camera.fovY) * 0.5f);
    const float aspect = static_cast<float>(camera.width) / static_cast<float>(camera.height);

    glm::mat4 toTexture(1.0f);
    toTexture[0][0] = toTexture[1][1] = 0.5f;
    toTexture[3][0] = toTexture[3][1] = 0.5f;
    for (int c = 0; c < setup.cascades; ++c) {
        const float nearDepth = depths[c], farDepth = depths[c + 1];
        setup.splitsNear[c] = nearDepth;
        setup.splitsFar[c] = farDepth;
        glm::vec3 corners[8];
        glm::vec3 centre(0.0f);
        for (int k = 0; k < 8; ++k) {
            const float d = (k & 4) ? farDepth : nearDepth;
            const float sx = (k & 1) ? 1.0f : -1.0f, sy = (k & 2) ? 1.0f : -1.0f;
            corners[k] = camera.position + camForward * d + camRight * (sx * d * tanHalf * aspect) +
                         camUp * (sy * d * tanHalf);
            centre += corners[k] / 8.0f;
        }
        float radius = 0.0f;
        for (const glm::vec3& corner : corners) radius = std::max(radius, glm::length(corner - centre));
        setup.splitSpheres[c] = glm::vec4(centre, radius);
        setup.splitSqRadii[c] = radius * radius;

        glm::vec3 lo(INFINITY), hi(-INFINITY);
        if (setup.stableFit) {
            glm::vec3 middle = worldToLight * centre;
            const float texel = 2.0f * radius / static_cast<float>(setup.tileSize);
            middle.x = std::floor(middle.x / texel) * texel;
            middle.y = std::floor(middle.y / texel) * texel;
            lo = middle - glm::vec3(radius);
            hi = middle + glm::vec3(radius);
        } else {
            for (const glm::vec3& corner : corners) {
                lo = glm::min(lo, worldToLight * corner);
                hi = glm::max(hi, worldToLight * corner);
            }
        }
        lo.z -= scene.shadowDistance;  // casters between the light and the slice
        setup.viewProjection[c] = orthoAlong(worldToLight, lo, hi);
        setup.tileOrigin[c] = setup.cascades == 1
                                  ? glm::uvec2(0)
                                  : glm::uvec2(c % 2, c / 2) * setup.tileSize;
        // Texture coordinates of the tile inside the atlas.
        const float scale = static_cast<float>(setup.tileSize) / static_cast<float>(setup.resolution);
        glm::mat4 tile(1.0f);
        tile[0][0] = tile[1][1] = scale;
        tile[3][0] = static_cast<float>(setup.tileOrigin[c].x) / static_cast<float>(setup.resolution);
        tile[3][1] = static_cast<float>(setup.tileOrigin[c].y) / static_cast<float>(setup.resolution);
        setup.worldToShadow[c] = tile * toTexture * setup.viewProjection[c];
    }
    return setup;
}

glm::vec4 lightShadowData(const Light& light, const Scene& scene) {
    return glm::vec4(1.0f - light.shadowStrength, 0.0f, 5.0f / scene.shadowDistance, -4.0f);
}

glm::vec4 shadowFadeCenterAndType(const Scene& scene) {
    return glm::vec4(scene.camera.position, 0.0f);
}

}  // namespace varc::scene
