// SPDX-License-Identifier: Apache-2.0
// A lavapipe fixture that draws one variant of the helpers pack over a full-target quad into a
// float target, for tests that compare every pixel with a CPU formula.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "FormulaComparison.h"
#include "VulkanTestSupport.h"
#include "varc/image/Image.h"
#include "varc/reader/Pack.h"
#include "varc/reader/PassView.h"
#include "varc/render/BuiltinTextures.h"
#include "varc/render/DrawResources.h"
#include "varc/render/SceneValues.h"
#include "varc/render/VertexLayout.h"
#include "varc/vulkan/Buffer.h"
#include "varc/vulkan/RenderTarget.h"

namespace varc::render::testing {

// A quad over the whole target whose uv runs 0..1 with the framebuffer's x and y.
std::vector<MeshVertex> fullTargetQuad();

// Opens helpers.svpack (built by the vulkan.build_packs test) and creates a square RGBA32F target
// of |size| pixels, the built-in textures, draw resources and the quad; any failure fails SetUp.
class QuadDrawTest : public VulkanTest {
protected:
    explicit QuadDrawTest(uint32_t size) : mSize(size) {}
    void SetUp() override;
    void TearDown() override;

    // Draws the variant of |pass| with exactly |keywords| (a missing variant fails the test)
    // with |values| and |textures|, and returns the float image (empty after a failure).
    image::Image drawQuad(const reader::PassView& pass, const std::vector<std::string>& keywords,
                          const ShaderValues& values, const TextureLookup& textures);

    // Draws pass 0 of |shader| with exactly |keyword| and expects the first |channels| channels
    // of every pixel to match |formula| (compareWithFormula: worst <= 1), whose largest expected
    // value must reach |minLargest| somewhere: a formula of nothing proves nothing.
    void expectPassFormula(const std::string& shader, const std::string& keyword,
                           const ShaderValues& values, const TextureLookup& textures,
                           const PixelFormula& formula, int channels, double absolute,
                           double relative, double minLargest = 0.1);
    // Binds the built-in white texture to every texture.
    TextureLookup whiteTextures() const;

    uint32_t mSize;
    std::optional<reader::Pack> mPack;
    std::optional<vulkan::RenderTarget> mTarget;
    std::optional<BuiltinTextures> mTextures;
    std::optional<DrawResources> mResources;
    std::optional<vulkan::Buffer> mQuad;
};

}  // namespace varc::render::testing
