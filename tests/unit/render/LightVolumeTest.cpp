// SPDX-License-Identifier: Apache-2.0
// LightVolume: the volume meshes hold everything their light reaches, and the faces drawn follow
// where the camera is (issue #6).
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/constants.hpp>
#include <map>
#include <random>
#include <set>

#include "varc/render/LightVolume.h"
#include "varc/scene/Scene.h"

namespace varc::render {
namespace {

// Largest signed distance of |p| to the outward face planes of |mesh| placed by |toWorld|.
float planeDistance(const scene::Mesh& mesh, const glm::mat4& toWorld, const glm::vec3& p) {
    float distance = -INFINITY;
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::vec3 a(toWorld * glm::vec4(mesh.positions[mesh.indices[t]], 1.0f));
        const glm::vec3 b(toWorld * glm::vec4(mesh.positions[mesh.indices[t + 1]], 1.0f));
        const glm::vec3 c(toWorld * glm::vec4(mesh.positions[mesh.indices[t + 2]], 1.0f));
        distance = std::max(distance, glm::dot(glm::normalize(glm::cross(b - a, c - a)), p - a));
    }
    return distance;
}

// Every directed edge appears once and its reverse once: closed, consistently wound.
void expectClosedAndConsistent(const scene::Mesh& mesh) {
    std::set<std::pair<uint32_t, uint32_t>> edges;
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        for (size_t k = 0; k < 3; ++k) {
            auto edge = std::make_pair(mesh.indices[t + k], mesh.indices[t + (k + 1) % 3]);
            EXPECT_TRUE(edges.insert(edge).second) << "edge used twice in one direction";
        }
    }
    for (const auto& [a, b] : edges)
        EXPECT_TRUE(edges.count({b, a})) << "open edge " << a << "-" << b;
}

// Outward winding: every face's cross(b - a, c - a) points away from the origin side.
void expectOutwardFaces(const scene::Mesh& mesh, const glm::vec3& interior) {
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::vec3& a = mesh.positions[mesh.indices[t]];
        const glm::vec3 n = glm::cross(mesh.positions[mesh.indices[t + 1]] - a,
                                       mesh.positions[mesh.indices[t + 2]] - a);
        EXPECT_GT(glm::dot(n, a - interior), 0.0f) << "face " << t / 3;
    }
}

TEST(LightVolume, SphereIsClosedOutwardAndHoldsTheUnitBall) {
    const scene::Mesh& sphere = unitSphereVolume();
    EXPECT_EQ(sphere.indices.size(), 80u * 3u);
    expectClosedAndConsistent(sphere);
    expectOutwardFaces(sphere, glm::vec3(0.0f));
    std::mt19937 rng(7);
    std::normal_distribution<float> normal;
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 onBall = glm::normalize(glm::vec3(normal(rng), normal(rng), normal(rng)));
        EXPECT_LE(planeDistance(sphere, glm::mat4(1.0f), onBall), 0.0f) << i;
    }
    // ... and not much more: the overdraw beyond the ball stays small.
    for (const glm::vec3& p : sphere.positions) EXPECT_LT(glm::length(p), 1.1f);
}

TEST(LightVolume, PyramidHoldsTheSpotConeUpToItsRange) {
    const scene::Mesh& pyramid = unitPyramidVolume();
    expectClosedAndConsistent(pyramid);
    expectOutwardFaces(pyramid, glm::vec3(0.0f, 0.0f, 0.5f));
    scene::Light spot;
    spot.type = scene::LightType::Spot;
    spot.transform.position = {1.0f, 2.0f, 3.0f};
    spot.transform.rotationDegrees = {35.0f, -70.0f, 10.0f};
    spot.range = 4.0f;
    spot.spotAngle = 50.0f;
    scene::Camera camera;
    camera.position = {0.0f, 2.0f, -20.0f};
    camera.target = spot.transform.position;
    const LightVolume volume = chooseLightVolume(spot, camera, scene::cameraMatrices(camera));
    ASSERT_EQ(volume.mesh, &pyramid);
    const glm::mat4 lightToWorld = spot.transform.rigidToWorld();
    const float half = glm::radians(spot.spotAngle) * 0.5f;
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int i = 0; i < 2000; ++i) {
        // A point of the cone cut at the range, in light space (+z forward).
        const float angle = half * unit(rng), around = glm::two_pi<float>() * unit(rng);
        const float distance = spot.range * unit(rng);
        const glm::vec3 local =
            distance * glm::vec3(std::sin(angle) * std::cos(around),
                                 std::sin(angle) * std::sin(around), std::cos(angle));
        const glm::vec3 world(lightToWorld * glm::vec4(local, 1.0f));
        EXPECT_LE(planeDistance(pyramid, volume.objectToWorld, world), 1e-4f) << i;
    }
    // The cone's edge at the range touches the pyramid's side: nothing much wider is drawn.
    const glm::vec3 edge(lightToWorld *
                         glm::vec4(spot.range * std::tan(half) * 1.05f, 0.0f, spot.range, 1.0f));
    EXPECT_GT(planeDistance(pyramid, volume.objectToWorld, edge), 0.0f);
}

