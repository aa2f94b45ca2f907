// SPDX-License-Identifier: Apache-2.0
#include "varc/render/SceneValues.h"

#include <algorithm>
#include <array>

#include "varc/scene/LightTextures.h"

namespace varc::render {

ShaderValues cameraValues(const scene::Scene& scene, const scene::CameraMatrices& m) {
    const scene::Camera& camera = scene.camera;
    ShaderValues values;
    auto width = static_cast<float>(camera.width), height = static_cast<float>(camera.height);
    float n = camera.nearPlane, f = camera.farPlane;
    values.set("_WorldSpaceCameraPos", camera.position, 1.0f);
    values.set("_ProjectionParams", glm::vec4(1.0f, n, f, 1.0f / f));
    values.set("_ScreenParams",
               glm::vec4(width, height, 1.0f + 1.0f / width, 1.0f + 1.0f / height));
    values.set("_ZBufferParams", glm::vec4(1.0f - f / n, f / n, (1.0f - f / n) / f, 1.0f / n));
    values.set("unity_OrthoParams", glm::vec4(0.0f));
    values.set("unity_MatrixV", m.view);
    values.set("unity_MatrixInvV", glm::inverse(m.view));
    values.set("glstate_matrix_projection", m.projection);
    values.set("unity_MatrixVP", m.viewProjection);
    values.set("unity_CameraProjection", m.glProjection);
    values.set("unity_CameraInvProjection", glm::inverse(m.glProjection));
    values.set("unity_WorldToCamera", m.worldToCamera);
    values.set("unity_CameraToWorld", m.cameraToWorld);
    values.set("varc_ProjectionMatrix", m.projection);
    // Clip -> world, for passes that rebuild positions from depth (the shadow collector).
    values.set("varc_CameraInvViewProjection", glm::mat4(glm::inverse(glm::dmat4(m.viewProjection))));
    for (const char* name : {"_Time", "_SinTime", "_CosTime", "unity_DeltaTime"})
        values.set(name, glm::vec4(0.0f));
    glm::vec4 ambient(scene.ambient, 1.0f);
    for (const char* name : {"glstate_lightmodel_ambient", "unity_AmbientSky",
                             "unity_AmbientEquator", "unity_AmbientGround",
                             "varc_LightModelAmbient"}) {
        values.set(name, ambient);
    }
    values.set("unity_IndirectSpecColor", glm::vec4(0.0f));
    return values;
}

ShaderValues objectValues(const scene::Scene& scene, const scene::Object& object,
                          const scene::CameraMatrices& camera,
                          const scene::ForwardLightAssignment& assignment) {
    ShaderValues values;
    glm::mat4 objectToWorld = object.transform.localToWorld();
    glm::mat4 worldToObject = glm::inverse(objectToWorld);
    for (const char* name : {"unity_ObjectToWorld", "_Object2World"})
        values.set(name, objectToWorld);
    for (const char* name : {"unity_WorldToObject", "_World2Object"})
        values.set(name, worldToObject);
    values.set("unity_WorldTransformParams",
               glm::vec4(0, 0, 0, glm::determinant(objectToWorld) < 0 ? -1.0f : 1.0f));
    values.set("unity_LODFade", glm::vec4(1, 1, 0, 0));
    values.set("unity_ProbesOcclusion", glm::vec4(1.0f));
    glm::mat4 modelView = camera.view * objectToWorld;
    values.set("varc_ModelViewProjectionMatrix", camera.viewProjection * objectToWorld);
    values.set("varc_ModelViewMatrix", modelView);
    values.set("varc_NormalMatrix", glm::transpose(glm::inverse(modelView)));
    values.set("varc_ModelViewMatrixInverseTranspose", glm::transpose(glm::inverse(modelView)));

    std::array<glm::vec4, 7> sh = scene::packedSH(scene, object, assignment.shLights);
    const char* shNames[] = {"unity_SHAr", "unity_SHAg", "unity_SHAb", "unity_SHBr",
                             "unity_SHBg", "unity_SHBb", "unity_SHC"};
    for (size_t i = 0; i < sh.size(); ++i) values.set(shNames[i], sh[i]);

    glm::vec4 x(0.0f), y(0.0f), z(0.0f), atten(0.0f);
    std::vector<glm::vec4> colors(8, glm::vec4(0.0f));
    for (size_t i = 0; i < assignment.vertexLights.size() && i < 4; ++i) {
        const scene::Light& light = scene.lights[static_cast<size_t>(assignment.vertexLights[i])];
        glm::vec3 position = light.transform.position;
        auto slot = static_cast<glm::length_t>(i);
        x[slot] = position.x;
        y[slot] = position.y;
        z[slot] = position.z;
        atten[slot] = 25.0f / (light.range * light.range);
        colors[i] = glm::vec4(light.finalColor(), 1.0f);
    }
    values.set("unity_4LightPosX0", x);
    values.set("unity_4LightPosY0", y);
    values.set("unity_4LightPosZ0", z);
    values.set("unity_4LightAtten0", atten);
    values.setArray("unity_LightColor", colors);
    // SHADER_ABI.md §4.13: lightmap uv = uv1 * ST.xy + ST.zw; varc's lightmaps are full HDR.
    const scene::Lightmap lightmap = object.lightmap.value_or(scene::Lightmap{});
    values.set("unity_LightmapST", lightmap.scaleOffset);
    values.set("unity_DynamicLightmapST", lightmap.realtimeScaleOffset);
    values.set("unity_Lightmap_HDR", glm::vec4(1, 1, 0, 0));
    values.set("unity_DynamicLightmap_HDR", glm::vec4(1, 1, 0, 0));
    return values;
}

ShaderValues forwardLightValues(const scene::Light* light) {
    ShaderValues values;
    values.set("_LightProjectionParams", glm::vec4(0, 0, 0, 1));
    values.set("unity_OcclusionMaskSelector", glm::vec4(1, 0, 0, 0));
    values.set("_LightShadowData", glm::vec4(0.0f));
    if (!light) {
        values.set("_LightColor0", glm::vec4(0.0f));
        // A unit direction: shaders normalize it, and normalize(0) is NaN (times a zero colour).
        values.set("_WorldSpaceLightPos0", glm::vec4(0, 1, 0, 0));
        // _LightMatrix0: the legacy name a GLSLPROGRAM declares as a loose uniform.
        for (const char* name : {"unity_WorldToLight", "_LightMatrix0"})
            values.set(name, glm::mat4(1.0f));
        return values;
    }
    glm::vec3 position = light->transform.position;
    if (light->type == scene::LightType::Directional) {
        values.set("_WorldSpaceLightPos0", -light->forward(), 0.0f);
    } else {
        values.set("_WorldSpaceLightPos0", position, 1.0f);
    }
    values.set("_LightColor0", light->finalColor(), light->intensity);
    values.set("_LightPositionRange", position, 1.0f / light->range);
    for (const char* name : {"unity_WorldToLight", "_LightMatrix0"})
        values.set(name, scene::worldToLight(*light, /*deferredSpotConvention=*/false));
    return values;
}

scene::Material withPropertyDefaults(scene::Material material,
                                     const std::vector<pack::ShaderProperty>& defaults) {
    for (const pack::ShaderProperty& property : defaults) {
        if (material.properties.count(property.name)) continue;
        const std::array<float, 4>& v = property.value;
        switch (property.kind) {
            case pack::PropertyKind::Float:
                material.properties[property.name] = v[0];
                break;
            case pack::PropertyKind::Vector:
            case pack::PropertyKind::Color:
                material.properties[property.name] = glm::vec4(v[0], v[1], v[2], v[3]);
                break;
            case pack::PropertyKind::Texture:
                // Unity's texture for an empty default name is gray.
                material.properties[property.name] =
                    property.texture.empty() ? std::string("gray") : property.texture;
                break;
        }
    }
    return material;
}

ShaderValues materialValues(const scene::Material& material,
                            std::map<std::string, std::string>& textures) {
    ShaderValues values;
    for (const auto& [name, value] : material.properties) {
        if (const float* number = std::get_if<float>(&value)) {
            values.set(name, *number);
        } else if (const glm::vec4* vector = std::get_if<glm::vec4>(&value)) {
            values.set(name, *vector);
        } else {
            textures[name] = std::get<std::string>(value);
        }
    }
    for (const auto& [name, texture] : textures) {
        if (!values.find(name + "_ST")) values.set(name + "_ST", glm::vec4(1, 1, 0, 0));
    }
    return values;
}

void setDynamicBranchValues(ShaderValues& values, const std::vector<std::string>& dynamicKeywords,
                            const std::vector<std::string>& enabled) {
    for (const std::string& keyword : dynamicKeywords) {
        const bool on = std::find(enabled.begin(), enabled.end(), keyword) != enabled.end();
        values.set(keyword, on ? 1.0f : 0.0f);
    }
}

}  // namespace varc::render
