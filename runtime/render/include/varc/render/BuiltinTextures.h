// SPDX-License-Identifier: Apache-2.0
// The textures the runtime provides by name (SHADER_ABI.md §6): white/black/bump defaults, the
// light falloff table, and the default spot, directional and point (cube) cookies.
#pragma once

#include <optional>
#include <string_view>

#include "varc/render/DrawResources.h"
#include "varc/scene/Scene.h"
#include "varc/vulkan/Texture.h"

namespace varc::render {

class BuiltinTextures {
public:
    static Result<BuiltinTextures> create(vulkan::VulkanContext& context);

    // "white", "black", "bump", "gray" ("grey"), "red" (2D; Unity's default texture names, in any
    // ASCII case: "Gray" is gray), "white" and "gray" (cube: a Cube property whose default is "")
    // and "white" (3D), linear-repeat sampled.
    std::optional<TextureBinding> named(std::string_view name, pack::ResourceDim dim) const;
    VkSampler repeatSampler() const { return mRepeat.get(); }  // linear, repeat
    VkSampler clampSampler() const { return mClamp.get(); }    // linear, clamp to edge
    TextureBinding falloff() const;                            // 1024 x 1, linear, clamp
    TextureBinding spotCookie() const;                         // linear, clamp
    TextureBinding directionalCookie() const;                  // linear, repeat
    TextureBinding pointCookie() const;                        // cube, linear, clamp
    // `_DitherMaskLOD` (SHADER_ABI.md §6): 4 x 4 x 16, slice k covers round(16 k / 15) texels of
    // the 4 x 4 tile in the order of the 4 x 4 Bayer matrix; nearest, repeat.
    TextureBinding ditherMask() const;

    // `_LightTexture0` / `_LightTextureB0` for a light (SHADER_ABI.md §6); nullopt for any other
    // name. Forward POINT reads its falloff from _LightTexture0; the deferred light pass reads
    // falloff from _LightTextureB0 and _LightTexture0 only for cookies (white otherwise).
    std::optional<TextureBinding> lightTexture(std::string_view name, pack::ResourceDim dim,
                                               scene::LightType type, bool cookie,
                                               bool deferred) const;

private:
    std::optional<vulkan::Texture> mWhite, mBlack, mBump, mGray, mRed, mWhiteCube, mGrayCube,
        mWhite3D, mFalloff, mSpot, mDirectional, mPoint, mDither;
    vulkan::UniqueHandle<VkSampler> mRepeat, mClamp, mNearestRepeat;
};

}  // namespace varc::render
