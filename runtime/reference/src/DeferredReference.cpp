// SPDX-License-Identifier: Apache-2.0
// DeferredReference: the G-buffer at each visible pixel, then the deferred light pass per light.
#include "varc/reference/DeferredReference.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "varc/reference/Shading.h"
#include "varc/reference/ShadowReference.h"
#include "varc/scene/CameraMatrices.h"
#include "varc/scene/ForwardLights.h"
#include "varc/scene/LightTextures.h"
#include "varc/scene/Mesh.h"

namespace varc::reference {
namespace {

float toHalf(float v) { return image::halfToFloat(image::floatToHalf(v)); }
float unorm8(float v) { return std::round(std::clamp(v, 0.0f, 1.0f) * 255.0f); }

Status readProperty(const scene::PropertyValue& value, const std::string& name, glm::vec4& out) {
    if (const auto* v = std::get_if<glm::vec4>(&value)) {
        out = *v;
        return Ok{};
    }
    return makeError(ErrorCode::InvalidInput, "material property " + name + ": expected a colour");
}

Status readProperty(const scene::PropertyValue& value, const std::string& name, float& out) {
    if (const auto* v = std::get_if<float>(&value)) {
        out = *v;
        return Ok{};
    }
    return makeError(ErrorCode::InvalidInput, "material property " + name + ": expected a number");
}

// Per object: material and the per-vertex world position and normal the G-buffer pass interpolates.
struct ObjectSurface {
    GBufferMaterial material;
    std::vector<glm::vec3> worldPos, worldNormal;
    const scene::Mesh* mesh = nullptr;  // its uvs are the G-buffer pass's uv0
    std::array<glm::vec4, 7> sh{};
};

Result<ObjectSurface> prepareObject(const scene::Scene& scene, const scene::Object& object) {
    ObjectSurface surface;
    auto material = resolveGBufferMaterial(object.material);
    if (!material) return material.error();
    surface.material = *material;
    surface.sh = scene::packedSH(scene, object, {});  // the flat ambient
    surface.mesh = &scene::builtinMesh(object.mesh);
    const glm::mat4 objectToWorld = object.transform.localToWorld();
    const glm::mat3 normalMatrix = glm::transpose(glm::mat3(glm::inverse(objectToWorld)));
    for (size_t i = 0; i < surface.mesh->positions.size(); ++i) {
        surface.worldPos.emplace_back(objectToWorld * glm::vec4(surface.mesh->positions[i], 1.0f));
        surface.worldNormal.push_back(glm::normalize(normalMatrix * surface.mesh->normals[i]));
    }
    return surface;
}

// LIGHTING.md §8.3, G-buffer pass, with the attachments' quantisation.
GBufferTexel gbufferTexel(const ObjectSurface& surface, const glm::vec3& interpolatedNormal,
                          const glm::vec2& uv, bool hdr) {
    const GBufferMaterial& m = surface.material;
    const glm::vec3 n = glm::normalize(interpolatedNormal);
    const glm::vec4 mainTex = m.mainTexture
                                  ? m.mainTexture->sample(uv * glm::vec2(m.mainTexST) +
                                                          glm::vec2(m.mainTexST.z, m.mainTexST.w))
                                  : m.mainTex;
    const SurfaceColors colors =
        diffuseAndSpecularFromMetallic(glm::vec3(mainTex) * glm::vec3(m.color), m.metallic);
    GBufferTexel texel;
    for (int c = 0; c < 3; ++c) {
        texel.diffuse[c] = srgb8RoundTrip(colors.diffuse[c]);
        texel.specular[c] = srgb8RoundTrip(colors.specular[c]);
    }
    texel.smoothness = unorm8(m.smoothness) / 255.0f;
    texel.encodedNormal = n * 0.5f + 0.5f;  // RT2 is R32G32B32A32_SFLOAT
    const glm::vec3 light =
        m.emission + colors.diffuse * glm::max(scene::shadeSH9(surface.sh, n), glm::vec3(0.0f));
    for (int c = 0; c < 3; ++c)
        texel.light[c] = hdr ? toHalf(light[c]) : unorm8(std::exp2(-light[c]));
    return texel;
}

// A scene's CPU shadow maps by light index (null for lights without one), with each light's fade.
struct DeferredShadows {
    std::vector<std::unique_ptr<ShadowMapReference>> maps;
    std::vector<std::vector<ShadowInterval>> masks;  // directional lights' screen masks
    std::vector<ShadowFade> fades;
};

// The light pass's shadow term (UnityDeferredComputeShadow: always faded); |upper| picks the
// upper bound of taps that straddle a comparison; exactly 1 without a map.
float deferredShadow(const DeferredShadows& shadows, size_t index, const scene::Light& light,
                     const glm::vec3& p, size_t pixel, bool upper) {
    if (!shadows.maps[index]) return 1.0f;
    const ShadowInterval realtime =
        !shadows.masks[index].empty()
            ? shadows.masks[index][pixel]
            : shadows.maps[index]->at(p, light.shadows == scene::ShadowType::Soft);
    const ShadowInterval faded = shadows.fades[index].apply(realtime, p);
    return upper ? faded.high : faded.low;
}

// LIGHTING.md §3, deferred table, and §8.3's light pass; |shadow| is the light's shadow term.
glm::vec3 lightPass(const scene::Light& light, const LightTextureSet& textures,
                    const GBufferTexel& texel, const glm::vec3& p, const glm::vec3& cameraPos,
                    float shadow) {
    const glm::vec4 lc =
        scene::worldToLight(light, /*deferredSpotConvention=*/true) * glm::vec4(p, 1.0f);
    const float invRangeSq = 1.0f / (light.range * light.range);
    glm::vec3 l(0.0f);
    float atten = 0.0f;
    if (light.type == scene::LightType::Directional) {
        l = -light.forward();
        atten =
            light.cookie != "none" ? textures.directionalCookie(glm::vec2(lc), light.cookie) : 1.0f;
    } else {
        const glm::vec3 toLight = light.transform.position - p;
        l = glm::normalize(toLight);
        // A light volume shades nothing beyond the range (the falloff itself reaches 0 there).
        const float t = glm::dot(toLight, toLight) * invRangeSq;
        atten = t <= 1.0f ? textures.falloff(t) : 0.0f;
        if (light.type == scene::LightType::Spot) {
            atten *= textures.spotCookie(glm::vec2(lc) / lc.w, light.cookie) *
                     (lc.w < 0.0f ? 1.0f : 0.0f);
        } else if (light.cookie != "none") {
            atten *= textures.pointCookie(glm::vec3(lc));
        }
    }
    SurfaceColors surface;
    surface.diffuse = texel.diffuse;
    surface.specular = texel.specular;
    surface.oneMinusReflectivity =
        1.0f - std::max({texel.specular.r, texel.specular.g, texel.specular.b});
    const glm::vec3 n = glm::normalize(texel.encodedNormal * 2.0f - 1.0f);
    const glm::vec3 v = glm::normalize(cameraPos - p);
    return brdfPbs(surface, texel.smoothness, n, v, l, light.finalColor() * (atten * shadow),
                   glm::vec3(0.0f), glm::vec3(0.0f));
}

// The light buffer after every light, then what the frame shows (LDR: decoded, 0..1).
glm::vec3 shadePixel(const scene::Scene& scene, const LightTextureSet& textures,
                     const DeferredShadows& shadows, const GBufferTexel& texel,
                     const glm::vec3& p, size_t pixel, bool upper) {
    const bool hdr = scene.camera.hdr;
    glm::vec3 buffer = texel.light;
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const scene::Light& light = scene.lights[i];
        const glm::vec3 c = lightPass(light, textures, texel, p, scene.camera.position,
                                      deferredShadow(shadows, i, light, p, pixel, upper));
        for (int k = 0; k < 3; ++k) {
            // LDR: Blend DstColor Zero on unorm8 = round(src8 · dst8 / 255).
            buffer[k] = hdr ? toHalf(buffer[k] + toHalf(c[k]))
                            : std::round(unorm8(std::exp2(-c[k])) * buffer[k] / 255.0f);
        }
    }
    if (hdr) return buffer;
    glm::vec3 decoded;
    for (int k = 0; k < 3; ++k) decoded[k] = unorm8(-std::log2(buffer[k] / 255.0f)) / 255.0f;
    return decoded;
}

Status checkCookies(const scene::Scene& scene) {
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const std::string& cookie = scene.lights[i].cookie;
        if (cookie != "none" && cookie != "default" && !scene::isTextureFile(cookie)) {
            return makeError(ErrorCode::Unsupported,
                             "/lights/" + std::to_string(i) +
                                 ": the CPU reference knows the default cookies and PNG files, "
                                 "not '" +
                                 cookie + "'");
        }
    }
    return Ok{};
}

}  // namespace

