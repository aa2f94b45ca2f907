// SPDX-License-Identifier: Apache-2.0
// ReferenceRenderer: per-object forward passes on the visibility buffer, with the attachment's
// quantisation between passes.
#include "varc/reference/ReferenceRenderer.h"

#include <algorithm>
#include <cmath>

#include "MaterialResolver.h"
#include "varc/reference/Shading.h"
#include "varc/reference/ShadowReference.h"
#include "varc/scene/CameraMatrices.h"
#include "varc/scene/Mesh.h"
#include "varc/scene/ObjectLightmaps.h"

namespace varc::reference {
namespace {

// The per-vertex and per-pass data of one object's draws.
struct ObjectDraw {
    MaterialParams material;
    std::vector<glm::vec3> worldPos, worldNormal, vertexTerm;
    glm::mat4 worldToObject{1.0f};
    const scene::Mesh* mesh = nullptr;
    bool vertexLightsOn = false;
    // LIGHTPROBE_SH in the base variant (the object uses light probes; shaders without the
    // keyword ignore it): SH, else the flat ambient colour.
    bool lightProbeSh = true;
    std::array<glm::vec4, 7> sh{};
    PassLight base;
    std::vector<PassLight> adds;
};

// The interpolated inputs of one fragment.
struct Varyings {
    glm::vec3 p, normal, vertexTerm;
    glm::vec2 uv;      // uv0 (object mesh), before _MainTex_ST
    size_t pixel = 0;  // row-major index of the camera pixel (screen-space shadow masks)
    glm::vec3 objectPos{0.0f}, objectNormal{0.0f};  // mesh position and normal, interpolated
};

// _MainTex at the fragment: the PNG filtered at TRANSFORM_TEX(uv, _MainTex), or the constant.
glm::vec4 mainTexAt(const MaterialParams& m, const Varyings& in) {
    if (!m.mainTexture) return m.mainTex;
    return m.mainTexture->sample(in.uv * glm::vec2(m.mainTexST) +
                                 glm::vec2(m.mainTexST.z, m.mainTexST.w));
}

glm::vec3 lightDirection(const PassLight& light, const glm::vec3& p) {
    return glm::normalize(glm::vec3(light.worldSpaceLightPos) - p * light.worldSpaceLightPos.w);
}

glm::vec3 maxZero(const glm::vec3& v) { return glm::max(v, glm::vec3(0.0f)); }

// The shadow term of |light| at |p| (LIGHTING.md §6), faded where the pass fades it: the
// interval's lower or |upper| bound; 1 without a shadow map.
float shadowTerm(const PassLight& light, const Varyings& in, bool upper) {
    const glm::vec3& p = in.p;
    if (!light.shadowMap && !light.screenMask) return 1.0f;
    ShadowInterval shadow = light.screenMask ? (*light.screenMask)[in.pixel]
                                             : light.shadowMap->at(p, light.softShadows);
    if (light.shadowFade) shadow = light.shadowFade->apply(shadow, p);
    return upper ? shadow.high : shadow.low;
}

// Seed 001's GLSL shader as written (LIGHTING.md §8.6): directional lights unattenuated, point
// and spot lights (no cone) 1/d; Phong specular; the base pass adds the vertex lights and
// gl_LightModel.ambient * _Color.
glm::vec3 seed001Phong(const MaterialParams& m, const Varyings& in, const PassLight& light,
                       const glm::vec3& n, const glm::vec3& cameraPos, const glm::vec3& ambient,
                       bool base) {
    const glm::vec3 v = glm::normalize(cameraPos - in.p);
    float attenuation = 1.0f;
    glm::vec3 l = glm::normalize(glm::vec3(light.worldSpaceLightPos));
    if (light.worldSpaceLightPos.w != 0.0f) {
        const glm::vec3 toLight = glm::vec3(light.worldSpaceLightPos) - in.p;
        attenuation = 1.0f / glm::length(toLight);
        l = glm::normalize(toLight);
    }
    const glm::vec3 color(m.color);
    const glm::vec3 diffuse = attenuation * light.color * color * std::max(0.0f, glm::dot(n, l));
    glm::vec3 specular(0.0f);
    if (glm::dot(n, l) >= 0.0f) {
        specular = attenuation * light.color * m.specColor *
                   std::pow(std::max(0.0f, glm::dot(glm::reflect(-l, n), v)), m.shininess);
    }
    glm::vec3 c = diffuse + specular;
    if (base) c += in.vertexTerm + ambient * color;
    return c;
}

// Seed 004's BetterDiffuse as written (LIGHTING.md §8.6): the interpolated object-space normal
// (not normalised) against the normalised object-space light vector, light and ambient doubled;
// the base pass tints by _Color + the vertex lights and reads _MainTex without _MainTex_ST. The
// add pass is the article's first fragment program, which still adds the ambient term (the text
// says to leave it out; the code it prints does not): every add light adds it once more.
glm::vec4 seed004Diffuse(const ObjectDraw& draw, const Varyings& in, const PassLight& light,
                         const glm::vec3& ambient, bool base, const LightTextureSet& textures,
                         bool upper) {
    const MaterialParams& m = draw.material;
    const glm::vec4 objectLight = draw.worldToObject * light.worldSpaceLightPos;
    const glm::vec3 l = glm::normalize(glm::vec3(objectLight) - in.objectPos * objectLight.w);
    const float diff = std::clamp(glm::dot(in.objectNormal, l), 0.0f, 1.0f);
    const float atten = lightAttenuation(light, textures, in.p) * shadowTerm(light, in, upper);
    glm::vec4 tex =
        base ? (m.mainTexture ? m.mainTexture->sample(in.uv) : m.mainTex) : mainTexAt(m, in);
    tex *= base ? m.color + glm::vec4(in.vertexTerm, 1.0f) : m.color;
    glm::vec3 c = ambient * 2.0f * glm::vec3(tex);
    c += glm::vec3(tex) * light.color * diff * (atten * 2.0f);
    return {c, tex.a};
}

// One pass of one fragment: LIGHTING.md §8.1, §8.2, §8.5, §8.6. |upper| picks the upper bound of
// shadow terms that straddle a comparison.
glm::vec4 shadePass(const ObjectDraw& draw, const Varyings& in, const PassLight& light, bool base,
                    const glm::vec3& cameraPos, const glm::vec3& ambient,
                    const LightTextureSet& textures, const ReferenceOptions& options, bool upper) {
    const MaterialParams& m = draw.material;
    const glm::vec3 n = glm::normalize(in.normal);
    const glm::vec3 l = lightDirection(light, in.p);
    switch (m.model) {
        case ShaderModel::ForwardPbs: {
            const glm::vec3 v = glm::normalize(cameraPos - in.p);
            const SurfaceColors surface = diffuseAndSpecularFromMetallic(
                glm::vec3(mainTexAt(m, in)) * glm::vec3(m.color), m.metallic);
            const glm::vec3 e = light.color * (lightAttenuation(light, textures, in.p) *
                                               shadowTerm(light, in, upper));
            glm::vec3 indirect(0.0f);
            if (base) {
                if (draw.vertexLightsOn) indirect = in.vertexTerm;
                indirect += maxZero(scene::shadeSH9(draw.sh, n));
            }
            return {brdfPbs(surface, m.smoothness, n, v, l, e, indirect, glm::vec3(0.0f)), 1.0f};
        }
        case ShaderModel::SimpleDiffuse: {
            const glm::vec4 albedo = mainTexAt(m, in) * m.color;
            const float atten =
                lightAttenuation(light, textures, in.p) * shadowTerm(light, in, upper);
            glm::vec3 c =
                glm::vec3(albedo) * light.color * (std::clamp(glm::dot(n, l), 0.0f, 1.0f) * atten);
            if (base) c += glm::vec3(albedo) * in.vertexTerm;
            return {c, albedo.a};
        }
        case ShaderModel::GlslBlinnPhong: {
            const glm::vec3 v = glm::normalize(cameraPos - in.p);
            const glm::vec3 toLight =
                glm::vec3(light.worldSpaceLightPos) - in.p * light.worldSpaceLightPos.w;
            float falloff = 1.0f;
            if (light.worldSpaceLightPos.w != 0.0f) {
                const float invRange = light.positionRange.w;
                const float t = glm::dot(toLight, toLight) * invRange * invRange;
                falloff = options.falloffOverride
                              ? options.falloffOverride(t)
                              : std::clamp((1.0f - t) / 0.36f, 0.0f, 1.0f) / (1.0f + 25.0f * t);
            }
            const glm::vec3 kd(m.color);
            const float ndotl = glm::dot(n, l);
            glm::vec3 specular(0.0f);
            if (ndotl > 0.0f) {
                const glm::vec3 h = glm::normalize(l + v);
                specular = m.specColor * std::pow(std::max(0.0f, glm::dot(n, h)), m.shininess);
            }
            glm::vec3 c = light.color * falloff * (kd * std::max(0.0f, ndotl) + specular);
            if (base) {
                const glm::vec3 a =
                    draw.lightProbeSh ? maxZero(scene::shadeSH9(draw.sh, n)) : ambient;
                c += kd * (a + in.vertexTerm);
            }
            return {c, 1.0f};
        }
        case ShaderModel::Seed001Phong:
            return {seed001Phong(m, in, light, n, cameraPos, ambient, base), 1.0f};
        case ShaderModel::Seed004Diffuse:
            return seed004Diffuse(draw, in, light, ambient, base, textures, upper);
        case ShaderModel::CasterOnly:  // not in the camera: never shaded
            break;
    }
    return glm::vec4(0.0f);
}

// The seeds' vertex-light loop: sum over the four slots of
// colour * max(0, n . l) / (1 + atten * d^2), with |n| as the shader computes it.
glm::vec3 seedVertexLights(const VertexLights& lights, const glm::vec3& p, const glm::vec3& n) {
    glm::vec3 sum(0.0f);
    for (int i = 0; i < 4; ++i) {
        const glm::vec3 toLight = glm::vec3(lights.posX[i], lights.posY[i], lights.posZ[i]) - p;
        const float attenuation = 1.0f / (1.0f + lights.attenSq[i] * glm::dot(toLight, toLight));
        sum += attenuation * lights.colors[static_cast<size_t>(i)] *
               std::max(0.0f, glm::dot(n, glm::normalize(toLight)));
    }
    return sum;
}

// Per-vertex terms (interpolated by the GPU): vertex lights, and SimpleDiffuse's ambient.
// |objectNormal| is the mesh's normal (seed 004 uses it unnormalised in world space).
glm::vec3 vertexTerm(const ObjectDraw& draw, const VertexLights& lights, const glm::vec3& ambient,
                     const glm::vec3& p, const glm::vec3& n, const glm::vec3& objectNormal,
                     const glm::mat4& objectToWorld) {
    const glm::vec3 color(draw.material.color);
    if (draw.material.model == ShaderModel::Seed001Phong) {
        return draw.vertexLightsOn ? color * seedVertexLights(lights, p, n) : glm::vec3(0.0f);
    }
    if (draw.material.model == ShaderModel::Seed004Diffuse) {
        const glm::vec3 worldN = glm::mat3(objectToWorld) * objectNormal;
        return draw.vertexLightsOn ? 2.0f * color * seedVertexLights(lights, p, worldN)
                                   : glm::vec3(0.0f);
    }
    glm::vec3 term(0.0f);
    if (draw.material.model == ShaderModel::SimpleDiffuse) {
        term = draw.lightProbeSh ? maxZero(scene::shadeSH9(draw.sh, n)) : ambient;
    }
    if (draw.vertexLightsOn) term += shade4PointLights(lights, p, n);
    return term;
}

// The CPU shadow maps of a scene by light index (null for lights without one), and the
// screen-space masks of its shadowed directional lights (empty for the others).
struct ShadowMapSet {
    std::vector<std::unique_ptr<ShadowMapReference>> maps;
    std::vector<std::vector<ShadowInterval>> masks;
};

Result<ObjectDraw> prepareObject(const scene::Scene& scene, const scene::Object& object,
                                 const ShadowMapSet& shadowMaps, const ReferenceOptions& options) {
    ObjectDraw draw;
    auto material = resolveMaterial(object.material);
    if (!material) return material.error();
    draw.material = *material;
    scene::ForwardLightAssignment lights = scene::assignForwardLights(scene, object);
    if (options.editAssignment) options.editAssignment(lights);
    draw.base = noPassLight();
    if (lights.mainDirectional >= 0) {
        auto main = passLightFor(scene.lights[lights.mainDirectional]);
        if (!main) return main.error();
        draw.base = *main;
        const auto light = static_cast<size_t>(lights.mainDirectional);
        if (draw.material.receivesBaseShadows && !shadowMaps.masks[light].empty())
            draw.base.screenMask = &shadowMaps.masks[light];
    }
    for (int index : lights.addLights) {
        auto add = passLightFor(scene.lights[index]);
        if (!add) return add.error();
        const auto light = static_cast<size_t>(index);
        if (draw.material.receivesAddShadows && shadowMaps.maps[light]) {
            if (shadowMaps.masks[light].empty()) {
                add->shadowMap = shadowMaps.maps[light].get();
            } else {
                add->screenMask = &shadowMaps.masks[light];
            }
            add->softShadows = scene.lights[light].shadows == scene::ShadowType::Soft;
            if (draw.material.model == ShaderModel::ForwardPbs && !options.ignoreShadowFade)
                add->shadowFade = shadowFadeFor(scene, scene.lights[light]);
        }
        draw.adds.push_back(*add);
    }
    // Lightmapped objects have no vertex lights (fwdbase: VERTEXLIGHT_ON => !LIGHTMAP_ON); the
    // lightmap keywords change nothing else in the models known here, whose shaders never sample
    // a lightmap (LIGHTING.md §8.7).
    const scene::ObjectLightmaps lightmaps = scene::objectLightmaps(scene, object);
    draw.vertexLightsOn = !lights.vertexLights.empty() && lightmaps.vertexLights();
    draw.lightProbeSh = options.lightProbeSh && lightmaps.lightProbes;
    draw.sh = scene::packedSH(scene, object, lights.shLights);
    const VertexLights vertexLights = vertexLightsFor(scene, lights.vertexLights);

    draw.mesh = &scene::builtinMesh(object.mesh);
    const glm::mat4 objectToWorld = object.transform.localToWorld();
    draw.worldToObject = glm::inverse(objectToWorld);
    // UnityObjectToWorldNormal: normalize(mul(n, (float3x3)unity_WorldToObject)).
    const glm::mat3 normalMatrix = glm::transpose(glm::mat3(glm::inverse(objectToWorld)));
    for (size_t i = 0; i < draw.mesh->positions.size(); ++i) {
        const glm::vec3 p(objectToWorld * glm::vec4(draw.mesh->positions[i], 1.0f));
        const glm::vec3 n = glm::normalize(normalMatrix * draw.mesh->normals[i]);
        draw.worldPos.push_back(p);
        draw.worldNormal.push_back(n);
        draw.vertexTerm.push_back(vertexTerm(draw, vertexLights, scene.ambient, p, n,
                                             draw.mesh->normals[i], objectToWorld));
    }
    return draw;
}

float quantize8(float v) { return std::round(std::clamp(v, 0.0f, 1.0f) * 255.0f); }
float toHalf(float v) { return image::halfToFloat(image::floatToHalf(v)); }

// The attachment after all passes: LDR in 8-bit units (0..255), HDR in half-rounded floats.
glm::vec4 accumulate(const glm::vec4& base, const std::vector<glm::vec4>& adds, bool hdr) {
    glm::vec4 dst;
    for (int c = 0; c < 4; ++c) dst[c] = hdr ? toHalf(base[c]) : quantize8(base[c]);
    for (const glm::vec4& add : adds) {
        for (int c = 0; c < 4; ++c) {
            dst[c] = hdr ? toHalf(dst[c] + toHalf(add[c]))
                         : std::min(255.0f, dst[c] + quantize8(add[c]));
        }
    }
    return hdr ? dst : dst / 255.0f;
}

// The shadow maps of |scene|'s shadowed lights drawn from |casts|, and the screen-space masks of
// its directional ones.
ShadowMapSet renderShadowMaps(const scene::Scene& scene, const std::vector<ShadowCaster>& casts,
                              const ReferenceOptions& options) {
    ShadowMapSet shadowMaps;
    shadowMaps.maps.resize(scene.lights.size());
    shadowMaps.masks.resize(scene.lights.size());
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const scene::Light& light = scene.lights[i];
        if (light.shadows == scene::ShadowType::None) continue;
        shadowMaps.maps[i] = std::make_unique<ShadowMapReference>(
            light.type == scene::LightType::Spot
                ? ShadowMapReference::renderSpot(scene, light, casts)
            : light.type == scene::LightType::Point
                ? ShadowMapReference::renderPoint(scene, light, casts)
                : ShadowMapReference::renderDirectional(scene, light, casts));
        if (options.editShadowMap) options.editShadowMap(*shadowMaps.maps[i]);
        if (light.type == scene::LightType::Directional) {
            shadowMaps.masks[i] = shadowMaps.maps[i]->screenMask(
                scene, casts, light.shadows == scene::ShadowType::Soft);
        }
    }
    return shadowMaps;
}

// The inputs of the fragment of |draw| at visibility sample |s|, camera pixel |pixel|.
Varyings interpolate(const ObjectDraw& draw, const SurfaceSample& s, size_t pixel) {
    Varyings in{glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f), glm::vec2(0.0f), pixel};
    for (int k = 0; k < 3; ++k) {
        const uint32_t v = draw.mesh->indices[3 * s.triangle + static_cast<uint32_t>(k)];
        in.p += s.bary[k] * draw.worldPos[v];
        in.normal += s.bary[k] * draw.worldNormal[v];
        in.vertexTerm += s.bary[k] * draw.vertexTerm[v];
        in.uv += s.bary[k] * draw.mesh->uvs[v];
        in.objectPos += s.bary[k] * draw.mesh->positions[v];
        in.objectNormal += s.bary[k] * draw.mesh->normals[v];
    }
    return in;
}

}  // namespace

