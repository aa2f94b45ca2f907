// SPDX-License-Identifier: Apache-2.0
// SinglePassReference: varc/SinglePassLit and seed 003's Lit shader on the CPU (docs/LIGHTING.md
// §8.4), on the shared visibility buffer.
#include "varc/reference/SinglePassReference.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "varc/scene/CameraMatrices.h"
#include "varc/scene/Mesh.h"

namespace varc::reference {
namespace {

constexpr const char* kLibraryModel = "varc-single-pass-lit";
// Seed 003's "My Pipeline/Lit": the same light buffer and fades, but the normal is
// mul((float3x3)UNITY_MATRIX_M, normal) (uniform scale assumed), unnormalised in the vertex
// stage (its per-vertex lights use it as is) and normalised per fragment.
constexpr const char* kSeed003Model = "seed003";

float saturate(float x) { return std::clamp(x, 0.0f, 1.0f); }

// What one object's draw needs per fragment.
struct ObjectShading {
    glm::vec3 albedo{1.0f};
    bool modelMatrixNormals = false;  // seed003: M's 3x3 part, not the inverse transpose
    std::vector<const scene::Light*> pixelLights;  // idx0[k], k < min(count, 4)
    const scene::Mesh* mesh = nullptr;
    std::vector<glm::vec3> worldPos, worldNormal, vertexLighting;  // per mesh vertex
};

Result<glm::vec3> albedoOf(const scene::Material& material) {
    const std::string model = scene::referenceModelOf(material);
    if (model != kLibraryModel && model != kSeed003Model) {
        return makeError(ErrorCode::NotFound,
                         "the single-pass reference has no model for shader '" + material.shader +
                             "' (only " + kLibraryModel + " and " + kSeed003Model + ")");
    }
    auto it = material.properties.find("_Color");
    if (it == material.properties.end()) return glm::vec3(1.0f);
    const auto* color = std::get_if<glm::vec4>(&it->second);
    if (!color)
        return makeError(ErrorCode::InvalidInput, "material property _Color: expected a colour");
    return glm::vec3(*color);
}

Result<ObjectShading> prepareObject(const scene::Scene& scene,
                                    const scene::VisibleLightSet& visible,
                                    const scene::Object& object,
                                    const SinglePassReferenceOptions& options) {
    ObjectShading out;
    auto albedo = albedoOf(object.material);
    if (!albedo) return albedo.error();
    out.albedo = *albedo;
    out.modelMatrixNormals = scene::referenceModelOf(object.material) == kSeed003Model;
    scene::ObjectLightList list = scene::objectLightList(scene, visible, object);
    if (options.editLights) options.editLights(list);
    // The shader clamps every index into the 16-slot buffer and reads only the first
    // min(count, 4) / min(count, 8) entries.
    auto lightAt = [&](size_t k) -> const scene::Light* {
        const int slot = std::clamp(list.slots[k], 0, scene::kMaxVisibleLights - 1);
        return &scene.lights[static_cast<size_t>(visible.slots[static_cast<size_t>(slot)])];
    };
    const size_t count = static_cast<size_t>(std::max(list.count, 0));
    std::vector<const scene::Light*> vertexLights;
    for (size_t k = 0; k < std::min<size_t>(count, scene::kMaxLightsPerObject); ++k) {
        (k < scene::kMaxPixelLightsPerObject ? out.pixelLights : vertexLights)
            .push_back(lightAt(k));
    }

    out.mesh = &scene::builtinMesh(object.mesh);
    const glm::mat4 objectToWorld = object.transform.localToWorld();
    // varc-single-pass-lit: normalize(mul(normalOS, (float3x3)unity_WorldToObject)), the
    // inverse transpose; seed003: mul((float3x3)UNITY_MATRIX_M, normalOS), not normalised.
    const glm::mat3 normalMatrix = out.modelMatrixNormals
                                       ? glm::mat3(objectToWorld)
                                       : glm::transpose(glm::mat3(glm::inverse(objectToWorld)));
    for (size_t i = 0; i < out.mesh->positions.size(); ++i) {
        const glm::vec3 p(objectToWorld * glm::vec4(out.mesh->positions[i], 1.0f));
        glm::vec3 n = normalMatrix * out.mesh->normals[i];
        if (!out.modelMatrixNormals) n = glm::normalize(n);
        glm::vec3 lighting(0.0f);
        for (const scene::Light* light : vertexLights) {
            lighting += singlePassIrradiance(*light, p, n, options.spotInnerTangentRatio);
        }
        out.worldPos.push_back(p);
        out.worldNormal.push_back(n);
        out.vertexLighting.push_back(lighting);
    }
    return out;
}

glm::vec3 shadeFragment(const ObjectShading& object, const SurfaceSample& sample,
                        const SinglePassReferenceOptions& options) {
    glm::vec3 p(0.0f), normal(0.0f), irradiance(0.0f);
    for (int k = 0; k < 3; ++k) {
        const uint32_t v = object.mesh->indices[3 * sample.triangle + static_cast<uint32_t>(k)];
        p += sample.bary[k] * object.worldPos[v];
        normal += sample.bary[k] * object.worldNormal[v];
        irradiance += sample.bary[k] * object.vertexLighting[v];
    }
    const glm::vec3 n = glm::normalize(normal);
    for (const scene::Light* light : object.pixelLights) {
        irradiance += singlePassIrradiance(*light, p, n, options.spotInnerTangentRatio);
    }
    return object.albedo * irradiance;
}

// The attachment's value: RGBA8_UNORM rounding (LDR) or half precision (HDR).
glm::vec4 quantize(const glm::vec4& c, bool hdr) {
    glm::vec4 out;
    for (int i = 0; i < 4; ++i) {
        out[i] = hdr ? image::halfToFloat(image::floatToHalf(c[i]))
                     : std::round(saturate(c[i]) * 255.0f) / 255.0f;
    }
    return out;
}

}  // namespace

glm::vec3 singlePassIrradiance(const scene::Light& light, const glm::vec3& p, const glm::vec3& n,
                               float spotInnerTangentRatio) {
    const bool directional = light.type == scene::LightType::Directional;
    const glm::vec3 toLight = directional ? -light.forward() : light.transform.position - p;
    const float distanceSq = glm::dot(toLight, toLight);
    const glm::vec3 l = toLight * (1.0f / std::sqrt(std::max(distanceSq, 1e-10f)));
    float rangeFade = 1.0f, spotFade = 1.0f;
    if (!directional) {
        const float invRangeSq = 1.0f / std::max(light.range * light.range, 1e-5f);
        const float t = distanceSq * invRangeSq;
        rangeFade = saturate(1.0f - t * t);
    }
    if (light.type == scene::LightType::Spot) {
        const float outer = glm::radians(0.5f * light.spotAngle);
        const float outerCos = std::cos(outer);
        const float innerCos = std::cos(std::atan(spotInnerTangentRatio * std::tan(outer)));
        const float a = 1.0f / std::max(innerCos - outerCos, 0.001f);
        spotFade = saturate(glm::dot(-light.forward(), l) * a - outerCos * a);
    }
    const float lambert = saturate(glm::dot(n, l));
    return light.finalColor() * (lambert * (rangeFade * rangeFade) * (spotFade * spotFade) /
                                 std::max(distanceSq, 1e-5f));
}

Result<ReferenceImage> renderSinglePassReference(const scene::Scene& scene,
                                                 const SinglePassReferenceOptions& options) {
    if (scene.camera.path != scene::RenderPath::SinglePass) {
        return makeError(ErrorCode::Unsupported,
                         "the single-pass reference renders \"path\": \"single_pass\" scenes only");
    }
    const scene::VisibleLightSet visible = scene::selectVisibleLights(scene);
    std::vector<ObjectShading> objects;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        auto object = prepareObject(scene, visible, scene.objects[i], options);
        if (!object) {
            return makeError(object.error().code,
                             "/objects/" + std::to_string(i) + ": " + object.error().detail);
        }
        objects.push_back(std::move(*object));
    }
    const scene::CameraMatrices camera = scene::cameraMatrices(scene.camera);
    ReferenceImage out;
    out.visibility = rasterizeScene(scene, camera);
    out.classes = classifyPixels(scene, out.visibility);
    const uint32_t w = scene.camera.width, h = scene.camera.height;
    out.color = image::Image(w, h, image::PixelFormat::RgbaFloat);
    const bool hdr = scene.camera.hdr;
    const glm::vec4 background = quantize(scene.camera.background, hdr);
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            const SurfaceSample& s = out.visibility.at(x, y);
            glm::vec4 c = background;
            if (s.object >= 0) {
                c = quantize(
                    glm::vec4(shadeFragment(objects[static_cast<size_t>(s.object)], s, options),
                              1.0f),
                    hdr);
            }
            out.color.setPixelFloat(x, y, {c.r, c.g, c.b, c.a});
        }
    }
    return out;
}

}  // namespace varc::reference
