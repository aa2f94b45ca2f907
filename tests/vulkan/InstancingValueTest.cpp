// SPDX-License-Identifier: Apache-2.0
// Value tests of UnityInstancing.cginc's plumbing (issue #27, docs/SHADER_ABI.md §4.10): a quad
// drawn as instance 0 (tests/vulkan/helpers/InstancingValues.shader) reads the object matrix and
// an instanced property from the draw's block, from the per-instance arrays (INSTANCING_ON) and
// from the procedural function of `#pragma instancing_options procedural:setupInstance`
// (PROCEDURAL_INSTANCING_ON), which starts from the draw's matrix; each is compared with the
// values set here. scripts/builtin-api.py counts the names below as implemented.
//
// api-value-tested: UNITY_SETUP_INSTANCE_ID UnitySetupInstanceID UNITY_TRANSFER_INSTANCE_ID
// api-value-tested: UNITY_GET_INSTANCE_ID UNITY_DEFINE_INSTANCED_PROP UNITY_ACCESS_INSTANCED_PROP
// api-value-tested: UNITY_INSTANCING_BUFFER_START UnityObjectToClipPosInstanced
// api-value-tested: UnityObjectToClipPos
#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "FormulaComparison.h"
#include "QuadDrawTest.h"

namespace varc::render {
namespace {

constexpr uint32_t kSize = 16;
using Vec4 = std::array<double, 4>;

// A matrix that scales, shears and translates (columns), and the fragment's object point.
glm::mat4 drawMatrix() {
    glm::mat4 m(1.0f);
    m[0] = {2.0f, 0.0f, 0.5f, 0.0f};
    m[1] = {0.0f, 1.5f, 0.0f, 0.0f};
    m[2] = {0.25f, 0.0f, 1.0f, 0.0f};
    m[3] = {-1.0f, 0.5f, 2.0f, 1.0f};
    return m;
}
glm::dvec4 objectPoint(double u, double v) { return {u, v, 0.25, 1.0}; }

class InstancingValueTest : public testing::QuadDrawTest {
protected:
    InstancingValueTest() : QuadDrawTest(kSize) {}

    void expect(const std::vector<std::string>& keywords, const ShaderValues& values,
                const testing::PixelFormula& formula) {
        reader::PassView pass = *mPack->findShader("Test/InstancingValues")->pass(0);
        const BuiltinTextures& builtin = *mTextures;
        TextureLookup textures = [&builtin](std::string_view, pack::ResourceDim dim) {
            return builtin.named("white", dim);
        };
        image::Image image = drawQuad(pass, keywords, values, textures);
        ASSERT_EQ(image.width(), kSize);
        testing::FormulaComparison result =
            testing::compareWithFormula(image, formula, 4, 1e-5, 1e-5);
        EXPECT_LE(result.worst, 1.0) << keywords.size() << " keywords: worst " << result.where;
        EXPECT_GT(result.largest, 1.0);
    }
};

// Not instanced: the draw's unity_ObjectToWorld and the block member _Tint.
TEST_F(InstancingValueTest, PlainDrawReadsTheDrawsValues) {
    ShaderValues values;
    values.set("unity_ObjectToWorld", drawMatrix());
    values.set("_Tint", glm::vec4(3.0f, 0.0f, 0.0f, 0.0f));
    expect({}, values, [](double u, double v) {
        glm::dvec4 w = glm::dmat4(drawMatrix()) * objectPoint(u, v);
        return Vec4{w.x, w.y, w.z, 3.0 * u};
    });
    glm::mat4 vp(1.0f);
    vp[1][1] = -0.5f;
    vp[3] = {0.0f, 0.125f, 0.0f, 1.0f};
    values.set("unity_MatrixVP", vp);
    expect({"IV_CLIP"}, values, [vp](double u, double v) {
        glm::dvec4 c = glm::dmat4(vp) * glm::dmat4(drawMatrix()) * objectPoint(u, v);
        return Vec4{c.x, c.y, c.z, c.w};
    });
}

// Instanced: element 0 of the per-instance arrays, not the draw's values.
TEST_F(InstancingValueTest, InstancedDrawReadsElementZero) {
    glm::mat4 instance = drawMatrix();
    instance[3] = {4.0f, -2.0f, 1.0f, 1.0f};
    std::vector<glm::mat4> matrices = {instance};
    std::vector<glm::mat4> inverses = {glm::inverse(instance)};
    std::vector<glm::vec4> tints = {glm::vec4(5.0f, 0.0f, 0.0f, 0.0f)};
    ShaderValues values;
    values.set("unity_ObjectToWorld", glm::mat4(1.0f));
    values.set("_Tint", glm::vec4(-9.0f));
    values.setArray("unity_ObjectToWorldArray", matrices);
    values.setArray("unity_WorldToObjectArray", inverses);
    values.setArray("_TintArray", tints);
    expect({"INSTANCING_ON"}, values, [instance](double u, double v) {
        glm::dvec4 w = glm::dmat4(instance) * objectPoint(u, v);
        return Vec4{w.x, w.y, w.z, 5.0 * u};
    });
    // UnityObjectToClipPos uses the instance's matrix: VP * M * p.
    glm::mat4 vp(1.0f);
    vp[0][0] = 0.5f;
    vp[3] = {0.25f, 0.0f, 0.0f, 1.0f};
    values.set("unity_MatrixVP", vp);
    expect({"INSTANCING_ON", "IV_CLIP"}, values, [instance, vp](double u, double v) {
        glm::dvec4 c = glm::dmat4(vp) * glm::dmat4(instance) * objectPoint(u, v);
        return Vec4{c.x, c.y, c.z, c.w};
    });
}

// Procedural: the function ran (matrix moved by 1.5 along x from the draw's, y scaled by 3; tint
// 7 + instance 0) in the fragment stage through UNITY_SETUP_INSTANCE_ID.
TEST_F(InstancingValueTest, ProceduralFunctionSetsTheInstance) {
    ShaderValues values;
    values.set("unity_ObjectToWorld", drawMatrix());
    values.set("_Tint", glm::vec4(-9.0f));
    expect({"PROCEDURAL_INSTANCING_ON"}, values, [](double u, double v) {
        glm::dmat4 m = glm::dmat4(drawMatrix());
        m[3][0] += 1.5;  // HLSL [0][3]: row 0, column 3
        m[1][1] *= 3.0;
        glm::dvec4 w = m * objectPoint(u, v);
        return Vec4{w.x, w.y, w.z, 7.0 * u};
    });
}

}  // namespace
}  // namespace varc::render
