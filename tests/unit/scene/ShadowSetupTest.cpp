// SPDX-License-Identifier: Apache-2.0
// ShadowSetup against closed forms stated here, not against other varc code (issue #29 item 4):
// the GPU path and the CPU reference both take these cameras, so a mistake in them would be
// invisible to the image comparison. Per light type: where a world point lands in the map (the
// cone's angle, Vulkan's cube-face rules, the cascade tiles), its depth (perspective depth
// between the near plane and the range), that the caster camera draws a point where the
// receiver's matrix looks it up, and the bias mapping.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "varc/scene/ShadowSetup.h"

namespace varc::scene {
namespace {

constexpr float kTolerance = 2e-4f;

glm::vec3 project(const glm::mat4& matrix, const glm::vec3& p) {
    const glm::vec4 clip = matrix * glm::vec4(p, 1.0f);
    return glm::vec3(clip) / clip.w;
}

// Vulkan depth of a perspective camera with near n and far f at view distance d.
float perspectiveDepth(float n, float f, float d) { return f * (d - n) / (d * (f - n)); }

Light shadowedLight(LightType type) {
    Light light;
    light.type = type;
    light.transform.position = {1.0f, 2.0f, 3.0f};  // rotation 0: the light travels along +z
    light.range = 12.0f;
    light.spotAngle = 50.0f;
    light.shadows = ShadowType::Hard;
    light.shadowBias = 0.07f;
    light.shadowNormalBias = 0.6f;
    light.shadowNearPlane = 0.3f;
    return light;
}

TEST(ShadowSetup, SpotMapCoversTheConeWithPerspectiveDepth) {
    const Light light = shadowedLight(LightType::Spot);
    const ShadowCamera camera = spotShadowCamera(light);
    const float tanHalf = std::tan(glm::radians(light.spotAngle * 0.5f));
    const glm::vec3 across[] = {{1, 0, 0}, {0, 1, 0}, glm::normalize(glm::vec3(1, -1, 0))};
    for (float d : {0.5f, 4.0f, 11.5f}) {
        for (float fraction : {0.0f, 0.4f, 0.99f}) {
            for (const glm::vec3& r : across) {
                const float offset = fraction * d * tanHalf;
                const glm::vec3 p = light.transform.position + glm::vec3(0, 0, d) + offset * r;
                const glm::vec3 lookup = project(camera.worldToShadow, p);
                // The map's square spans the cone: the edge of the cone is the edge of the map.
                EXPECT_NEAR(glm::length(glm::vec2(lookup) - 0.5f), 0.5f * fraction, kTolerance);
                EXPECT_NEAR(lookup.z, perspectiveDepth(light.shadowNearPlane, light.range, d),
                            kTolerance);
                // The caster's camera draws p into the texel and depth the receiver reads.
                const glm::vec3 drawn = project(camera.matrices.viewProjection, p);
                EXPECT_NEAR((drawn.x + 1.0f) * 0.5f, lookup.x, kTolerance);
                EXPECT_NEAR((drawn.y + 1.0f) * 0.5f, lookup.y, kTolerance);
                EXPECT_NEAR(drawn.z, lookup.z, kTolerance);
            }
        }
    }
    EXPECT_FLOAT_EQ(camera.bias.x, light.shadowBias / 100.0f);
    EXPECT_FLOAT_EQ(camera.bias.z, light.shadowNormalBias / 20.0f);
}

// Vulkan's cube-map face selection and face coordinates (the spec's table "Cube map face
// selection"): for direction r with major axis face, (s, t) in [0, 1].
glm::vec2 cubeFaceCoordinates(const glm::vec3& r, int face) {
    float sc = 0, tc = 0, ma = 0;
    switch (face) {
        case 0:
            sc = -r.z, tc = -r.y, ma = r.x;
            break;  // +X
        case 1:
            sc = r.z, tc = -r.y, ma = -r.x;
            break;  // -X
        case 2:
            sc = r.x, tc = r.z, ma = r.y;
            break;  // +Y
        case 3:
            sc = r.x, tc = -r.z, ma = -r.y;
            break;  // -Y
        case 4:
            sc = r.x, tc = -r.y, ma = r.z;
            break;  // +Z
        default:
            sc = -r.x, tc = -r.y, ma = -r.z;
            break;  // -Z
    }
    return {0.5f * (sc / ma + 1.0f), 0.5f * (tc / ma + 1.0f)};
}

TEST(ShadowSetup, PointFacesFollowVulkanCubeSampling) {
    const Light light = shadowedLight(LightType::Point);
    const PointShadowCamera camera = pointShadowCamera(light);
    const float n = light.shadowNearPlane, f = light.range;
    const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int face = 0; face < 6; ++face) {
        // Directions whose major axis is this face's: the axis plus offsets in the other two.
        for (glm::vec2 offset : {glm::vec2(0, 0), glm::vec2(0.5f, -0.3f), glm::vec2(-0.9f, 0.8f)}) {
            glm::vec3 r = axes[face];
            const int u = face / 2 == 0 ? 1 : 0, v = face / 2 == 2 ? 1 : 2;
            r[u] = offset.x;
            r[v] = offset.y;
            for (float m : {0.5f, 3.0f, 11.0f}) {  // distance along the major axis
                const glm::vec3 drawn =
                    project(camera.faceViewProjection[face], light.transform.position + r * m);
                const glm::vec2 st = cubeFaceCoordinates(r, face);
                EXPECT_NEAR((drawn.x + 1.0f) * 0.5f, st.x, kTolerance) << face;
                EXPECT_NEAR((drawn.y + 1.0f) * 0.5f, st.y, kTolerance) << face;
                const float depth = perspectiveDepth(n, f, m);
                EXPECT_NEAR(drawn.z, depth, kTolerance) << face;
                // The receiver's reconstruction from _LightProjectionParams (bias aside).
                EXPECT_NEAR(-camera.projectionParams.x + camera.projectionParams.y / m, depth,
                            kTolerance);
            }
        }
    }
    EXPECT_FLOAT_EQ(camera.projectionParams.z, light.shadowBias / 10.0f);
    EXPECT_FLOAT_EQ(camera.bias.z, light.shadowNormalBias / 20.0f);
    EXPECT_FLOAT_EQ(camera.bias.x, 0.0f);
}

// The eight corners of the camera's view frustum between view depths |near| and |far|, from the
// camera's look-at frame (world up +y; the camera in these tests never looks straight up).
std::array<glm::vec3, 8> sliceCorners(const Camera& camera, float near, float far) {
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    const glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0, 1, 0), forward));
    const glm::vec3 up = glm::cross(forward, right);
    const float tanHalf = std::tan(glm::radians(camera.fovY * 0.5f));
    const float aspect = static_cast<float>(camera.width) / static_cast<float>(camera.height);
    std::array<glm::vec3, 8> corners{};
    int i = 0;
    for (float depth : {near, far}) {
        for (float sx : {-1.0f, 1.0f}) {
            for (float sy : {-1.0f, 1.0f}) {
                corners[i++] = camera.position + depth * forward +
                               sx * depth * tanHalf * aspect * right + sy * depth * tanHalf * up;
            }
        }
    }
    return corners;
}

