// SPDX-License-Identifier: Apache-2.0
// ReferenceRenderer: renders a forward Scene on the CPU exactly as the GPU forward renderer should
// (docs/LIGHTING.md §9.2): same camera, meshes, rasterisation rules, light assignment and per-pixel
// lighting (docs/LIGHTING.md §8, §9), with the colour attachment's quantisation. No Vulkan.
#pragma once

#include <functional>
#include <string>

#include "varc/core/Result.h"
#include "varc/image/Image.h"
#include "varc/reference/LinearTexture.h"
#include "varc/reference/Rasterizer.h"
#include "varc/reference/ShadowReference.h"
#include "varc/scene/ForwardLights.h"
#include "varc/scene/Scene.h"

namespace varc::reference {

// The shaders the reference knows and how it reads their material properties.
enum class ShaderModel {
    ForwardPbs,      // "Custom/My First Lighting Shader" (_Tint) and "varc/Forward" (_Color)
    SimpleDiffuse,   // "varc/SimpleDiffuse"
    GlslBlinnPhong,  // "varc/GlslVertexLights"
    Seed001Phong,    // seed 001 as written: per-pixel Phong, 1/d point lights, 4 vertex lights
    Seed004Diffuse,  // seed 004 as written: object-space Lambert, ambient x2 and light x2
    // varc's built-in fallbacks used directly ("Legacy Shaders/VertexLit", "Standard", the
    // Transparent/Cutout family): a ShadowCaster pass only, nothing drawn in the camera.
    CasterOnly,
};
struct MaterialParams {
    ShaderModel model = ShaderModel::ForwardPbs;
    glm::vec4 color{1.0f};    // _Tint or _Color
    glm::vec4 mainTex{1.0f};  // the constant value of _MainTex ("white" or "black")
    std::shared_ptr<const LinearTexture> mainTexture;  // _MainTex as a PNG file, else null
    glm::vec4 mainTexST{1.0f, 1.0f, 0.0f, 0.0f};       // _MainTex_ST (tiling xy, offset zw)
    float metallic = 0.0f;      // _Metallic, as given (no [Gamma] conversion)
    float smoothness = 0.5f;    // _Smoothness
    glm::vec3 specColor{1.0f};  // _SpecColor (GLSL)
    float shininess = 32.0f;    // _Shininess (GLSL)
    // Whether the shader draws a ShadowCaster pass (varc/Forward, varc/SimpleDiffuse: their
    // Fallback's) and whether its ForwardAdd pass samples spot shadow maps
    // (multi_compile_fwdadd_fullshadows).
    bool castsShadows = false;
    bool receivesAddShadows = false;
    bool receivesBaseShadows = false;  // the main directional light's (SHADOWS_SCREEN) in ForwardBase
    // The caster pass's Cull Off and alpha test against _Cutoff (ShadowCaster), and the
    // property the test reads (the shader's default 0.5 unless the material sets it).
    bool casterCullOff = false;
    bool casterAlphaTest = false;
    float cutoff = 0.5f;
    // Standard's alpha-blended caster (_ALPHABLEND_ON, _ALPHAPREMULTIPLY_ON): dithered
    // coverage of alpha * casterAlphaScale + casterAlphaBias (ShadowCaster).
    bool casterDither = false;
    float casterAlphaScale = 1.0f, casterAlphaBias = 0.0f;
};
// The parameters of |material| for its reference model (scene::referenceModelOf: "seed000",
// "varc-forward", "varc-simple-diffuse", "varc-glsl-vertex-lights", "seed001", "seed004",
// "varc-caster", "varc-caster-cutout" and "varc-standard-caster" (material keywords
// _ALPHATEST_ON, _ALPHABLEND_ON, _ALPHAPREMULTIPLY_ON) for the fallbacks that only cast) with
// that shader's Properties defaults. _MainTex may be "white", "black" or a PNG file (loaded
// here). NotFound when the material names no model the forward reference knows (the scene can
// still be rendered, without a comparison); Unsupported for other texture names; InvalidInput
// for a property of the wrong kind; IoError/InvalidInput for an unreadable PNG.
Result<MaterialParams> resolveMaterial(const scene::Material& material);

struct ReferenceOptions {
    // Base-pass LIGHTPROBE_SH for shaders with that keyword (SimpleDiffuse, GlslVertexLights):
    // on = max(0, ShadeSH9) ambient, off = the flat UNITY_LIGHTMODEL_AMBIENT. Each object's
    // own setting decides (scene::ObjectLightmaps: on unless lightmapped or "light_probes":
    // false); false turns it off for every object.
    bool lightProbeSh = true;
    // Mutation hooks for the comparator's tests: replace the falloff lookup, or edit the light
    // assignment after assignForwardLights. Leave empty for real references.
    std::function<float(float t)> falloffOverride;
    std::function<void(scene::ForwardLightAssignment&)> editAssignment;
    // Mutation: forward receivers ignore the shadow-distance fade.
    bool ignoreShadowFade = false;
    // Mutation: alpha-tested casters ignore _Cutoff (cast as if opaque).
    bool ignoreCasterCutoff = false;
    // Edits each CPU shadow map after it is rasterised (e.g. ShadowMapReference's mutations).
    std::function<void(ShadowMapReference&)> editShadowMap;
};

struct ReferenceImage {
    image::Image color;  // RgbaFloat, linear; LDR values are multiples of 1/255
    // The upper bound of each pixel where a shadow tap could go either way (color is then the
    // lower bound); equal to color elsewhere. Empty when the scene has no shadow maps.
    image::Image colorHigh;
    Classification classes;
    VisibilityBuffer visibility;
};

// Renders |scene| (camera.path must be Forward): background = camera.background; per object the
// base pass (main directional light, vertex lights, SH) and one additive pass per add light;
// objects whose shader only casts (ShaderModel::CasterOnly) draw into the shadow maps only.
// LDR (camera.hdr = false) models an RGBA8_UNORM attachment: each pass's output is clamped to
// [0, 1] and rounded to 8 bits, blended One One with saturation. HDR models
// R16G16B16A16_SFLOAT: each pass output and each sum is rounded to half precision.
// Errors: Unsupported for another path, shader, or a cookie that is not "none"/"default".
Result<ReferenceImage> renderReference(const scene::Scene& scene,
                                       const ReferenceOptions& options = {});

}  // namespace varc::reference
