// SPDX-License-Identifier: Apache-2.0
// PropertyScenes: the generated scenes and lights of the property checks.
#include "varc/properties/PropertyScenes.h"

#include "varc/reader/PassView.h"

namespace varc::properties {

namespace {

scene::Object object(const std::string& shader, scene::MeshKind mesh, glm::vec3 position) {
    scene::Object result;
    result.mesh = mesh;
    result.transform.position = position;
    result.material.shader = shader;
    return result;
}

bool declares(const reader::PassView& pass, std::string_view keyword) {
    return pass.keywordIndex(keyword).has_value();
}

}  // namespace

LightSupport lightSupportOf(const reader::ShaderView& shader) {
    LightSupport support;
    support.forwardBase = shader.pass("ForwardBase").has_value();
    support.deferred = shader.pass("Deferred").has_value();
    std::optional<reader::PassView> add = shader.pass("ForwardAdd");
    if (!support.forwardBase || !add) return support;
    support.forwardAdd = true;
    const bool anyLightKeyword = declares(*add, "POINT") || declares(*add, "SPOT") ||
                                 declares(*add, "DIRECTIONAL") || declares(*add, "POINT_COOKIE") ||
                                 declares(*add, "DIRECTIONAL_COOKIE");
    support.point = !anyLightKeyword || declares(*add, "POINT");
    support.spot = declares(*add, "SPOT");
    support.directionalCookie = declares(*add, "DIRECTIONAL_COOKIE");
    support.pointCookie = declares(*add, "POINT_COOKIE");
    return support;
}

scene::Scene emptyScene(const std::string& shader, bool hdr, uint32_t size) {
    scene::Scene scene;
    scene.camera.position = {0.0f, 2.2f, -4.2f};
    scene.camera.target = {0.0f, -0.1f, 0.0f};
    scene.camera.fovY = 45.0f;
    scene.camera.width = scene.camera.height = size;
    scene.camera.hdr = hdr;
    scene.ambient = glm::vec3(0.0f);
    scene.objects.push_back(object(shader, scene::MeshKind::Sphere, {-1.2f, 0.0f, 0.0f}));
    scene::Object cube = object(shader, scene::MeshKind::Cube, {1.2f, 0.0f, 0.0f});
    cube.transform.rotationDegrees = {0.0f, 30.0f, 0.0f};
    scene.objects.push_back(cube);
    scene::Object plane = object(shader, scene::MeshKind::Plane, {0.0f, -0.5f, 0.0f});
    plane.transform.scale = glm::vec3(0.3f);  // 3 m x 3 m
    scene.objects.push_back(plane);
    return scene;
}

scene::Scene withLights(scene::Scene scene, const std::vector<scene::Light>& lights) {
    scene.lights.insert(scene.lights.end(), lights.begin(), lights.end());
    return scene;
}

scene::Light keyDirectional() {
    scene::Light light;
    light.type = scene::LightType::Directional;
    light.color = {1.0f, 0.95f, 0.9f};
    light.transform.rotationDegrees = {50.0f, -30.0f, 0.0f};
    return light;
}

scene::Light secondDirectional() {
    scene::Light light;
    light.type = scene::LightType::Directional;
    light.color = {0.3f, 0.5f, 0.9f};
    light.intensity = 0.8f;
    light.transform.rotationDegrees = {30.0f, 60.0f, 0.0f};
    light.renderMode = scene::LightRenderMode::Important;
    return light;
}

scene::Light keyPoint() {
    scene::Light light;
    light.type = scene::LightType::Point;
    light.color = {0.4f, 0.7f, 1.0f};
    light.intensity = 1.5f;
    light.transform.position = {-0.4f, 1.2f, -1.0f};
    light.range = 4.0f;
    light.renderMode = scene::LightRenderMode::Important;
    return light;
}

scene::Light keySpot() {
    scene::Light light;
    light.type = scene::LightType::Spot;
    light.color = {1.0f, 0.6f, 0.3f};
    light.intensity = 2.0f;
    light.transform.position = {1.2f, 2.5f, 0.0f};
    light.transform.rotationDegrees = {90.0f, 0.0f, 0.0f};  // +z -> -y: straight down
    light.range = 5.0f;
    light.spotAngle = 70.0f;
    light.renderMode = scene::LightRenderMode::Important;
    return light;
}

// Cube top face at y = 0.5 (1.3 m below the light, range 1.1), cube bounds radius 0.866 (1.8 m
// from the light: reached), plane 2.3 m below (bounds radius 2.12, 2.59 m away: reached),
// sphere bounds 3 m away (not reached).
scene::Light outOfRangePoint() {
    scene::Light light;
    light.type = scene::LightType::Point;
    light.intensity = 2.0f;
    light.transform.position = {1.2f, 1.8f, 0.0f};
    light.range = 1.1f;
    light.renderMode = scene::LightRenderMode::Important;
    return light;
}

scene::Light outOfRangeSpot() {
    scene::Light light = outOfRangePoint();
    light.type = scene::LightType::Spot;
    light.transform.rotationDegrees = {90.0f, 0.0f, 0.0f};
    light.spotAngle = 80.0f;
    return light;
}

scene::Scene similar(const scene::Scene& original, float scale, glm::vec3 offset) {
    scene::Scene scene = original;
    auto move = [&](glm::vec3 p) { return scale * p + offset; };
    scene.camera.position = move(scene.camera.position);
    scene.camera.target = move(scene.camera.target);
    scene.camera.nearPlane *= scale;
    scene.camera.farPlane *= scale;
    for (scene::Object& object : scene.objects) {
        object.transform.position = move(object.transform.position);
        object.transform.scale *= scale;
    }
    for (scene::Light& light : scene.lights) {
        light.transform.position = move(light.transform.position);
        light.range *= scale;
        light.cookieSize *= scale;
    }
    return scene;
}

scene::Scene turned(const scene::Scene& original, float degrees) {
    scene::Scene scene = original;
    const glm::mat3 turn = scene::Transform{{}, {0.0f, degrees, 0.0f}, glm::vec3(1.0f)}.rotation();
    scene.camera.position = turn * scene.camera.position;
    scene.camera.target = turn * scene.camera.target;
    for (scene::Object& object : scene.objects) {
        object.transform.position = turn * object.transform.position;
        object.transform.rotationDegrees.y += degrees;
    }
    for (scene::Light& light : scene.lights) {
        light.transform.position = turn * light.transform.position;
        light.transform.rotationDegrees.y += degrees;
    }
    return scene;
}

scene::Light overheadDirectional() {
    scene::Light light = keyDirectional();
    light.transform.rotationDegrees = {90.0f, 0.0f, 0.0f};  // +z -> -y: straight down
    return light;
}

scene::Light onLightAxis(scene::Light light, float height) {
    light.transform.position = {0.0f, height, 0.0f};
    return light;
}

scene::Scene fromAbove(scene::Scene scene) {
    scene.camera.position = {0.0f, 6.5f, 0.0f};
    scene.camera.target = glm::vec3(0.0f);
    return scene;
}

scene::Scene floorFromAbove(const std::string& shader, uint32_t size) {
    scene::Scene scene = fromAbove(emptyScene(shader, true, size));
    scene.objects.erase(scene.objects.begin(), scene.objects.end() - 1);  // the plane is last
    return scene;
}

scene::Light underFloor(scene::Light light) {
    light.transform.rotationDegrees = {-90.0f, 0.0f, 0.0f};  // +z -> +y: straight up
    light.transform.position = {0.0f, -6.0f, 0.0f};
    light.range = 12.0f;
    return light;
}

scene::Scene objectsTurned(const scene::Scene& original, float degrees) {
    scene::Scene scene = original;
    const glm::mat3 turn = scene::Transform{{}, {0.0f, degrees, 0.0f}, glm::vec3(1.0f)}.rotation();
    for (scene::Object& object : scene.objects) {
        object.transform.position = turn * object.transform.position;
        object.transform.rotationDegrees.y += degrees;
    }
    return scene;
}

scene::Scene mirrored(const scene::Scene& original) {
    scene::Scene scene = original;
    auto mirror = [](glm::vec3 p) { return glm::vec3(-p.x, p.y, p.z); };
    auto mirrorAngles = [](glm::vec3 a) { return glm::vec3(a.x, -a.y, -a.z); };
    scene.camera.position = mirror(scene.camera.position);
    scene.camera.target = mirror(scene.camera.target);
    for (scene::Object& object : scene.objects) {
        object.transform.position = mirror(object.transform.position);
        object.transform.rotationDegrees = mirrorAngles(object.transform.rotationDegrees);
        // S M = T(S t) (S R S) (S Sc): each vertex lands on the mirror of its original, so
        // the triangulation (and per-vertex shading) is mirrored exactly.
        object.transform.scale.x = -object.transform.scale.x;
    }
    for (scene::Light& light : scene.lights) {
        light.transform.position = mirror(light.transform.position);
        light.transform.rotationDegrees = mirrorAngles(light.transform.rotationDegrees);
    }
    return scene;
}

}  // namespace varc::properties
