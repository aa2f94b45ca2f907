// SPDX-License-Identifier: Apache-2.0
// Value tests of UnityCG.cginc's vertex helpers (issue #27, docs/BUILTIN_API.md), run on
// lavapipe by tests/vulkan/helpers/UnityCgMiscValues.shader and compared with their documented
// meaning computed here: pixel snapping rounds the clip position to the pixel grid of
// _ScreenParams; a shadow caster's world position moves against its world normal by
// unity_LightShadowBias.z * sin(angle to the light) before the view-projection, then gets the
// linear bias (z + saturate(bias.x / w) w, at most w); vert_img is the clip position and uv of
// an image-effect vertex; COMPUTE_EYEDEPTH is the view-space distance in front of the camera
// (-z); UNITY_OPAQUE_ALPHA forces alpha to 1. scripts/builtin-api.py counts the names on the
// api-value-tested lines below as implemented.
//
// api-value-tested: UnityPixelSnap UnityClipSpaceShadowCasterPos TRANSFER_SHADOW_CASTER
// api-value-tested: TRANSFER_SHADOW_CASTER_NORMALOFFSET TRANSFER_SHADOW_CASTER_NOPOS
// api-value-tested: TRANSFER_SHADOW_CASTER_NOPOS_LEGACY vert_img COMPUTE_EYEDEPTH
// api-value-tested: UNITY_OPAQUE_ALPHA
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <glm/glm.hpp>
#include <string>

#include "FormulaComparison.h"
#include "QuadDrawTest.h"

namespace varc::render {
namespace {

constexpr uint32_t kSize = 32;
using Vec4 = std::array<double, 4>;
using Formula = std::function<Vec4(double s, double t)>;

// An object matrix that rotates about z, scales unevenly (2, 1, 0.5) and translates; a view that
// translates; a perspective-like projection (w = -view z).
struct Scene {
    glm::dmat4 objectToWorld{1.0}, worldToObject{1.0}, view{1.0}, viewProjection{1.0};
    glm::dvec4 light{0.3, 0.8, -0.5, 0.0};  // directional: the direction towards the light
    Scene() {
        objectToWorld[0] = {1.6, 1.2, 0.0, 0.0};
        objectToWorld[1] = {-0.6, 0.8, 0.0, 0.0};
        objectToWorld[2] = {0.0, 0.0, 0.5, 0.0};
        objectToWorld[3] = {0.5, -1.0, 2.0, 1.0};
        worldToObject = glm::inverse(objectToWorld);
        view[3] = {-0.25, 0.5, -4.0, 1.0};
        glm::dmat4 projection(0.0);
        projection[0][0] = 1.5;
        projection[1][1] = -2.0;
        projection[2][2] = 0.1;
        projection[2][3] = -1.0;
        projection[3][2] = 0.3;
        viewProjection = projection * view;
    }
    void set(ShaderValues& values, double normalBias) const {
        values.set("unity_ObjectToWorld", glm::mat4(objectToWorld));
        values.set("unity_WorldToObject", glm::mat4(worldToObject));
        values.set("unity_MatrixV", glm::mat4(view));
        values.set("unity_MatrixVP", glm::mat4(viewProjection));
        values.set("_WorldSpaceLightPos0", glm::vec4(light));
        values.set("unity_LightShadowBias",
                   glm::vec4(0.05f, 0.0f, static_cast<float>(normalBias), 0.0f));
    }
};

glm::dvec4 testVertex(double s, double t) { return {s - 0.5, t - 0.5, 0.2 + 0.3 * s, 1.0}; }
glm::dvec3 testNormal(double s, double t) {
    return glm::normalize(glm::dvec3(0.3, s - 0.5, 1 - t));
}

// The caster's clip position before the linear bias.
glm::dvec4 casterPos(const Scene& scene, double s, double t, double normalBias) {
    glm::dvec4 world = scene.objectToWorld * testVertex(s, t);
    if (normalBias != 0.0) {
        // Normals transform by the inverse transpose.
        glm::dvec3 n =
            glm::normalize(glm::transpose(glm::dmat3(scene.worldToObject)) * testNormal(s, t));
        glm::dvec3 toLight = glm::normalize(glm::dvec3(scene.light));
        double cosine = glm::dot(n, toLight);
        world -= glm::dvec4(n * normalBias * std::sqrt(1 - cosine * cosine), 0.0);
    }
    return scene.viewProjection * world;
}
glm::dvec4 linearBias(glm::dvec4 clip, double bias) {
    clip.z = std::min(clip.z + std::clamp(bias / clip.w, 0.0, 1.0) * clip.w, clip.w);
    return clip;
}

class UnityCgMiscValueTest : public testing::QuadDrawTest {
protected:
    UnityCgMiscValueTest() : QuadDrawTest(kSize) {}

