// SPDX-License-Identifier: Apache-2.0
#include "varc/render/DeferredValues.h"

#include <glm/gtc/matrix_inverse.hpp>

#include "varc/scene/LightTextures.h"

namespace varc::render {

ShaderValues deferredLightValues(const scene::Light& light, bool asQuad) {
    ShaderValues values;
    values.set("_LightPos", light.transform.position, 1.0f / (light.range * light.range));
    values.set("_LightDir", light.forward(), 0.0f);
    values.set("_LightColor", light.finalColor(), light.intensity);
    values.set("_LightAsQuad", asQuad ? 1.0f : 0.0f);
    values.set("unity_LightmapFade", glm::vec4(0.0f));
    for (const char* name : {"unity_WorldToLight", "_LightMatrix0"})
        values.set(name, scene::worldToLight(light, /*deferredSpotConvention=*/true));
    values.set("_LightShadowData", glm::vec4(0.0f));
    values.set("unity_ShadowFadeCenterAndType", glm::vec4(0.0f));
    values.set("_LightProjectionParams", glm::vec4(0, 0, 0, 1));
    values.set("unity_OcclusionMaskSelector", glm::vec4(1, 0, 0, 0));
    return values;
}

ShaderValues fullScreenQuadValues(const scene::CameraMatrices& camera) {
    ShaderValues values;
    // Inverted in double: VP · inverse(VP) must give the NDC corners back to ~1e-7.
    glm::mat4 inverseVP = glm::mat4(glm::inverse(glm::dmat4(camera.viewProjection)));
    for (const char* name : {"unity_ObjectToWorld", "_Object2World"}) values.set(name, inverseVP);
    for (const char* name : {"unity_WorldToObject", "_World2Object"})
        values.set(name, camera.viewProjection);
    values.set("unity_WorldTransformParams", glm::vec4(0, 0, 0, 1));
    values.set("unity_LODFade", glm::vec4(1, 1, 0, 0));
    return values;
}

ShaderValues lightVolumeValues(const glm::mat4& objectToWorld) {
    ShaderValues values;
    for (const char* name : {"unity_ObjectToWorld", "_Object2World"})
        values.set(name, objectToWorld);
    for (const char* name : {"unity_WorldToObject", "_World2Object"})
        values.set(name, glm::inverse(objectToWorld));
    values.set("unity_WorldTransformParams", glm::vec4(0, 0, 0, 1));
    values.set("unity_LODFade", glm::vec4(1, 1, 0, 0));
    return values;
}

std::array<QuadCorner, 4> fullScreenQuad(const scene::CameraMatrices& camera) {
    // NDC depth 1e-4: the near plane itself (0) could round to just outside the clip volume.
    constexpr float kQuadDepth = 1e-4f;
    const glm::dmat4 inverseProjection = glm::inverse(glm::dmat4(camera.projection));
    const glm::vec2 ndc[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    std::array<QuadCorner, 4> corners{};
    for (size_t i = 0; i < 4; ++i) {
        glm::dvec4 far = inverseProjection * glm::dvec4(ndc[i].x, ndc[i].y, 1.0, 1.0);
        far /= far.w;
        // View space looks down -z; camera local space down +z (SHADER_ABI.md §2).
        corners[i].position = glm::vec3(ndc[i], kQuadDepth);
        corners[i].ray = glm::vec3(static_cast<float>(far.x), static_cast<float>(far.y),
                                   static_cast<float>(-far.z));
        corners[i].uv = ndc[i] * 0.5f + 0.5f;
    }
    return corners;
}

}  // namespace varc::render
