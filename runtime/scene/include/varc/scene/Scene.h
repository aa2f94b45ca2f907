// SPDX-License-Identifier: Apache-2.0
// Scene: the camera, objects, materials and lights of a validation scene (docs/SCENES.md), in
// Unity's conventions, and the JSON reader for it.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "varc/core/Result.h"

namespace varc::scene {

enum class MeshKind { Sphere, Cube, Plane };
enum class LightType { Directional, Point, Spot };
enum class LightRenderMode { Auto, Important, NotImportant };
enum class RenderPath { Forward, Deferred, SinglePass };
enum class ShadowType { None, Hard, Soft };
// Unity's Lighting window "Lighting Mode" for mixed lights, with the quality setting's Shadowmask
// Mode split in two (docs/SCENES.md "Lightmaps"): which shadow-mixing keywords objects get.
enum class MixedLightingMode { BakedIndirect, Subtractive, Shadowmask, DistanceShadowmask };

// Unity conventions: left-handed, y up, metres; local +z forward; Euler angles in degrees applied
// as Unity does (rotation = Ry(y) * Rx(x) * Rz(z), i.e. z first, then x, then y). The rotation
// matrices have the usual form (Ry(90°) maps +z to +x, Rx(90°) maps +z to -y, Rz(90°) maps +x
// to +y), which in a left-handed world are clockwise turns seen from the axis' positive end.
struct Transform {
    glm::vec3 position{0.0f};
    glm::vec3 rotationDegrees{0.0f};
    glm::vec3 scale{1.0f};
    glm::mat3 rotation() const;      // Ry(y) * Rx(x) * Rz(z)
    glm::mat4 localToWorld() const;  // T * R * S, column vectors (glm)
    glm::mat4 rigidToWorld() const;  // T * R (no scale): light and camera frames
};

struct Camera {
    glm::vec3 position{0.0f, 0.0f, -5.0f};
    glm::vec3 target{0.0f};
    float fovY = 60.0f;  // degrees, vertical
    float nearPlane = 0.1f, farPlane = 100.0f;
    uint32_t width = 256, height = 256;
    bool hdr = false;
    RenderPath path = RenderPath::Forward;
    glm::vec4 background{0.0f, 0.0f, 0.0f, 1.0f};  // linear clear colour
    // The deferred path's light shader ("deferred_shader"; pass 0 lights, pass 1 decodes LDR),
    // as Unity's Graphics settings choose it; "" = the renderer's own (varc/DeferredLight).
    std::string deferredShader;
};

// A material property: a float, a vector/colour, or a texture: a built-in name ("white",
// "black", "gray", "bump", "red") or a PNG file ("textures/wood.png", sRGB colour).
using PropertyValue = std::variant<float, glm::vec4, std::string>;

struct Material {
    std::string shader;                               // e.g. "Custom/My First Lighting Shader"
    std::map<std::string, PropertyValue> properties;  // "_Tint" -> vec4, "_Smoothness" -> 0.5
    // The CPU reference's lighting model for this material ("reference" in the scene file), e.g.
    // "seed004"; "" = the default for the shader (referenceModelOf).
    std::string reference;
    // The material's shader keywords ("keywords" in the scene file), e.g. "_ALPHATEST_ON": they
    // select shader_feature variants of the passes the object draws, as Unity's material
    // keywords do.
    std::vector<std::string> keywords;
};

// The reference model a material selects: its own `reference`, else the default for varc's
// library shaders and the seed-000 fixture ("varc/Forward" -> "varc-forward", ...), else "" (no
// reference model: the scene renders without a comparison).
std::string referenceModelOf(const Material& material);

// An object's lightmaps ("lightmap" in the scene file), SHADER_ABI.md §4.13, §6: each map a
// constant (linear HDR colours, bound as 1x1 float textures) or a PNG file (|*File|, a path
// resolved against the scene file; its values as stored, linear, bound UNORM; the constant is
// then unused). At least one of |baked| and |realtime| is set.
struct Lightmap {
    std::optional<glm::vec3> baked;      // LIGHTMAP_ON: unity_Lightmap
    std::optional<glm::vec3> realtime;   // DYNAMICLIGHTMAP_ON: unity_DynamicLightmap
    // DIRLIGHTMAP_COMBINED: the dominant direction (unit, world) and rebalancing factor w of
    // unity_LightmapInd / unity_DynamicDirectionality (stored as xyz * 0.5 + 0.5, w).
    std::optional<glm::vec4> directional;
    glm::vec4 shadowmask{1.0f};                    // unity_ShadowMask (per light channel)
    std::string bakedFile, realtimeFile, directionalFile, shadowmaskFile;  // "" = the constant
    glm::vec4 scaleOffset{1.0f, 1.0f, 0.0f, 0.0f};  // unity_LightmapST
    glm::vec4 realtimeScaleOffset{1.0f, 1.0f, 0.0f, 0.0f};  // unity_DynamicLightmapST
};

struct Object {
    std::string name;  // "" allowed
    MeshKind mesh = MeshKind::Sphere;
    Transform transform;
    Material material;
    std::optional<Lightmap> lightmap;  // none: a dynamic object
    // Unity's renderer "Light Probes" setting ("light_probes"); unset: on for objects without a
    // lightmap, off for lightmapped ones (usesLightProbes()).
    std::optional<bool> lightProbes;
    bool usesLightProbes() const { return lightProbes.value_or(!lightmap.has_value()); }
};

struct Light {
    LightType type = LightType::Directional;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    Transform transform;          // position and rotation used; light travels along local +z
    float range = 10.0f;          // point, spot
    float spotAngle = 30.0f;      // degrees, full cone angle
    // "none" | "default" (built-in patterns) | "white" (built-in, alpha 1 everywhere: 2D, or a
    // cube for point lights; not known to the CPU reference) | a PNG file (spot, directional;
    // alpha).
    std::string cookie = "none";
    float cookieSize = 10.0f;     // directional cookies: metres covered by one cookie tile
    LightRenderMode renderMode = LightRenderMode::Auto;
    // Real-time shadows (SHADER_ABI.md §4.7 turns these into the shaders' shadow uniforms).
    ShadowType shadows = ShadowType::None;
    float shadowStrength = 1.0f;     // 0..1; shadowed light is scaled by 1 - strength
    float shadowBias = 0.05f;        // depth bias, Unity's light inspector units
    float shadowNormalBias = 0.4f;   // normal offset, Unity's light inspector units
    float shadowNearPlane = 0.2f;    // metres; the shadow camera's near plane
    uint32_t shadowResolution = 512; // shadow map texels per side
    glm::vec3 finalColor() const { return color * intensity; }  // linear
    glm::vec3 forward() const;  // unit world direction the light travels (local +z)
    // Whether the light draws with a cookie. Spot lights always have one (the default disc when
    // |cookie| is "none", SHADER_ABI.md §6); directional and point lights when |cookie| != "none".
    bool hasCookie() const { return type == LightType::Spot || cookie != "none"; }
};

struct Scene {
    Camera camera;
    glm::vec3 ambient{0.0f};  // linear flat ambient colour
    int pixelLightCount = 4;  // quality.pixel_light_count
    float shadowDistance = 50.0f;  // quality.shadow_distance: shadows fade out towards it
    // Directional shadow cascades (quality.shadow_cascades 1, 2 or 4), the split distances as
    // fractions of shadowDistance (quality.shadow_cascade_splits: 1, or 3 increasing values),
    // and the fit (quality.shadow_projection "stable_fit": bounding spheres, Unity's default;
    // "close_fit": bounding boxes).
    int shadowCascades = 1;
    glm::vec3 cascadeSplits{0.067f, 0.2f, 0.467f};
    bool stableFit = true;
    // lighting.mixed_mode: how baked and realtime shadows mix (docs/SCENES.md "Lightmaps").
    MixedLightingMode mixedLighting = MixedLightingMode::BakedIndirect;
    std::vector<Object> objects;
    std::vector<Light> lights;
};

// What a scene may hold (docs/SECURITY.md): scene files come from anywhere, and each of these
// bounds the memory or time a render and its CPU reference can take.
inline constexpr size_t kMaxSceneFileBytes = 16u << 20;     // 16 MiB of JSON
inline constexpr int kMaxSceneNesting = 32;                 // [ and { levels
inline constexpr uint32_t kMaxImageSide = 16384;            // camera width, height
inline constexpr uint64_t kMaxImagePixels = 4096u * 4096u;  // camera width x height
inline constexpr size_t kMaxSceneObjects = 4096;
inline constexpr size_t kMaxSceneLights = 1024;
inline constexpr float kMinScale = 1e-6f;  // |scale| per axis: 0 makes normals NaN

// Parses the scene JSON format of docs/SCENES.md. Every field is optional (defaults as in the
// structs above) except each object's "mesh" and each light's "type"; unknown keys are errors.
// Besides the issue's keys: camera "background" [r,g,b(,a)], light "cookie_size", object
// "name". Colours are [r,g,b] or [r,g,b,a]; material properties are numbers, arrays of 1-4
// numbers (padded with 0, alpha 1 for 3) or texture strings (a relative PNG path is resolved
// against the scene file's folder). Every error message starts
// with "<path>: " and names the JSON pointer, e.g.
//   "scenes/a.json: /lights/2/type: expected one of directional, point, spot, got 'pointy'".
// Limits above are errors that name the limit. Never throws; errors are ErrorCode::InvalidInput.
// Example: parseScene(R"({"objects":[{"mesh":"sphere"}]})", "a.json") -> one default sphere.
Result<Scene> parseScene(std::string_view json, const std::string& path);

// Reads |path| and parses it with parseScene. ErrorCode::IoError when unreadable.
Result<Scene> loadScene(const std::string& path);

// Whether a texture property names a PNG file ("textures/wood.png") rather than a built-in
// texture ("white"). The parser makes such paths relative to the scene file's folder.
bool isTextureFile(std::string_view name);

const char* toString(MeshKind kind);
const char* toString(LightType type);

}  // namespace varc::scene