    void expectFormula(const std::string& keyword, const ShaderValues& values,
                       const Formula& formula, int channels) {
        expectPassFormula("Test/UnityCgMiscValues", keyword, values, whiteTextures(), formula,
                          channels, 2e-5, 2e-4);
    }
};

// x and y of the clip position go to the nearest point of the half-resolution grid (hpc =
// _ScreenParams.xy / 2 per unit of NDC) and back; z and w are unchanged. The inputs keep every
// x * hpc at least 0.01 away from a rounding tie.
TEST_F(UnityCgMiscValueTest, PixelSnap) {
    ShaderValues values;
    values.set("_ScreenParams", glm::vec4(64.0f, 48.0f, 1.0f + 1.0f / 64, 1.0f + 1.0f / 48));
    expectFormula(
        "CM_SNAP", values,
        [](double s, double t) {
            double w = 1.5 + s;
            double x = std::round(0.93 * (2 * s - 1) * 32.0) / 32.0 * w;
            double y = std::round(0.93 * (2 * t - 1) * 24.0) / 24.0 * w;
            return Vec4{x, y, 0.3, w};
        },
        4);
}

// Both overloads, without the normal offset (bias.z = 0) and with it.
TEST_F(UnityCgMiscValueTest, ShadowCasterPosition) {
    Scene scene;
    for (double normalBias : {0.0, 0.15}) {
        ShaderValues values;
        scene.set(values, normalBias);
        expectFormula(
            "CM_CASTER", values,
            [&scene, normalBias](double s, double t) {
                glm::dvec4 p = casterPos(scene, s, t, normalBias);
                return Vec4{p.x, p.y, p.z, p.w};
            },
            4);
    }
}

// The caster macros read v.vertex and v.normal and store the biased position.
TEST_F(UnityCgMiscValueTest, ShadowCasterMacros) {
    Scene scene;
    ShaderValues values;
    scene.set(values, 0.15);
    expectFormula(
        "CM_CASTER_MACROS", values,
        [&scene](double s, double t) {
            glm::dvec4 p = linearBias(casterPos(scene, s, t, 0.15), 0.05);
            return Vec4{p.z, p.z, p.z, p.w};
        },
        4);
}

// vert_img: UnityObjectToClipPos of the vertex and the texcoord as it is.
TEST_F(UnityCgMiscValueTest, ImageEffectVertex) {
    Scene scene;
    ShaderValues values;
    scene.set(values, 0.0);
    expectFormula(
        "CM_IMG", values,
        [&scene](double s, double t) {
            glm::dvec4 clip =
                scene.viewProjection * scene.objectToWorld * glm::dvec4(s - 0.5, t, 0.25, 1.0);
            return Vec4{clip.x, clip.w, t, s};
        },
        4);
}

TEST_F(UnityCgMiscValueTest, EyeDepthAndOpaqueAlpha) {
    Scene scene;
    ShaderValues values;
    scene.set(values, 0.0);
    expectFormula(
        "CM_EYEDEPTH", values,
        [&scene](double s, double t) {
            glm::dvec4 viewPos = scene.view * scene.objectToWorld * testVertex(s, t);
            return Vec4{-viewPos.z, 1.0, 0, 0};
        },
        2);
}

}  // namespace
}  // namespace varc::render
