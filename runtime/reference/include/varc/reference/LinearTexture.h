// SPDX-License-Identifier: Apache-2.0
// LinearTexture: a PNG colour texture as the GPU samples it for the CPU reference: sRGB-encoded
// texels decoded to linear first (Vulkan decodes before filtering), then bilinear filtering with
// repeat addressing and texel centres at (i + 0.5) / size; one mip level.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

#include "varc/core/Result.h"
#include "varc/scene/Scene.h"

namespace varc::reference {

class LinearTexture {
public:
    // Reads the PNG at |path|. Errors: those of image::readPng (the message names the path).
    static Result<std::shared_ptr<const LinearTexture>> load(const std::string& path);

    // The filtered linear RGBA at |uv| (any value: repeat).
    glm::vec4 sample(glm::vec2 uv) const;

    uint32_t width() const { return mWidth; }
    uint32_t height() const { return mHeight; }

private:
    uint32_t mWidth = 0, mHeight = 0;
    std::vector<glm::vec4> mTexels;  // linear, row 0 first (v = 0 at the top row, as Vulkan)
};

// A colour texture property as the references read it: "white" or "black" set |constant| (and
// leave |texture| null), a PNG file (scene::isTextureFile) loads |texture|. InvalidInput for a
// non-texture value, Unsupported for another name, the load's error for an unreadable file; the
// messages start with "material property <name>: ".
Status readColorTexture(const scene::PropertyValue& value, const std::string& name,
                        glm::vec4& constant, std::shared_ptr<const LinearTexture>& texture);

}  // namespace varc::reference
