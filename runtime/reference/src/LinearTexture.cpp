// SPDX-License-Identifier: Apache-2.0
#include "varc/reference/LinearTexture.h"

#include <cmath>

#include "varc/image/Png.h"

namespace varc::reference {

namespace {

float srgbToLinear(uint8_t byte) {
    const float c = static_cast<float>(byte) / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

int wrap(int i, int size) { return ((i % size) + size) % size; }

}  // namespace

Result<std::shared_ptr<const LinearTexture>> LinearTexture::load(const std::string& path) {
    auto image = image::readPng(path);
    if (!image) return image.error();
    auto texture = std::make_shared<LinearTexture>();
    texture->mWidth = image->width();
    texture->mHeight = image->height();
    texture->mTexels.reserve(size_t{texture->mWidth} * texture->mHeight);
    for (uint32_t y = 0; y < texture->mHeight; ++y) {
        for (uint32_t x = 0; x < texture->mWidth; ++x) {
            const auto p = image->pixel8(x, y);
            texture->mTexels.emplace_back(srgbToLinear(p[0]), srgbToLinear(p[1]),
                                          srgbToLinear(p[2]), static_cast<float>(p[3]) / 255.0f);
        }
    }
    return std::shared_ptr<const LinearTexture>(std::move(texture));
}

glm::vec4 LinearTexture::sample(glm::vec2 uv) const {
    const int w = static_cast<int>(mWidth), h = static_cast<int>(mHeight);
    const float x = uv.x * static_cast<float>(w) - 0.5f;
    const float y = uv.y * static_cast<float>(h) - 0.5f;
    const float x0 = std::floor(x), y0 = std::floor(y);
    const float fx = x - x0, fy = y - y0;
    const int i0 = wrap(static_cast<int>(x0), w), i1 = wrap(static_cast<int>(x0) + 1, w);
    const int j0 = wrap(static_cast<int>(y0), h), j1 = wrap(static_cast<int>(y0) + 1, h);
    auto at = [&](int i, int j) { return mTexels[static_cast<size_t>(j) * mWidth + i]; };
    const glm::vec4 top = at(i0, j0) * (1.0f - fx) + at(i1, j0) * fx;
    const glm::vec4 bottom = at(i0, j1) * (1.0f - fx) + at(i1, j1) * fx;
    return top * (1.0f - fy) + bottom * fy;
}

Status readColorTexture(const scene::PropertyValue& value, const std::string& name,
                        glm::vec4& constant, std::shared_ptr<const LinearTexture>& texture) {
    const auto* text = std::get_if<std::string>(&value);
    const std::string prefix = "material property " + name + ": ";
    if (text == nullptr)
        return makeError(ErrorCode::InvalidInput, prefix + "expected a texture name");
    if (*text == "white") {
        constant = glm::vec4(1.0f);
    } else if (*text == "black") {
        constant = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    } else if (scene::isTextureFile(*text)) {
        auto loaded = LinearTexture::load(*text);
        if (!loaded) return makeError(loaded.error().code, prefix + loaded.error().detail);
        texture = std::move(*loaded);
    } else {
        return makeError(ErrorCode::Unsupported,
                         prefix +
                             "the CPU reference knows the textures 'white', 'black' and PNG "
                             "files, not '" +
                             *text + "'");
    }
    return Ok{};
}

}  // namespace varc::reference
