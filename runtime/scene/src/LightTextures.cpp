// SPDX-License-Identifier: Apache-2.0
// LightTextures: falloff table, default cookies and unity_WorldToLight (SHADER_ABI.md §5, §6).
#include "varc/scene/LightTextures.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_access.hpp>

namespace varc::scene {
namespace {

uint8_t toUnorm8(float v) {
    return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

// A width x height x layers RGBA8 image with rgb = 255 and alpha = |alpha(layer, s, t)| at
// texel centres s = (x + 0.5)/width, t = (y + 0.5)/height.
template <typename F>
CookieImage alphaCookie(uint32_t width, uint32_t height, uint32_t layers, F alpha) {
    CookieImage image;
    image.width = width;
    image.height = height;
    image.layers = layers;
    image.rgba.reserve(size_t{4} * width * height * layers);
    for (uint32_t layer = 0; layer < layers; ++layer) {
        for (uint32_t y = 0; y < height; ++y) {
            for (uint32_t x = 0; x < width; ++x) {
                const glm::vec2 st((static_cast<float>(x) + 0.5f) / static_cast<float>(width),
                                   (static_cast<float>(y) + 0.5f) / static_cast<float>(height));
                image.rgba.insert(image.rgba.end(), {255, 255, 255, toUnorm8(alpha(layer, st))});
            }
        }
    }
    return image;
}

}  // namespace

float falloff(float t) {
    return 1.0f / (1.0f + 25.0f * t) * std::clamp((1.0f - t) / 0.36f, 0.0f, 1.0f);
}

std::vector<uint16_t> falloffTable() {
    std::vector<uint16_t> table(kFalloffTableSize);
    for (uint32_t i = 0; i < kFalloffTableSize; ++i) {
        const float t = (static_cast<float>(i) + 0.5f) / static_cast<float>(kFalloffTableSize);
        table[i] = static_cast<uint16_t>(std::lround(falloff(t) * 65535.0f));
    }
    return table;
}

float sampleFalloffTable(const std::vector<uint16_t>& table, float t) {
    const auto size = static_cast<int>(table.size());
    const float x = t * static_cast<float>(size) - 0.5f;
    const float x0 = std::floor(x);
    const float frac = x - x0;
    const int i0 = std::clamp(static_cast<int>(x0), 0, size - 1);
    const int i1 = std::clamp(static_cast<int>(x0) + 1, 0, size - 1);
    const float a = static_cast<float>(table[i0]) / 65535.0f;
    const float b = static_cast<float>(table[i1]) / 65535.0f;
    return a + (b - a) * frac;
}

// Soft disc: alpha = saturate(5 (1 - 2 |uv - 0.5|)), 1 inside radius 0.4, 0 outside 0.5, and 0
// in the outermost texel ring: with clamp-to-edge addressing the cookie must be 0 outside the cone
// (the formula alone leaves 10/255 at the middle of each border).
CookieImage defaultSpotCookie() {
    constexpr float kSize = 128.0f;
    return alphaCookie(128, 128, 1, [](uint32_t, glm::vec2 st) {
        const float border = 1.0f / kSize;
        if (st.x < border || st.y < border || st.x > 1.0f - border || st.y > 1.0f - border) return 0.0f;
        return 5.0f * (1.0f - 2.0f * glm::length(st - glm::vec2(0.5f)));
    });
}

// Tiling soft grid: alpha = 0.6 + 0.4 cos(2 pi u) cos(2 pi v), periodic in u and v.
CookieImage defaultDirectionalCookie() {
    return alphaCookie(64, 64, 1, [](uint32_t, glm::vec2 st) {
        const float twoPi = 2.0f * glm::pi<float>();
        return 0.6f + 0.4f * std::cos(twoPi * st.x) * std::cos(twoPi * st.y);
    });
}

// Smooth in the direction d (unit, light space): alpha = 0.5 + 0.5 (d.x² - d.y²): 1 along ±x,
// 0 along ±y, 0.5 along ±z. Continuous across faces, so cube-edge filtering differences between
// implementations stay far below 1/255.
CookieImage defaultPointCookie() {
    return alphaCookie(32, 32, 6, [](uint32_t face, glm::vec2 st) {
        const glm::vec3 d = glm::normalize(cubeFaceDirection(static_cast<int>(face), st));
        return 0.5f + 0.5f * (d.x * d.x - d.y * d.y);
    });
}

CubeCoord cubeFaceCoord(const glm::vec3& d) {
    const glm::vec3 a = glm::abs(d);
    CubeCoord c;
    float sc = 0.0f, tc = 0.0f, ma = 1.0f;
    if (a.x >= a.y && a.x >= a.z) {
        c.face = d.x >= 0.0f ? 0 : 1;
        sc = d.x >= 0.0f ? -d.z : d.z;
        tc = -d.y;
        ma = a.x;
    } else if (a.y >= a.z) {
        c.face = d.y >= 0.0f ? 2 : 3;
        sc = d.x;
        tc = d.y >= 0.0f ? d.z : -d.z;
        ma = a.y;
    } else {
        c.face = d.z >= 0.0f ? 4 : 5;
        sc = d.z >= 0.0f ? d.x : -d.x;
        tc = -d.y;
        ma = a.z;
    }
    c.st = glm::vec2(0.5f * (sc / ma + 1.0f), 0.5f * (tc / ma + 1.0f));
    return c;
}

glm::vec3 cubeFaceDirection(int face, const glm::vec2& st) {
    const float sc = 2.0f * st.x - 1.0f, tc = 2.0f * st.y - 1.0f;
    switch (face) {
        case 0: return {1.0f, -tc, -sc};
        case 1: return {-1.0f, -tc, sc};
        case 2: return {sc, 1.0f, tc};
        case 3: return {sc, -1.0f, -tc};
        case 4: return {sc, -tc, 1.0f};
        default: return {-sc, -tc, -1.0f};
    }
}

glm::mat4 worldToLight(const Light& light, bool deferredSpotConvention) {
    const glm::mat4 l = glm::inverse(light.transform.rigidToWorld());
    const glm::vec4 lx = glm::row(l, 0), ly = glm::row(l, 1), lz = glm::row(l, 2);
    const glm::vec4 w(0.0f, 0.0f, 0.0f, 1.0f);
    const float r = light.range;
    glm::mat4 m(1.0f);
    switch (light.type) {
        case LightType::Point:
            m = glm::row(m, 0, lx / r);
            m = glm::row(m, 1, ly / r);
            m = glm::row(m, 2, lz / r);
            m = glm::row(m, 3, w);
            break;
        case LightType::Spot: {
            const float t = std::tan(glm::radians(light.spotAngle) * 0.5f);
            if (deferredSpotConvention) {
                m = glm::row(m, 0, -lx - t * lz);
                m = glm::row(m, 1, -ly - t * lz);
                m = glm::row(m, 2, -lz);
                m = glm::row(m, 3, -2.0f * t * lz);
            } else {
                m = glm::row(m, 0, lx / r);
                m = glm::row(m, 1, ly / r);
                m = glm::row(m, 2, lz / r);
                m = glm::row(m, 3, 2.0f * t * lz / r);
            }
            break;
        }
        case LightType::Directional:
            if (light.hasCookie()) {
                const float s = light.cookieSize;
                const glm::vec4 half(0.0f, 0.0f, 0.0f, 0.5f);
                m = glm::row(m, 0, lx / s + half);
                m = glm::row(m, 1, ly / s + half);
                m = glm::row(m, 2, lz);
                m = glm::row(m, 3, w);
            }
            break;
    }
    return m;
}

}  // namespace varc::scene