Scene cascadeScene(int cascades, bool stableFit) {
    Scene scene;
    scene.camera.position = {0.0f, 3.0f, -6.0f};
    scene.camera.target = {0.5f, 0.0f, 0.0f};
    scene.camera.width = 320;
    scene.camera.height = 240;
    scene.shadowDistance = 30.0f;
    scene.shadowCascades = cascades;
    scene.stableFit = stableFit;
    return scene;
}

// Checks one cascade: the slice's corners fall inside its tile, the caster's camera draws them
// where the receiver looks them up, and a caster above the slice towards the light is in range.
void expectCascadeCoversSlice(const DirectionalShadowSetup& setup, const Scene& scene, int c,
                              const glm::vec3& towardsLight) {
    const float res = static_cast<float>(setup.resolution);
    const glm::vec2 low = glm::vec2(setup.tileOrigin[c]) / res;
    const glm::vec2 high = low + static_cast<float>(setup.tileSize) / res;
    for (const glm::vec3& corner :
         sliceCorners(scene.camera, setup.splitsNear[c], setup.splitsFar[c])) {
        const glm::vec3 lookup = project(setup.worldToShadow[c], corner);
        EXPECT_GE(lookup.x, low.x - kTolerance) << c;
        EXPECT_LE(lookup.x, high.x + kTolerance) << c;
        EXPECT_GE(lookup.y, low.y - kTolerance) << c;
        EXPECT_LE(lookup.y, high.y + kTolerance) << c;
        EXPECT_GE(lookup.z, -kTolerance) << c;
        EXPECT_LE(lookup.z, 1.0f + kTolerance) << c;
        const glm::vec3 drawn = project(setup.viewProjection[c], corner);
        EXPECT_NEAR(low.x + (drawn.x + 1.0f) * 0.5f * (high.x - low.x), lookup.x, kTolerance);
        EXPECT_NEAR(low.y + (drawn.y + 1.0f) * 0.5f * (high.y - low.y), lookup.y, kTolerance);
        EXPECT_NEAR(drawn.z, lookup.z, kTolerance);
        if (setup.stableFit) {
            const glm::vec4 sphere = setup.splitSpheres[c];
            EXPECT_LE(glm::length(corner - glm::vec3(sphere)), sphere.w * (1.0f + 1e-4f)) << c;
        }
        // A caster most of the shadow distance towards the light still lands in the map's depth.
        const float caster =
            project(setup.worldToShadow[c], corner + 0.9f * scene.shadowDistance * towardsLight).z;
        EXPECT_GE(caster, -kTolerance) << c;
        EXPECT_LE(caster, lookup.z + kTolerance) << c;
    }
}

