// SPDX-License-Identifier: Apache-2.0
// HLSL's cbuffer packing end to end (the relaxed block layout): a material block with a float3
// right after a float builds, draws with the validation layer on, and every member reaches the
// shader at the offset glslang gave it.
#include <gtest/gtest.h>

#include "VulkanTestSupport.h"
#include "varc/reader/Pack.h"
#include "varc/render/ForwardRenderer.h"
#include "varc/scene/Scene.h"

namespace varc::render {
namespace {

using RelaxedBlockLayoutTest = testing::VulkanTest;

TEST_F(RelaxedBlockLayoutTest, HlslPackedCbufferMembersReachTheShader) {
    auto pack = reader::Pack::open(VARC_TEST_PACK_DIR "/helpers.svpack");
    ASSERT_TRUE(pack) << pack.error().detail;
    auto renderer = ForwardRenderer::create(context(), {&*pack});
    ASSERT_TRUE(renderer) << renderer.error().detail;
    scene::Scene scene;
    scene.camera.width = scene.camera.height = 32;
    scene::Object sphere;
    sphere.material.shader = "varc-test/CbufferPacking";
    sphere.material.properties = {{"_A", 0.25f},
                                  {"_B", glm::vec4(0.5f, 0.75f, 1.0f, 0.0f)},
                                  {"_C", 0.5f}};
    scene.objects.push_back(sphere);
    RenderedFrame frame = testing::frameOf(renderer->render(scene));
    ASSERT_EQ(frame.image.width(), 32u);
    const auto centre = frame.image.pixel8(16, 16);
    EXPECT_EQ(centre[0], 128);  // _B.x
    EXPECT_EQ(centre[1], 191);  // _B.y
    EXPECT_EQ(centre[2], 255);  // _B.z
    EXPECT_EQ(centre[3], 191);  // _A + _C
}

}  // namespace
}  // namespace varc::render