float srgb8RoundTrip(float linear) {
    const float x = std::clamp(linear, 0.0f, 1.0f);
    const float encoded = x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
    const float byte = std::round(encoded * 255.0f) / 255.0f;
    return byte <= 0.04045f ? byte / 12.92f : std::pow((byte + 0.055f) / 1.055f, 2.4f);
}

Result<GBufferMaterial> resolveGBufferMaterial(const scene::Material& material) {
    if (scene::referenceModelOf(material) != "varc-deferred-gbuffer") {
        return makeError(ErrorCode::NotFound,
                         "the deferred reference has no model for shader '" + material.shader + "'");
    }
    GBufferMaterial m;
    for (const auto& [name, value] : material.properties) {
        Status status = Ok{};
        if (name == "_Color") {
            status = readProperty(value, name, m.color);
        } else if (name == "_Metallic") {
            status = readProperty(value, name, m.metallic);
        } else if (name == "_Smoothness") {
            status = readProperty(value, name, m.smoothness);
        } else if (name == "_EmissionColor") {
            glm::vec4 e;
            status = readProperty(value, name, e);
            m.emission = glm::vec3(e);
        } else if (name == "_MainTex") {
            status = readColorTexture(value, name, m.mainTex, m.mainTexture);
        } else if (name == "_MainTex_ST") {
            status = readProperty(value, name, m.mainTexST);
        }
        if (!status) return status.error();
    }
    return m;
}

