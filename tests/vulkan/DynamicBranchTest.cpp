// SPDX-License-Identifier: Apache-2.0
// dynamic_branch keywords on lavapipe (tests/vulkan/helpers/DynamicBranch.shader): the keywords
// select no variant, the draw sets their uniforms, and every pixel of each keyword state matches
// the CPU value of the branches the state takes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "QuadDrawTest.h"
#include "varc/reader/Pack.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ShaderView.h"
#include "varc/render/ForwardRenderer.h"
#include "varc/render/SceneValues.h"
#include "varc/scene/Scene.h"

namespace varc::render {
namespace {

constexpr uint32_t kSize = 16;
constexpr const char* kShader = "varc-test/DynamicBranch";
const glm::vec4 kTint(0.2f, 0.4f, 0.6f, 1.0f);  // the shader's default, set again by the test
using Keywords = std::vector<std::string>;
using Pixel8 = std::array<uint8_t, 4>;

bool has(const Keywords& keywords, const char* name) {
    return std::find(keywords.begin(), keywords.end(), name) != keywords.end();
}

// The shader's shade() on the CPU for the keywords |on|: the branches of RED, GREEN and WAVE
// when on, never the `#ifdef RED` block, the HALF variant's scale.
std::array<double, 4> expected(double u, double v, const Keywords& on) {
    std::array<double, 4> c{kTint.r, kTint.g, u, v};
    if (has(on, "RED")) c[0] = 1.0 - 0.5 * kTint.r;
    if (has(on, "GREEN")) c[1] = kTint.g * kTint.g + 0.5;
    if (has(on, "WAVE")) c[2] = u * v;
    if (has(on, "HALF")) {
        for (size_t i = 0; i < 3; ++i) c[i] *= 0.5;
    }
    return c;
}

class DynamicBranchTest : public testing::QuadDrawTest {
protected:
    DynamicBranchTest() : QuadDrawTest(kSize) {}

    reader::PassView quadPass() const { return *mPack->findShader(kShader)->pass(size_t{0}); }

    // Draws the quad pass with |keywords| enabled, the dynamic ones through their uniforms, and
    // compares every pixel with expected(); reports the worst one.
    void expectState(const Keywords& keywords) {
        reader::PassView pass = quadPass();
        ShaderValues values;
        values.set("_Tint", kTint);
        setDynamicBranchValues(values, pass.dynamicKeywords(), keywords);
        const BuiltinTextures& builtin = *mTextures;
        image::Image image =
            drawQuad(pass, keywords, values, [&builtin](std::string_view, pack::ResourceDim dim) {
                return builtin.named("white", dim);
            });
        ASSERT_EQ(image.width(), kSize);
        double worst = 0;
        std::string where;
        for (uint32_t y = 0; y < kSize; ++y) {
            for (uint32_t x = 0; x < kSize; ++x) {
                std::array<double, 4> want =
                    expected((x + 0.5) / kSize, (y + 0.5) / kSize, keywords);
                std::array<float, 4> got = image.pixelFloat(x, y);
                for (size_t c = 0; c < 4; ++c) {
                    double error = std::abs(got[c] - want[c]);
                    if (error > worst) {
                        worst = error;
                        where = "pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                ") channel " + std::to_string(c) + ": GPU " +
                                std::to_string(got[c]) + ", CPU " + std::to_string(want[c]);
                    }
                }
            }
        }
        std::string state;
        for (const std::string& keyword : keywords) state += keyword + " ";
        EXPECT_LE(worst, 1e-5) << "keywords { " << state << "}: worst " << where;
    }
};

TEST_F(DynamicBranchTest, KeywordsAreRecordedApartAndSelectNoVariant) {
    reader::PassView pass = quadPass();
    EXPECT_EQ(pass.dynamicKeywords(), (Keywords{"GREEN", "RED", "WAVE"}));
    EXPECT_EQ(mPack->findShader(kShader)->dynamicKeywords(), (Keywords{"GREEN", "RED", "WAVE"}));
    ASSERT_EQ(pass.keywordCount(), 1u);  // HALF only
    EXPECT_EQ(pass.variantCount(), 2u);
    auto plain = pass.lookup(Keywords{}, variants::SelectionPolicy::Strict);
    auto red = pass.lookup(Keywords{"RED", "WAVE"}, variants::SelectionPolicy::Strict);
    auto half = pass.lookup(Keywords{"RED", "HALF"}, variants::SelectionPolicy::Strict);
    ASSERT_TRUE(plain && red && half);
    EXPECT_EQ(red->describe(), plain->describe());
    EXPECT_NE(half->describe(), plain->describe());
}

TEST_F(DynamicBranchTest, EachKeywordIsAnIntegerUniformOfTheProgram) {
    auto variant = quadPass().lookup(Keywords{}, variants::SelectionPolicy::Exact);
    ASSERT_TRUE(variant);
    pack::ProgramReflection reflection = variant->program(Stage::Fragment)->reflection();
    std::vector<std::string> found;
    for (const pack::UniformBlock& block : reflection.uniformBlocks) {
        for (const pack::BlockMember& member : block.members) {
            if (member.name == "RED" || member.name == "GREEN" || member.name == "WAVE") {
                EXPECT_EQ(member.type, "int") << member.name;
                found.push_back(member.name);
            }
        }
    }
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, (Keywords{"GREEN", "RED", "WAVE"}));
}

TEST_F(DynamicBranchTest, EveryPixelFollowsTheEnabledKeywords) {
    expectState({});
    expectState({"RED"});
    expectState({"GREEN"});
    expectState({"RED", "GREEN"});  // Unity runs every enabled keyword's branch
    expectState({"WAVE"});
    expectState({"HALF", "RED", "WAVE"});
}

// The scene renderer sets the uniforms from the material's keywords.
TEST_F(DynamicBranchTest, SceneMaterialKeywordsSetTheUniforms) {
    auto renderer = ForwardRenderer::create(context(), {&*mPack});
    ASSERT_TRUE(renderer) << renderer.error().detail;
    auto centre = [&renderer](const Keywords& keywords) {
        scene::Scene scene;
        scene.camera.width = scene.camera.height = 32;
        scene::Object sphere;
        sphere.material.shader = kShader;
        sphere.material.properties = {{"_Tint", kTint}};
        sphere.material.keywords = keywords;
        scene.objects.push_back(sphere);
        RenderedFrame frame = testing::frameOf(renderer->render(scene));
        EXPECT_EQ(frame.image.width(), 32u);
        return frame.image.width() == 32 ? frame.image.pixel8(16, 16) : Pixel8{};
    };
    const auto off = centre({});
    EXPECT_EQ(off[0], 51);   // _Tint.r
    EXPECT_EQ(off[1], 102);  // _Tint.g
    const auto on = centre({"RED", "GREEN"});
    EXPECT_EQ(on[0], 230);  // 1 - 0.5 * 0.2
    EXPECT_EQ(on[1], 168);  // 0.4^2 + 0.5
}

}  // namespace
}  // namespace varc::render
