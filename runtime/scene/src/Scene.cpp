// SPDX-License-Identifier: Apache-2.0
// Scene: Unity-convention transforms and light directions.
#include "varc/scene/Scene.h"

#include <glm/gtc/matrix_transform.hpp>

namespace varc::scene {

glm::mat3 Transform::rotation() const {
    const glm::vec3 r = glm::radians(rotationDegrees);
    const glm::mat4 ry = glm::rotate(glm::mat4(1.0f), r.y, glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::mat4 rx = glm::rotate(glm::mat4(1.0f), r.x, glm::vec3(1.0f, 0.0f, 0.0f));
    const glm::mat4 rz = glm::rotate(glm::mat4(1.0f), r.z, glm::vec3(0.0f, 0.0f, 1.0f));
    return glm::mat3(ry * rx * rz);
}

glm::mat4 Transform::rigidToWorld() const {
    glm::mat4 m(rotation());
    m[3] = glm::vec4(position, 1.0f);
    return m;
}

glm::mat4 Transform::localToWorld() const {
    return rigidToWorld() * glm::scale(glm::mat4(1.0f), scale);
}

glm::vec3 Light::forward() const {
    return glm::normalize(transform.rotation() * glm::vec3(0.0f, 0.0f, 1.0f));
}

const char* toString(MeshKind kind) {
    switch (kind) {
        case MeshKind::Sphere: return "sphere";
        case MeshKind::Cube: return "cube";
        case MeshKind::Plane: return "plane";
    }
    return "?";
}

const char* toString(LightType type) {
    switch (type) {
        case LightType::Directional: return "directional";
        case LightType::Point: return "point";
        case LightType::Spot: return "spot";
    }
    return "?";
}

std::string referenceModelOf(const Material& material) {
    if (!material.reference.empty()) return material.reference;
    static const std::map<std::string, std::string, std::less<>> kDefaults = {
        {"Custom/My First Lighting Shader", "seed000"},
        {"varc/Forward", "varc-forward"},
        {"varc/SimpleDiffuse", "varc-simple-diffuse"},
        {"varc/GlslVertexLights", "varc-glsl-vertex-lights"},
        {"varc/DeferredGBuffer", "varc-deferred-gbuffer"},
        {"varc/SinglePassLit", "varc-single-pass-lit"},
        // varc's built-in fallbacks drawn directly: a ShadowCaster pass and nothing else.
        {"Legacy Shaders/VertexLit", "varc-caster"},
        {"Legacy Shaders/Diffuse", "varc-caster"},
        {"Legacy Shaders/Specular", "varc-caster"},
        {"Legacy Shaders/Bumped Diffuse", "varc-caster"},
        {"Legacy Shaders/Bumped Specular", "varc-caster"},
        {"Mobile/VertexLit", "varc-caster"},
        {"Mobile/Diffuse", "varc-caster"},
        {"Mobile/Bumped Diffuse", "varc-caster"},
        {"Standard", "varc-standard-caster"},
        {"Legacy Shaders/Transparent/Cutout/VertexLit", "varc-caster-cutout"},
        {"Legacy Shaders/Transparent/Cutout/Diffuse", "varc-caster-cutout"},
        {"Legacy Shaders/Transparent/Cutout/Specular", "varc-caster-cutout"},
    };
    auto it = kDefaults.find(material.shader);
    return it == kDefaults.end() ? std::string() : it->second;
}

}  // namespace varc::scene