Result<ReferenceImage> renderReference(const scene::Scene& scene, const ReferenceOptions& options) {
    if (scene.camera.path != scene::RenderPath::Forward) {
        return makeError(ErrorCode::Unsupported, "the CPU reference renders the forward path only");
    }
    std::vector<ShadowCaster> casts;
    std::vector<bool> drawn;  // in the camera
    for (const scene::Object& object : scene.objects) {
        auto material = resolveMaterial(object.material);
        casts.push_back(material ? casterOf(*material, options) : ShadowCaster{});
        drawn.push_back(!material || material->model != ShaderModel::CasterOnly);
    }
    const ShadowMapSet shadowMaps = renderShadowMaps(scene, casts, options);
    std::vector<ObjectDraw> draws;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        auto draw = prepareObject(scene, scene.objects[i], shadowMaps, options);
        if (!draw) {
            return makeError(draw.error().code,
                             "/objects/" + std::to_string(i) + ": " + draw.error().detail);
        }
        draws.push_back(std::move(*draw));
    }
    LightTextureSet textures;
    if (Status cookies = textures.loadCookieFiles(scene.lights); !cookies) return cookies.error();
    if (options.falloffOverride) textures.setFalloffOverride(options.falloffOverride);

    const scene::CameraMatrices camera = scene::cameraMatrices(scene.camera);
    ReferenceImage out;
    out.visibility = rasterizeScene(scene, camera, drawn);
    out.classes = classifyPixels(scene, out.visibility);
    const uint32_t w = scene.camera.width, h = scene.camera.height;
    out.color = image::Image(w, h, image::PixelFormat::RgbaFloat);
    const bool anyShadowMap = std::any_of(shadowMaps.maps.begin(), shadowMaps.maps.end(),
                                          [](const auto& map) { return map != nullptr; });
    if (anyShadowMap) out.colorHigh = image::Image(w, h, image::PixelFormat::RgbaFloat);
    const bool hdr = scene.camera.hdr;
    const glm::vec4 background = accumulate(scene.camera.background, {}, hdr);
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            const SurfaceSample& s = out.visibility.at(x, y);
            glm::vec4 c = background, high = background;
            if (s.object >= 0) {
                const ObjectDraw& draw = draws[static_cast<size_t>(s.object)];
                const Varyings in = interpolate(draw, s, size_t{y} * w + x);
                for (bool upper : {false, true}) {
                    if (upper && !anyShadowMap) break;
                    const glm::vec4 base =
                        shadePass(draw, in, draw.base, true, scene.camera.position, scene.ambient,
                                  textures, options, upper);
                    std::vector<glm::vec4> adds;
                    for (const PassLight& light : draw.adds) {
                        adds.push_back(shadePass(draw, in, light, false, scene.camera.position,
                                                 scene.ambient, textures, options, upper));
                    }
                    (upper ? high : c) = accumulate(base, adds, hdr);
                }
            }
            out.color.setPixelFloat(x, y, {c.r, c.g, c.b, c.a});
            if (anyShadowMap) out.colorHigh.setPixelFloat(x, y, {high.r, high.g, high.b, high.a});
        }
    }
    return out;
}

}  // namespace varc::reference