namespace {

// The shadow maps, screen-space masks and fades of |scene|'s lights; |anyShadowMap| tells
// whether some light has a map.
DeferredShadows renderDeferredShadows(const scene::Scene& scene, bool& anyShadowMap) {
    // Every G-buffer object casts (varc/DeferredGBuffer falls back to VertexLit's caster).
    DeferredShadows shadows;
    ShadowCaster opaque;
    opaque.casts = true;
    const std::vector<ShadowCaster> casts(scene.objects.size(), opaque);
    for (const scene::Light& light : scene.lights) {
        shadows.fades.push_back(shadowFadeFor(scene, light));
        const bool mapped = light.shadows != scene::ShadowType::None;
        std::unique_ptr<ShadowMapReference> map;
        std::vector<ShadowInterval> mask;
        if (mapped && light.type == scene::LightType::Spot) {
            map = std::make_unique<ShadowMapReference>(
                ShadowMapReference::renderSpot(scene, light, casts));
        } else if (mapped && light.type == scene::LightType::Point) {
            map = std::make_unique<ShadowMapReference>(
                ShadowMapReference::renderPoint(scene, light, casts));
        } else if (mapped) {
            map = std::make_unique<ShadowMapReference>(
                ShadowMapReference::renderDirectional(scene, light, casts));
            mask = map->screenMask(scene, casts, light.shadows == scene::ShadowType::Soft);
        }
        shadows.maps.push_back(std::move(map));
        shadows.masks.push_back(std::move(mask));
        anyShadowMap = anyShadowMap || mapped;
    }
    return shadows;
}

}  // namespace

Result<ReferenceImage> renderDeferredReference(const scene::Scene& scene) {
    if (scene.camera.path != scene::RenderPath::Deferred) {
        return makeError(ErrorCode::Unsupported,
                         "renderDeferredReference renders the deferred path only");
    }
    if (Status cookies = checkCookies(scene); !cookies) return cookies.error();
    std::vector<ObjectSurface> surfaces;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        auto surface = prepareObject(scene, scene.objects[i]);
        if (!surface) {
            return makeError(surface.error().code,
                             "/objects/" + std::to_string(i) + ": " + surface.error().detail);
        }
        surfaces.push_back(std::move(*surface));
    }
    LightTextureSet textures;
    if (Status cookies = textures.loadCookieFiles(scene.lights); !cookies) return cookies.error();
    bool anyShadowMap = false;
    const DeferredShadows shadows = renderDeferredShadows(scene, anyShadowMap);
    const scene::CameraMatrices camera = scene::cameraMatrices(scene.camera);
    ReferenceImage out;
    out.visibility = rasterizeScene(scene, camera);
    out.classes = classifyPixels(scene, out.visibility);
    const uint32_t w = scene.camera.width, h = scene.camera.height;
    out.color = image::Image(w, h, image::PixelFormat::RgbaFloat);
    if (anyShadowMap) out.colorHigh = image::Image(w, h, image::PixelFormat::RgbaFloat);
    const bool hdr = scene.camera.hdr;
    glm::vec4 background = scene.camera.background;
    for (int c = 0; c < 4; ++c)
        background[c] = hdr ? toHalf(background[c]) : unorm8(background[c]) / 255.0f;
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            const SurfaceSample& s = out.visibility.at(x, y);
            glm::vec4 c = background, high = background;
            if (s.object >= 0) {
                const ObjectSurface& surface = surfaces[static_cast<size_t>(s.object)];
                glm::vec3 p(0.0f), normal(0.0f);
                glm::vec2 uv(0.0f);
                for (uint32_t k = 0; k < 3; ++k) {
                    const uint32_t v = surface.mesh->indices[3 * s.triangle + k];
                    const float weight = s.bary[static_cast<glm::length_t>(k)];
                    p += weight * surface.worldPos[v];
                    normal += weight * surface.worldNormal[v];
                    uv += weight * surface.mesh->uvs[v];
                }
                const GBufferTexel texel = gbufferTexel(surface, normal, uv, hdr);
                const float alpha = hdr ? 1.0f : background.a;
                const size_t pixel = size_t{y} * w + x;
                c = glm::vec4(shadePixel(scene, textures, shadows, texel, p, pixel, false), alpha);
                if (anyShadowMap) {
                    high = glm::vec4(shadePixel(scene, textures, shadows, texel, p, pixel, true),
                                     alpha);
                }
            }
            out.color.setPixelFloat(x, y, {c.r, c.g, c.b, c.a});
            if (anyShadowMap) out.colorHigh.setPixelFloat(x, y, {high.r, high.g, high.b, high.a});
        }
    }
    return out;
}

}  // namespace varc::reference