TEST(ShadowSetup, DirectionalCascadesSplitTheShadowDistanceAndCoverTheirSlices) {
    Light light = shadowedLight(LightType::Directional);
    light.transform.rotationDegrees = {90.0f, 0.0f, 0.0f};  // Unity's x = 90: the light points down
    const glm::vec3 towardsLight{0.0f, 1.0f, 0.0f};
    for (int cascades : {1, 2, 4}) {
        for (bool stableFit : {true, false}) {
            const Scene scene = cascadeScene(cascades, stableFit);
            const DirectionalShadowSetup setup = directionalShadowSetup(scene, light);
            ASSERT_EQ(setup.cascades, cascades);
            EXPECT_EQ(setup.tileSize, cascades == 1 ? setup.resolution : setup.resolution / 2);
            // Splits: the camera's near plane, the scene's fractions of the shadow distance, and
            // the shadow distance, each slice starting where the one before ends.
            const float d = scene.shadowDistance;
            std::vector<float> ends = {d};
            if (cascades == 2) ends = {scene.cascadeSplits.x * d, d};
            if (cascades == 4)
                ends = {scene.cascadeSplits.x * d, scene.cascadeSplits.y * d,
                        scene.cascadeSplits.z * d, d};
            for (int c = 0; c < cascades; ++c) {
                EXPECT_NEAR(setup.splitsNear[c], c == 0 ? scene.camera.nearPlane : ends[c - 1],
                            1e-4f);
                EXPECT_NEAR(setup.splitsFar[c], ends[c], 1e-4f);
                if (stableFit) {
                    EXPECT_NEAR(setup.splitSqRadii[c],
                                setup.splitSpheres[c].w * setup.splitSpheres[c].w, 1e-3f);
                }
                expectCascadeCoversSlice(setup, scene, c, towardsLight);
            }
        }
    }
}

TEST(ShadowSetup, ShadowsFadeOverTheLastFifthOfTheShadowDistance) {
    Light light = shadowedLight(LightType::Directional);
    light.shadowStrength = 0.75f;
    Scene scene;
    scene.shadowDistance = 40.0f;
    const glm::vec4 data = lightShadowData(light, scene);
    EXPECT_FLOAT_EQ(data.x, 0.25f);  // shadowed light keeps 1 - strength
    auto fade = [&](float depth) { return std::clamp(depth * data.z + data.w, 0.0f, 1.0f); };
    EXPECT_NEAR(fade(0.0f), 0.0f, 1e-6f);
    EXPECT_NEAR(fade(0.8f * scene.shadowDistance), 0.0f, 1e-5f);
    EXPECT_NEAR(fade(0.9f * scene.shadowDistance), 0.5f, 1e-5f);
    EXPECT_NEAR(fade(scene.shadowDistance), 1.0f, 1e-5f);
}

}  // namespace
}  // namespace varc::scene
