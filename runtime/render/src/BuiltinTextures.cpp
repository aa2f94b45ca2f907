// SPDX-License-Identifier: Apache-2.0
#include "varc/render/BuiltinTextures.h"

#include <vector>

#include "varc/core/AsciiCase.h"
#include "varc/scene/LightTextures.h"
#include "varc/vulkan/Sampler.h"

namespace varc::render {

namespace {

image::Image solid(uint8_t r, uint8_t g, uint8_t b, uint8_t a) {
    image::Image image(1, 1, image::PixelFormat::Rgba8);
    image.setPixel8(0, 0, {r, g, b, a});
    return image;
}

// The falloff table as a float image (sampled as R16G16B16A16_SFLOAT: within 1/2048 of the
// 16-bit table, far below an 8-bit LSB), every channel holding f.
image::Image falloffImage() {
    std::vector<uint16_t> table = scene::falloffTable();
    image::Image image(static_cast<uint32_t>(table.size()), 1, image::PixelFormat::RgbaFloat);
    for (uint32_t i = 0; i < table.size(); ++i) {
        float f = static_cast<float>(table[i]) / 65535.0f;
        image.setPixelFloat(i, 0, {f, f, f, f});
    }
    return image;
}

std::vector<image::Image> cookieLayers(const scene::CookieImage& cookie) {
    std::vector<image::Image> layers;
    size_t layerBytes = size_t{cookie.width} * cookie.height * 4;
    for (uint32_t layer = 0; layer < cookie.layers; ++layer) {
        image::Image image(cookie.width, cookie.height, image::PixelFormat::Rgba8);
        std::copy_n(cookie.rgba.begin() + static_cast<std::ptrdiff_t>(layer * layerBytes),
                    layerBytes, image.bytes().begin());
        layers.push_back(std::move(image));
    }
    return layers;
}

// The 16 slices of _DitherMaskLOD: texel (x, y) of slice k has alpha 1 when its rank in the 4 x 4
// Bayer matrix is below round(16 k / 15), else 0 (slice 0: nothing, slice 15: everything).
std::vector<image::Image> ditherSlices() {
    constexpr uint8_t kBayer[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};
    std::vector<image::Image> slices;
    for (uint32_t k = 0; k < 16; ++k) {
        const uint32_t covered = (16 * k + 7) / 15;
        image::Image image(4, 4, image::PixelFormat::Rgba8);
        for (uint32_t y = 0; y < 4; ++y) {
            for (uint32_t x = 0; x < 4; ++x) {
                const uint8_t a = kBayer[y][x] < covered ? 255 : 0;
                image.setPixel8(x, y, {255, 255, 255, a});
            }
        }
        slices.push_back(std::move(image));
    }
    return slices;
}

Result<vulkan::Texture> make2D(vulkan::VulkanContext& context, const image::Image& image,
                               const char* name) {
    vulkan::TextureOptions options;
    options.name = name;
    return vulkan::Texture::create2D(context, image, options);
}

}  // namespace

Result<BuiltinTextures> BuiltinTextures::create(vulkan::VulkanContext& context) {
    BuiltinTextures textures;
    struct Solid {
        std::optional<vulkan::Texture>* slot;
        image::Image image;
        const char* name;
    };
    Solid solids[] = {{&textures.mWhite, solid(255, 255, 255, 255), "white"},
                      {&textures.mBlack, solid(0, 0, 0, 0), "black"},
                      {&textures.mBump, solid(128, 128, 255, 255), "bump"},
                      {&textures.mGray, solid(128, 128, 128, 255), "gray"},
                      {&textures.mRed, solid(255, 0, 0, 255), "red"},
                      {&textures.mFalloff, falloffImage(), "falloff"},
                      {&textures.mSpot, cookieLayers(scene::defaultSpotCookie())[0], "spot cookie"},
                      {&textures.mDirectional, cookieLayers(scene::defaultDirectionalCookie())[0],
                       "directional cookie"}};
    for (Solid& entry : solids) {
        auto texture = make2D(context, entry.image, entry.name);
        if (!texture) return texture.error();
        entry.slot->emplace(std::move(*texture));
    }
    std::vector<image::Image> whiteFaces(6, solid(255, 255, 255, 255));
    auto whiteCube = vulkan::Texture::createCube(context, whiteFaces, {false, false, "white cube"});
    if (!whiteCube) return whiteCube.error();
    textures.mWhiteCube.emplace(std::move(*whiteCube));
    // A Cube property whose default is "" or "gray" (Unity's texture for an empty name).
    std::vector<image::Image> grayFaces(6, solid(128, 128, 128, 255));
    auto grayCube = vulkan::Texture::createCube(context, grayFaces, {false, false, "gray cube"});
    if (!grayCube) return grayCube.error();
    textures.mGrayCube.emplace(std::move(*grayCube));
    auto white3D = vulkan::Texture::createVolume(
        context, std::span<const image::Image>(whiteFaces.data(), 1), {false, false, "white 3D"});
    if (!white3D) return white3D.error();
    textures.mWhite3D.emplace(std::move(*white3D));
    auto point = vulkan::Texture::createCube(context, cookieLayers(scene::defaultPointCookie()),
                                             {false, false, "point cookie"});
    if (!point) return point.error();
    textures.mPoint.emplace(std::move(*point));
    const std::vector<image::Image> dither = ditherSlices();
    auto ditherMask = vulkan::Texture::createVolume(context, dither, {false, false, "dither mask"});
    if (!ditherMask) return ditherMask.error();
    textures.mDither.emplace(std::move(*ditherMask));

    vulkan::SamplerDesc repeat;
    repeat.name = "linear repeat";
    auto repeatSampler = createSampler(context, repeat);
    if (!repeatSampler) return repeatSampler.error();
    textures.mRepeat = std::move(*repeatSampler);
    vulkan::SamplerDesc clamp;
    clamp.addressMode = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    clamp.name = "linear clamp";
    auto clampSampler = createSampler(context, clamp);
    if (!clampSampler) return clampSampler.error();
    textures.mClamp = std::move(*clampSampler);
    vulkan::SamplerDesc nearest;
    nearest.filter = VK_FILTER_NEAREST;
    nearest.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    nearest.name = "nearest repeat";
    auto nearestSampler = createSampler(context, nearest);
    if (!nearestSampler) return nearestSampler.error();
    textures.mNearestRepeat = std::move(*nearestSampler);
    return textures;
}

std::optional<TextureBinding> BuiltinTextures::named(std::string_view givenName,
                                                     pack::ResourceDim dim) const {
    // Unity matches the default texture names without regard to case ("Gray" {} is gray).
    const std::string name = toAsciiLower(givenName);
    if (dim == pack::ResourceDim::Cube) {
        if (name == "white" || name.empty())
            return TextureBinding{mWhiteCube->view(), mRepeat.get()};
        if (name == "gray" || name == "grey")
            return TextureBinding{mGrayCube->view(), mRepeat.get()};
        return std::nullopt;
    }
    if (dim == pack::ResourceDim::Dim3D) {
        if (name == "white" || name.empty()) return TextureBinding{mWhite3D->view(), mRepeat.get()};
        return std::nullopt;
    }
    if (dim != pack::ResourceDim::Dim2D) return std::nullopt;
    if (name == "white" || name.empty()) return TextureBinding{mWhite->view(), mRepeat.get()};
    if (name == "black") return TextureBinding{mBlack->view(), mRepeat.get()};
    if (name == "bump") return TextureBinding{mBump->view(), mRepeat.get()};
    if (name == "gray" || name == "grey") return TextureBinding{mGray->view(), mRepeat.get()};
    if (name == "red") return TextureBinding{mRed->view(), mRepeat.get()};
    return std::nullopt;
}

TextureBinding BuiltinTextures::falloff() const { return {mFalloff->view(), mClamp.get()}; }
TextureBinding BuiltinTextures::ditherMask() const {
    return {mDither->view(), mNearestRepeat.get()};
}
TextureBinding BuiltinTextures::spotCookie() const { return {mSpot->view(), mClamp.get()}; }
TextureBinding BuiltinTextures::directionalCookie() const {
    return {mDirectional->view(), mRepeat.get()};
}
std::optional<TextureBinding> BuiltinTextures::lightTexture(std::string_view name,
                                                            pack::ResourceDim dim,
                                                            scene::LightType type, bool cookie,
                                                            bool deferred) const {
    if (name == "_LightTextureB0") return falloff();
    if (name != "_LightTexture0") return std::nullopt;
    switch (type) {
        case scene::LightType::Spot:
            return spotCookie();
        case scene::LightType::Point:
            if (cookie) return pointCookie();
            return deferred ? named("white", dim) : falloff();
        case scene::LightType::Directional:
            return cookie ? directionalCookie() : named("white", dim);
    }
    return std::nullopt;
}

TextureBinding BuiltinTextures::pointCookie() const { return {mPoint->view(), mClamp.get()}; }

}  // namespace varc::render
