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

namespace varc::reference {

class LinearTexture {
public:
    // Reads the PNG at |path|. Errors: those of runtime::readPng (the message names the path).
    static Result<std::shared_ptr<const LinearTexture>> load(const std::string& path);

    // The filtered linear RGBA at |uv| (any value: repeat).
    glm::vec4 sample(glm::vec2 uv) const;

    uint32_t width() const { return mWidth; }
    uint32_t height() const { return mHeight; }

private:
    uint32_t mWidth = 0, mHeight = 0;
    std::vector<glm::vec4> mTexels;  // linear, row 0 first (v = 0 at the top row, as Vulkan)
};

}  // namespace varc::reference