scene::Light pointLight(glm::vec3 position, float range) {
    scene::Light light;
    light.type = scene::LightType::Point;
    light.transform.position = position;
    light.range = range;
    return light;
}

LightVolumeDraw drawOf(const scene::Light& light, const scene::Camera& camera) {
    return chooseLightVolume(light, camera, scene::cameraMatrices(camera)).draw;
}

TEST(LightVolume, DirectionalLightsAreFullScreenQuads) {
    scene::Light sun;
    sun.type = scene::LightType::Directional;
    const LightVolume volume = chooseLightVolume(sun, scene::Camera{}, scene::cameraMatrices({}));
    EXPECT_EQ(volume.draw, LightVolumeDraw::FullScreenQuad);
    EXPECT_EQ(volume.mesh, nullptr);
}

TEST(LightVolume, FacesFollowWhetherTheNearPlaneCanCutTheVolume) {
    scene::Camera camera;  // at (0, 0, -5), near 0.1, fov 60, square
    const float nearCorner =
        0.1f * std::sqrt(1.0f + 2.0f * std::pow(std::tan(glm::radians(30.0f)), 2.0f));
    EXPECT_EQ(drawOf(pointLight({0, 0, 0}, 2.0f), camera), LightVolumeDraw::FrontFaces);
    EXPECT_EQ(drawOf(pointLight({0, 0, -4}, 2.0f), camera), LightVolumeDraw::BackFaces);
    // Outside the sphere but closer than the near plane's corners: the near plane may cut it.
    const float gap = 1.001f * 2.0f + 0.5f * nearCorner;
    EXPECT_EQ(drawOf(pointLight({0, 0, -5.0f + gap}, 2.0f), camera), LightVolumeDraw::BackFaces);
    const float farGap = 1.001f * 2.0f + 2.0f * nearCorner + 0.1f;
    EXPECT_EQ(drawOf(pointLight({0, 0, -5.0f + farGap}, 2.0f), camera),
              LightVolumeDraw::FrontFaces);
}

TEST(LightVolume, AVolumeBeyondTheFarPlaneAroundTheCameraFallsBackToTheQuad) {
    scene::Camera camera;
    camera.farPlane = 20.0f;
    EXPECT_EQ(drawOf(pointLight({0, 0, -5}, 25.0f), camera), LightVolumeDraw::FullScreenQuad);
    // Outside, the front faces are what counts: far-plane clipping takes nothing visible away.
    EXPECT_EQ(drawOf(pointLight({0, 0, 30}, 25.0f), camera), LightVolumeDraw::FrontFaces);
}

// The validation scenes must keep exercising all three ways a deferred light is drawn.
TEST(LightVolume, TheVolumeScenesUseEveryDraw) {
    for (const char* name : {"volumes-hdr.json", "volumes-ldr.json"}) {
        auto scene =
            scene::loadScene(std::string(VARC_SOURCE_DIR) + "/tests/scenes/deferred/" + name);
        ASSERT_TRUE(scene.ok()) << scene.error().detail;
        const scene::CameraMatrices matrices = scene::cameraMatrices(scene->camera);
        std::map<LightVolumeDraw, int> draws;
        for (const scene::Light& light : scene->lights) {
            ++draws[chooseLightVolume(light, scene->camera, matrices).draw];
        }
        EXPECT_EQ(draws[LightVolumeDraw::FrontFaces], 3) << name;
        EXPECT_EQ(draws[LightVolumeDraw::BackFaces], 1) << name;
        EXPECT_EQ(draws[LightVolumeDraw::FullScreenQuad], 2) << name;  // directional + huge point
    }
}

}  // namespace
}  // namespace varc::render
