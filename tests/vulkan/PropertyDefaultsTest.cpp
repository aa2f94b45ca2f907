// SPDX-License-Identifier: Apache-2.0
// The pack stores each shader's Properties defaults and the renderers start every material from
// them: a material that leaves a property out renders exactly like one that spells the default
// out (and unlike one that sets it to 0, so the comparison can fail).
#include <gtest/gtest.h>

#include "VulkanTestSupport.h"
#include "varc/reader/Pack.h"
#include "varc/render/DeferredRenderer.h"
#include "varc/render/ForwardRenderer.h"
#include "varc/scene/Scene.h"

namespace varc::render {
namespace {

// The numeric properties (floats, vectors, colours) of every object's shader, set by |value|:
// the default itself, nothing (erased) or zero.
enum class Fill { Default, Omit, Zero };

scene::Scene withNumericProperties(scene::Scene scene, const reader::Pack& pack, Fill fill,
                                   int& touched) {
    touched = 0;
    for (scene::Object& object : scene.objects) {
        std::optional<reader::ShaderView> shader = pack.findShader(object.material.shader);
        if (!shader) continue;
        for (const pack::ShaderProperty& property : shader->properties()) {
            if (property.kind == pack::PropertyKind::Texture) continue;
            ++touched;
            auto& properties = object.material.properties;
            const std::array<float, 4>& v = property.value;
            switch (fill) {
                case Fill::Omit:
                    properties.erase(property.name);
                    break;
                case Fill::Zero:
                    if (property.kind == pack::PropertyKind::Float) {
                        properties[property.name] = 0.0f;
                    } else {
                        properties[property.name] = glm::vec4(0.0f);
                    }
                    break;
                case Fill::Default:
                    if (property.kind == pack::PropertyKind::Float) {
                        properties[property.name] = v[0];
                    } else {
                        properties[property.name] = glm::vec4(v[0], v[1], v[2], v[3]);
                    }
                    break;
            }
        }
    }
    return scene;
}

template <typename Renderer>
class DefaultsTest : public testing::RendererTest<Renderer> {
public:
    RenderedFrame renderFrame(const scene::Scene& scene) { return this->render(scene); }
};

template <typename Renderer>
void expectOmittedPropertiesTakeDefaults(DefaultsTest<Renderer>& test, const std::string& sceneFile,
                                         const reader::Pack& pack) {
    auto scene = scene::loadScene(sceneFile);
    ASSERT_TRUE(scene.ok()) << scene.error().detail;
    int touched = 0;
    scene::Scene spelled = withNumericProperties(*scene, pack, Fill::Default, touched);
    ASSERT_GT(touched, 0) << sceneFile << ": no shader with numeric properties";
    scene::Scene omitted = withNumericProperties(*scene, pack, Fill::Omit, touched);
    scene::Scene zeroed = withNumericProperties(*scene, pack, Fill::Zero, touched);
    image::Image spelledImage = test.renderFrame(spelled).image;
    image::Image omittedImage = test.renderFrame(omitted).image;
    image::Image zeroedImage = test.renderFrame(zeroed).image;
    EXPECT_EQ(testing::maxRgbDifference(spelledImage, omittedImage), 0.0f) << sceneFile;
    EXPECT_GT(testing::maxRgbDifference(spelledImage, zeroedImage), 0.05f) << sceneFile;
}

using ForwardDefaultsTest = DefaultsTest<ForwardRenderer>;
using DeferredDefaultsTest = DefaultsTest<DeferredRenderer>;

TEST_F(ForwardDefaultsTest, OmittedPropertiesTakeTheShaderDefaultsFromThePack) {
    expectOmittedPropertiesTakeDefaults<ForwardRenderer>(
        *this, std::string(VARC_TEST_SCENE_DIR) + "/forward/point.json", *mPack);
}

TEST_F(DeferredDefaultsTest, OmittedPropertiesTakeTheShaderDefaultsFromThePack) {
    expectOmittedPropertiesTakeDefaults<DeferredRenderer>(
        *this, std::string(VARC_TEST_SCENE_DIR) + "/deferred/point-hdr.json", *mPack);
}

}  // namespace
}  // namespace varc::render
