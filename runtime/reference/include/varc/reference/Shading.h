// SPDX-License-Identifier: Apache-2.0
// Shading: the per-pixel lighting math of docs/LIGHTING.md, evaluated on the CPU in 32-bit float
// in the order the library's shaders evaluate it, and the light textures sampled as the GPU
// samples them. No Vulkan.
#pragma once

#include <array>
#include <functional>
#include <glm/glm.hpp>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "varc/core/Result.h"
#include "varc/reference/ShadowReference.h"
#include "varc/scene/LightTextures.h"
#include "varc/scene/Scene.h"

namespace varc::reference {


// LIGHTING.md §1: DiffuseAndSpecularFromMetallic.
struct SurfaceColors {
    glm::vec3 diffuse{0.0f};   // c_d
    glm::vec3 specular{0.0f};  // F0
    float oneMinusReflectivity = 1.0f;
};
SurfaceColors diffuseAndSpecularFromMetallic(const glm::vec3& albedo, float metallic);

// LIGHTING.md §2, BRDF1_Unity_PBS: |l| unit towards the light, |lightColor| = E (attenuation
// applied), |indirectDiffuse| = I_d, |indirectSpecular| = I_s. Returns rgb.
glm::vec3 brdfPbs(const SurfaceColors& surface, float smoothness, const glm::vec3& n,
                  const glm::vec3& v, const glm::vec3& l, const glm::vec3& lightColor,
                  const glm::vec3& indirectDiffuse, const glm::vec3& indirectSpecular);

// The four vertex-light slots of SHADER_ABI.md §4.5 (unused slots zero).
struct VertexLights {
    glm::vec4 posX{0.0f}, posY{0.0f}, posZ{0.0f};  // unity_4LightPosX0/Y0/Z0
    glm::vec4 attenSq{0.0f};                       // unity_4LightAtten0 = 25 / range²
    std::array<glm::vec3, 4> colors{};             // unity_LightColor[0..3].rgb
};
VertexLights vertexLightsFor(const scene::Scene& scene, const std::vector<int>& lights);
// docs/LIGHTING.md §5.
glm::vec3 shade4PointLights(const VertexLights& lights, const glm::vec3& pos,
                            const glm::vec3& normal);

// The GPU-side light textures, sampled with linear filtering as SHADER_ABI.md §6 binds them.
class LightTextureSet {
public:
    LightTextureSet();
    float falloff(float t) const;  // _LightTexture0 (POINT) / _LightTextureB0
    // The cookie a light names ("none"/"default": the default image, else a PNG file loaded by
    // loadCookieFiles), bilinear on its alpha: spot clamps to edge, directional repeats.
    float spotCookie(const glm::vec2& uv, const std::string& cookie = "default") const;
    float directionalCookie(const glm::vec2& uv, const std::string& cookie = "default") const;
    // Loads the PNG cookie of every light that names one (its alpha channel; the scene parser
    // allows them on spot and directional lights only). The file's error when unreadable.
    Status loadCookieFiles(const std::vector<scene::Light>& lights);
    // Face selected as Vulkan does, bilinear inside the face with clamp to edge (Vulkan filters
    // across faces; the default cookie is smooth across edges, so the difference is ≪ 1/255).
    float pointCookie(const glm::vec3& direction) const;
    // Mutation tests only: replaces falloff() by |f| (empty = the table).
    void setFalloffOverride(std::function<float(float)> f) { mFalloffOverride = std::move(f); }

private:
    std::function<float(float)> mFalloffOverride;
    std::vector<uint16_t> mFalloff;
    scene::CookieImage mSpot, mDirectional, mPoint;
    std::map<std::string, scene::CookieImage> mFiles;  // by path
};

// The per-pass light uniforms of SHADER_ABI.md §4.6 plus the variant's light keyword.
enum class LightKeyword { Directional, DirectionalCookie, Point, PointCookie, Spot };
struct PassLight {
    LightKeyword keyword = LightKeyword::Directional;
    glm::vec4 worldSpaceLightPos{0.0f, 1.0f, 0.0f, 0.0f};  // _WorldSpaceLightPos0
    glm::vec3 color{0.0f};                                 // _LightColor0.rgb
    glm::vec4 positionRange{0.0f};                         // _LightPositionRange
    glm::mat4 worldToLight{1.0f};                          // unity_WorldToLight (forward)
    std::string cookie = "none";                           // scene::Light::cookie
    // The light's shadow map when the pass samples one (SHADOWS_DEPTH), else null.
    const ShadowMapReference* shadowMap = nullptr;
    bool softShadows = false;                              // SHADOWS_SOFT
    // A directional light's screen-space mask when the pass reads one (SHADOWS_SCREEN), per
    // camera pixel, row-major; else null.
    const std::vector<ShadowInterval>* screenMask = nullptr;
    std::optional<ShadowFade> shadowFade;  // set where the pass fades shadows (UNITY_LIGHT_ATTENUATION)
};
// The pass light for |light| (ForwardAdd or the ForwardBase main light). Its PNG cookie, if any,
// is sampled through LightTextureSet::loadCookieFiles.
Result<PassLight> passLightFor(const scene::Light& light);
// ForwardBase without a directional light: _LightColor0 = 0 and a unit direction (0, 1, 0).
PassLight noPassLight();

// LIGHTING.md §3, forward (UNITY_LIGHT_ATTENUATION without shadows) at world position |p|.
float lightAttenuation(const PassLight& light, const LightTextureSet& textures, const glm::vec3& p);

}  // namespace varc::reference
