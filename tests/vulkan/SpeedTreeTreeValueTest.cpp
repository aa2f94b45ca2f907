// SPDX-License-Identifier: Apache-2.0
// Value tests of varc's SpeedTree include files, whole vertices and surfaces:
// OffsetSpeedTreeVertex of SpeedTree 7 and 8 trees (a calm tree does not move, wind moves it,
// the LOD blend), SpeedTree 7's surface path and SpeedTreeBillboardVert (the billboard's
// documented geometry), on lavapipe over the grid of tests/vulkan/helpers/SpeedTreeValues.shader.
//
// api-value-tested: SpeedTreeBillboardVert SpeedTreeFrag SPEEDTREE_COPY_FRAG
#include "SpeedTreeValueTest.h"

namespace varc::render::speedtree {
namespace {

// The whole vertex path (OffsetSpeedTreeVertex of SpeedTree 7 leaves, fronds and branches at
// the best and palm qualities, and of SpeedTree 8 with palm wind) with the wind on: a calm tree
// (zero _ST_Wind* uniforms; then zero strengths and distances with running clocks) keeps every
// vertex and normal; the same variants with wind move nearly every vertex.
TEST_F(SpeedTreeValueTest, CalmTreesDoNotMove) {
    ShaderValues calm;
    calm.set("_WindEnabled", 1.0f);
    calm.set("unity_ObjectToWorld", glm::mat4(1.0f));
    calm.set("unity_WorldToObject", glm::mat4(1.0f));
    ShaderValues clocks = calm;
    clocks.set("_GlobalWindTime", 12.5f);
    clocks.set("_ST_WindGlobal", glm::vec4(3.0f, 0.0f, 5.0f, 1.5f));
    clocks.set("_ST_WindBranch", glm::vec4(2.0f, 0.0f, 0.0f, 0.0f));
    clocks.set("_ST_WindBranchTwitch", glm::vec4(0.5f, 1.7f, 0.0f, 0.0f));
    clocks.set("_ST_WindBranchWhip", glm::vec4(0.4f, 0.0f, 0.0f, 0.0f));
    clocks.set("_ST_WindBranchAdherences", glm::vec4(0.3f, 0.2f, 0.0f, 0.0f));
    clocks.set("_ST_WindTurbulences", glm::vec4(0.5f, 0.0f, 0.0f, 0.0f));
    clocks.set("_ST_WindLeaf1Ripple", glm::vec4(1.7f, 0.0f, 0.0f, 0.0f));
    clocks.set("_ST_WindLeaf1Tumble", glm::vec4(1.1f, 0.8f, 0.6f, 0.3f));
    clocks.set("_ST_WindLeaf1Twitch", glm::vec4(0.4f, 0.5f, 0.5f, 0.0f));
    clocks.set("_ST_WindFrondRipple", glm::vec4(0.9f, 0.0f, 2.5f, 0.0f));
    auto still = [](double u, double v) {
        Vec3 p = position(u, v);
        return Vec4{p[0], p[1], p[2], 0.0};
    };
    for (const char* keyword : {"ST7_LEAF", "ST7_FROND", "ST7_BRANCH", "ST8_TREE"}) {
        for (float quality : {4.0f, 5.0f}) {
            calm.set("_WindQuality", quality);
            clocks.set("_WindQuality", quality);
            expectFormula(keyword, still, 4, 1e-6, 1e-6, calm);
            expectFormula(keyword, still, 4, 1e-6, 1e-6, clocks);
        }
    }
}

// With LOD_FADE_PERCENTAGE a vertex blends to its next-LOD position by the LOD value.
TEST_F(SpeedTreeValueTest, LodFadePercentage) {
    ShaderValues values;
    values.set("_StLod", 0.35f);
    for (const char* keyword : {"ST7_BRANCH", "ST8_TREE"}) {
        expectFormula(
            keyword,
            [](double u, double v) {
                Vec3 p = add(position(u, v), {0.1, 0.2, 0.3}, 0.35);
                return Vec4{p[0], p[1], p[2], 0.0};
            },
            4, 1e-5, 1e-5, values);
    }
}

TEST_F(SpeedTreeValueTest, WindMovesTrees) {
    ShaderValues values = windValues();
    values.set("_WindEnabled", 1.0f);
    values.set("_WindQuality", 5.0f);
    values.set("unity_ObjectToWorld", glm::mat4(1.0f));
    values.set("unity_WorldToObject", glm::mat4(1.0f));
    values.set("_ST_WindVector", glm::vec4(0.9f, 0.0f, 1.2f, 0.0f));
    values.set("_ST_WindBranch", glm::vec4(2.0f, 0.5f, 0.0f, 0.0f));
    values.set("_ST_WindBranchAnchor", glm::vec4(0.0f, 1.0f, 0.0f, 0.5f));
    values.set("_ST_WindLeaf1Ripple", glm::vec4(1.7f, 0.3f, 0.0f, 0.0f));
    values.set("_ST_WindLeaf2Ripple", glm::vec4(0.7f, 0.2f, 0.0f, 0.0f));
    for (const char* keyword : {"ST7_LEAF", "ST7_FROND", "ST7_BRANCH", "ST8_TREE"}) {
        image::Image image = run(keyword, values);
        ASSERT_EQ(image.width(), kSize) << keyword;
        int moved = 0;
        for (uint32_t y = 0; y < kSize; ++y) {
            for (uint32_t x = 0; x < kSize; ++x) {
                Vec3 p = position((x + 0.5) / kSize, (y + 0.5) / kSize);
                std::array<float, 4> got = image.pixelFloat(x, y);
                ASSERT_TRUE(std::isfinite(got[0]) && std::isfinite(got[1]) && std::isfinite(got[2]))
                    << keyword << " pixel " << x << ", " << y;
                moved += length(add({got[0], got[1], got[2]}, p, -1.0)) > 1e-3 ? 1 : 0;
            }
        }
        EXPECT_GE(moved, static_cast<int>(kSize * kSize * 3 / 4)) << keyword;
    }
}

// SpeedTree 7's surface path for a branch with hue variation (the test binds white textures):
// SpeedTreeVert passes the UV and _Color times the vertex's occlusion, and the hue amount
// saturate(frac(tree base . 1 + 0.1 (x + z)) * _HueVariation.a); SpeedTreeFrag shifts white
// towards _HueVariation.rgb at constant brightness; SPEEDTREE_COPY_FRAG copies albedo and alpha.
TEST_F(SpeedTreeValueTest, SurfacePath) {
    ShaderValues values;
    values.set("_Color", glm::vec4(0.8f, 0.6f, 0.4f, 0.9f));
    values.set("_HueVariation", glm::vec4(0.2f, 0.9f, 0.1f, 0.5f));
    values.set("unity_ObjectToWorld", glm::mat4(1.0f));
    expectFormula(
        "ST7_SURFACE",
        [](double u, double v) {
            Vec3 p = position(u, v), hue{0.2, 0.9, 0.1}, color{0.8 * u, 0.6 * u, 0.4 * u};
            double amount = clamp01(frac(0.1 * (p[0] + p[2])) * 0.5);
            Vec3 shifted = add({1.0, 1.0, 1.0}, add(hue, {1.0, 1.0, 1.0}, -1.0), amount);
            double brightest = std::max({shifted[0], shifted[1], shifted[2]});
            Vec4 out{0.0, 0.0, 0.0, 0.9 + u + v};
            for (size_t c = 0; c < 3; ++c) out[c] = clamp01(shifted[c] / brightest) * color[c];
            return out;
        },
        4, 1e-4, 1e-3, values);
}

// Billboards: a quad of width unity_BillboardSize.x times the width scale, from -bottom to
// height - bottom about the base, across the horizontal direction to the camera; normal towards
// the camera, tangent across; the atlas image of the nearest of unity_BillboardInfo.x angles.
class SpeedTreeBillboardTest : public SpeedTreeValueTest {
protected:
    static constexpr double kYaw = 0.9, kRotation = 0.7, kWidth = 3.0 * 1.5, kHeight = 6.0,
                            kBottom = 0.5;
    static Vec3 base(double u, double v) { return {10.0 * u - 5.0, 0.0, 10.0 * v - 5.0}; }
    static Vec3 toCamera(double u, double v, bool cameraPosition) {
        if (!cameraPosition) return {std::sin(kYaw), 0.0, std::cos(kYaw)};
        Vec3 b = base(u, v);
        return normalized({12.0 - b[0], 0.0, -9.0 - b[2]});
    }
    // The image index as a real number: the shader takes its floor.
    static double image(const Vec3& t) {
        return frac(std::atan2(t[0], t[2]) / kTwoPi - kRotation / kTwoPi + 1.0 / 16.0) * 8.0;
    }
    static Vec4 corner(double u, double v, bool cameraPosition) {
        Vec3 t = toCamera(u, v, cameraPosition), across{t[2], 0.0, -t[0]};
        double cx = frac(4.0 * u), cy = frac(4.0 * v);
        Vec3 p =
            add(add(base(u, v), across, (cx - 0.5) * kWidth), {0.0, cy * kHeight - kBottom, 0.0});
        return {p[0], p[1], p[2], std::floor(image(t)) / 8.0 + cx / 8.0};
    }
    static ShaderValues values() {
        ShaderValues values;
        values.set("unity_BillboardSize", glm::vec4(3.0f, 6.0f, 0.5f, 0.0f));
        values.set("unity_BillboardInfo", glm::vec4(8.0f, 0.0f, 0.0f, 0.0f));
        values.set("unity_BillboardCameraParams", glm::vec4(12.0f, 4.0f, -9.0f, float(kYaw)));
        std::array<glm::vec4, 16> images{};
        for (size_t i = 0; i < images.size(); ++i) {
            images[i] = glm::vec4(float(i) / 8.0f, 0.25f, 1.0f / 8.0f, 0.5f);
        }
        values.setArray("unity_BillboardImageTexCoords", images);
        values.set("_Color", glm::vec4(1.0f));
        return values;
    }
};

TEST_F(SpeedTreeBillboardTest, FacesTheCameraDirection) {
    expectFormula(
        "ST_BILLBOARD", [](double u, double v) { return corner(u, v, false); }, 4, 1e-4, 1e-4,
        values());
    expectFormula(
        "ST_BILLBOARD_FRAME",
        [](double, double v) {
            Vec3 t = toCamera(0.0, 0.0, false);
            return Vec4{t[0], t[2], -t[0], 0.25 + frac(4.0 * v) * 0.5};
        },
        4, 1e-5, 1e-4, values());
}

// Facing the camera position, each quad turns on its own; the image index may differ from the
// CPU's only where the angle is within 1e-3 of a step between two images.
TEST_F(SpeedTreeBillboardTest, FacesTheCameraPosition) {
    expectFormula(
        "ST_BILLBOARD_CAMPOS", [](double u, double v) { return corner(u, v, true); }, 3, 1e-4, 1e-4,
        values());
    image::Image result = run("ST_BILLBOARD_CAMPOS", values());
    ASSERT_EQ(result.width(), kSize);
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            double u = (x + 0.5) / kSize, v = (y + 0.5) / kSize;
            double index = image(toCamera(u, v, true));
            double got = (result.pixelFloat(x, y)[3] - frac(4.0 * u) / 8.0) * 8.0;
            bool nearStep = std::abs(index - std::round(index)) < 1e-3;
            double wanted = std::floor(index);
            EXPECT_TRUE(
                std::abs(got - wanted) < 1e-3 ||
                (nearStep && std::abs(got - std::fmod(std::round(index), 8.0)) < 1e-3) ||
                (nearStep && std::abs(got - std::fmod(std::floor(index - 0.5) + 8.0, 8.0)) < 1e-3))
                << "pixel " << x << ", " << y << ": image " << got << ", CPU " << index;
        }
    }
}

}  // namespace
}  // namespace varc::render::speedtree
