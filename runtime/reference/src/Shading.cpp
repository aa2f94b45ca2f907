// SPDX-License-Identifier: Apache-2.0
// Shading: BRDF, vertex lights, light attenuation and texture sampling of docs/LIGHTING.md.
#include "varc/reference/Shading.h"

#include <algorithm>
#include <cmath>

#include "varc/image/Png.h"

namespace varc::reference {
namespace {

constexpr float kPi = 3.14159265359f;     // UNITY_PI
constexpr float kInvPi = 0.31830988618f;  // UNITY_INV_PI

float saturate(float x) { return std::clamp(x, 0.0f, 1.0f); }
float pow5(float x) { return x * x * x * x * x; }

// Bilinear sample of the alpha channel of layer |layer| at (s, t); |repeat| wraps, else clamps.
float sampleAlpha(const scene::CookieImage& image, uint32_t layer, glm::vec2 st, bool repeat) {
    const auto w = static_cast<int>(image.width), h = static_cast<int>(image.height);
    const float x = st.x * static_cast<float>(w) - 0.5f, y = st.y * static_cast<float>(h) - 0.5f;
    const float fx0 = std::floor(x), fy0 = std::floor(y);
    const float ax = x - fx0, ay = y - fy0;
    auto texel = [&](int tx, int ty) {
        if (repeat) {
            tx = ((tx % w) + w) % w;
            ty = ((ty % h) + h) % h;
        } else {
            tx = std::clamp(tx, 0, w - 1);
            ty = std::clamp(ty, 0, h - 1);
        }
        const size_t index =
            (size_t{layer} * image.height + static_cast<size_t>(ty)) * image.width +
            static_cast<size_t>(tx);
        return static_cast<float>(image.rgba[4 * index + 3]) / 255.0f;
    };
    const int x0 = static_cast<int>(fx0), y0 = static_cast<int>(fy0);
    const float top = texel(x0, y0) + (texel(x0 + 1, y0) - texel(x0, y0)) * ax;
    const float bottom = texel(x0, y0 + 1) + (texel(x0 + 1, y0 + 1) - texel(x0, y0 + 1)) * ax;
    return top + (bottom - top) * ay;
}

}  // namespace

SurfaceColors diffuseAndSpecularFromMetallic(const glm::vec3& albedo, float metallic) {
    // unity_ColorSpaceDielectricSpec = (0.04, 0.04, 0.04, 0.96) in linear space.
    SurfaceColors s;
    s.specular = glm::vec3(0.04f) + (albedo - glm::vec3(0.04f)) * metallic;
    s.oneMinusReflectivity = 0.96f - metallic * 0.96f;
    s.diffuse = albedo * s.oneMinusReflectivity;
    return s;
}

glm::vec3 brdfPbs(const SurfaceColors& surface, float smoothness, const glm::vec3& n,
                  const glm::vec3& v, const glm::vec3& l, const glm::vec3& lightColor,
                  const glm::vec3& indirectDiffuse, const glm::vec3& indirectSpecular) {
    const float perceptualRoughness = 1.0f - smoothness;
    const float roughness = std::max(perceptualRoughness * perceptualRoughness, 0.002f);
    const glm::vec3 lv = l + v;
    const glm::vec3 h = lv / std::sqrt(std::max(0.001f, glm::dot(lv, lv)));

    const float nv = saturate(std::abs(glm::dot(n, v)));
    const float nl = saturate(glm::dot(n, l));
    const float nh = saturate(glm::dot(n, h));
    const float lh = saturate(glm::dot(l, h));

    const float fd90 = 0.5f + 2.0f * lh * lh * perceptualRoughness;
    const float lightScatter = 1.0f + (fd90 - 1.0f) * pow5(1.0f - nl);
    const float viewScatter = 1.0f + (fd90 - 1.0f) * pow5(1.0f - nv);
    const float diffuseTerm = lightScatter * viewScatter * nl;

    const float a = roughness;
    const float lambdaV = nl * (nv * (1.0f - a) + a);
    const float lambdaL = nv * (nl * (1.0f - a) + a);
    const float visibility = 0.5f / (lambdaV + lambdaL + 1e-5f);
    const float a2 = roughness * roughness;
    const float d = (nh * a2 - nh) * nh + 1.0f;
    const float distribution = kInvPi * a2 / (d * d + 1e-7f);
    float specularTerm = std::max(0.0f, visibility * distribution * kPi * nl);
    if (surface.specular == glm::vec3(0.0f)) specularTerm = 0.0f;

    const float surfaceReduction = 1.0f / (roughness * roughness + 1.0f);
    const float grazing = saturate(smoothness + (1.0f - surface.oneMinusReflectivity));
    const glm::vec3 fresnel =
        surface.specular + (glm::vec3(1.0f) - surface.specular) * pow5(1.0f - lh);
    const glm::vec3 fresnelLerp =
        surface.specular + (glm::vec3(grazing) - surface.specular) * pow5(1.0f - nv);
    return surface.diffuse * (indirectDiffuse + lightColor * diffuseTerm) +
           specularTerm * lightColor * fresnel + surfaceReduction * indirectSpecular * fresnelLerp;
}

VertexLights vertexLightsFor(const scene::Scene& scene, const std::vector<int>& lights) {
    VertexLights out;
    for (size_t slot = 0; slot < lights.size() && slot < 4; ++slot) {
        const scene::Light& light = scene.lights[lights[slot]];
        const auto k = static_cast<int>(slot);
        out.posX[k] = light.transform.position.x;
        out.posY[k] = light.transform.position.y;
        out.posZ[k] = light.transform.position.z;
        out.attenSq[k] = 25.0f / (light.range * light.range);
        out.colors[slot] = light.finalColor();
    }
    return out;
}

glm::vec3 shade4PointLights(const VertexLights& lights, const glm::vec3& pos,
                            const glm::vec3& normal) {
    glm::vec3 result(0.0f);
    for (int j = 0; j < 4; ++j) {
        const glm::vec3 toLight = glm::vec3(lights.posX[j], lights.posY[j], lights.posZ[j]) - pos;
        const float lengthSq = std::max(glm::dot(toLight, toLight), 0.000001f);
        const float ndotl = std::max(0.0f, glm::dot(toLight, normal) / std::sqrt(lengthSq));
        const float atten = 1.0f / (1.0f + lengthSq * lights.attenSq[j]);
        result += lights.colors[static_cast<size_t>(j)] * (ndotl * atten);
    }
    return result;
}

LightTextureSet::LightTextureSet()
    : mFalloff(scene::falloffTable()),
      mSpot(scene::defaultSpotCookie()),
      mDirectional(scene::defaultDirectionalCookie()),
      mPoint(scene::defaultPointCookie()) {}

float LightTextureSet::falloff(float t) const {
    return mFalloffOverride ? mFalloffOverride(t) : scene::sampleFalloffTable(mFalloff, t);
}

float LightTextureSet::spotCookie(const glm::vec2& uv, const std::string& cookie) const {
    auto file = mFiles.find(cookie);
    return sampleAlpha(file != mFiles.end() ? file->second : mSpot, 0, uv, false);
}

float LightTextureSet::directionalCookie(const glm::vec2& uv, const std::string& cookie) const {
    auto file = mFiles.find(cookie);
    return sampleAlpha(file != mFiles.end() ? file->second : mDirectional, 0, uv, true);
}

Status LightTextureSet::loadCookieFiles(const std::vector<scene::Light>& lights) {
    for (const scene::Light& light : lights) {
        if (!scene::isTextureFile(light.cookie) || mFiles.count(light.cookie)) continue;
        auto image = image::readPng(light.cookie);
        if (!image) return makeError(image.error().code, "cookie: " + image.error().detail);
        scene::CookieImage cookie;
        cookie.width = image->width();
        cookie.height = image->height();
        for (uint32_t y = 0; y < cookie.height; ++y) {
            for (uint32_t x = 0; x < cookie.width; ++x) {
                const auto p = image->pixel8(x, y);
                cookie.rgba.insert(cookie.rgba.end(), p.begin(), p.end());
            }
        }
        mFiles.emplace(light.cookie, std::move(cookie));
    }
    return Ok{};
}

float LightTextureSet::pointCookie(const glm::vec3& direction) const {
    const scene::CubeCoord c = scene::cubeFaceCoord(direction);
    return sampleAlpha(mPoint, static_cast<uint32_t>(c.face), c.st, false);
}

Result<PassLight> passLightFor(const scene::Light& light) {
    if (light.cookie != "none" && light.cookie != "default" &&
        !scene::isTextureFile(light.cookie)) {
        return makeError(ErrorCode::Unsupported,
                         "the CPU reference knows the default cookies and PNG files, not '" +
                             light.cookie + "'");
    }
    PassLight p;
    p.cookie = light.cookie;
    const bool cookie = light.cookie != "none";
    switch (light.type) {
        case scene::LightType::Directional:
            p.keyword = cookie ? LightKeyword::DirectionalCookie : LightKeyword::Directional;
            p.worldSpaceLightPos = glm::vec4(-light.forward(), 0.0f);
            break;
        case scene::LightType::Point:
            p.keyword = cookie ? LightKeyword::PointCookie : LightKeyword::Point;
            p.worldSpaceLightPos = glm::vec4(light.transform.position, 1.0f);
            break;
        case scene::LightType::Spot:
            p.keyword = LightKeyword::Spot;
            p.worldSpaceLightPos = glm::vec4(light.transform.position, 1.0f);
            break;
    }
    p.color = light.finalColor();
    p.positionRange = glm::vec4(light.transform.position, 1.0f / light.range);
    p.worldToLight = scene::worldToLight(light, false);
    return p;
}

PassLight noPassLight() { return PassLight{}; }

float lightAttenuation(const PassLight& light, const LightTextureSet& textures,
                       const glm::vec3& p) {
    const glm::vec4 lc = light.worldToLight * glm::vec4(p, 1.0f);
    const glm::vec3 q(lc);
    switch (light.keyword) {
        case LightKeyword::Directional:
            return 1.0f;
        case LightKeyword::DirectionalCookie:
            return textures.directionalCookie(glm::vec2(lc), light.cookie);
        case LightKeyword::Point:
            return textures.falloff(glm::dot(q, q));
        case LightKeyword::PointCookie:
            return textures.falloff(glm::dot(q, q)) * textures.pointCookie(q);
        case LightKeyword::Spot:
            return (lc.z > 0.0f ? 1.0f : 0.0f) *
                   textures.spotCookie(glm::vec2(lc) / lc.w + glm::vec2(0.5f), light.cookie) *
                   textures.falloff(glm::dot(q, q));
    }
    return 1.0f;
}

}  // namespace varc::reference
