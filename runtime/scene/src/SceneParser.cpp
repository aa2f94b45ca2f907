// SPDX-License-Identifier: Apache-2.0
// SceneParser: the scene JSON format of docs/SCENES.md → Scene, with JSON-pointer error messages.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <tuple>
#include <nlohmann/json.hpp>
#include <utility>

#include "varc/core/FileRead.h"
#include "varc/scene/Scene.h"

namespace varc::scene {
namespace {

using nlohmann::json;

// Collects the first error; every read* returns false after reporting it.
class Reader {
public:
    explicit Reader(std::string path) : mPath(std::move(path)) {}

    bool fail(const std::string& pointer, const std::string& message) {
        if (mError.empty())
            mError = mPath + ": " + (pointer.empty() ? "/" : pointer) + ": " + message;
        return false;
    }
    const std::string& error() const { return mError; }
    const std::string& path() const { return mPath; }

    // Fails when |value| (an object) has a key outside |allowed|.
    bool onlyKeys(const json& value, const std::string& pointer,
                  std::initializer_list<const char*> allowed) {
        if (!value.is_object()) return fail(pointer, "expected an object, got " + typeName(value));
        for (const auto& [key, unused] : value.items()) {
            bool known = false;
            for (const char* name : allowed) known = known || key == name;
            if (!known) {
                std::string list;
                for (const char* name : allowed)
                    list += (list.empty() ? "" : ", ") + std::string(name);
                return fail(pointer + "/" + key, "unknown key (expected one of " + list + ")");
            }
        }
        return true;
    }

    bool readFloat(const json& value, const std::string& pointer, float& out) {
        if (!value.is_number()) return fail(pointer, "expected a number, got " + typeName(value));
        const double d = value.get<double>();
        if (!std::isfinite(d)) return fail(pointer, "expected a finite number");
        out = static_cast<float>(d);
        return true;
    }

    bool readPositive(const json& value, const std::string& pointer, float& out) {
        if (!readFloat(value, pointer, out)) return false;
        if (!(out > 0.0f)) return fail(pointer, "expected a number > 0, got " + shortDump(value));
        return true;
    }

    bool readVec3(const json& value, const std::string& pointer, glm::vec3& out) {
        if (!value.is_array() || value.size() != 3) {
            return fail(pointer, "expected an array of 3 numbers, got " + shortDump(value));
        }
        for (size_t i = 0; i < 3; ++i) {
            if (!readFloat(value[i], pointer + "/" + std::to_string(i), out[static_cast<int>(i)])) {
                return false;
            }
        }
        return true;
    }

    // [r, g, b] (alpha 1) or [r, g, b, a].
    bool readColor(const json& value, const std::string& pointer, glm::vec4& out) {
        if (!value.is_array() || value.size() < 3 || value.size() > 4) {
            return fail(pointer,
                        "expected a colour [r, g, b] or [r, g, b, a], got " + shortDump(value));
        }
        out = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        for (size_t i = 0; i < value.size(); ++i) {
            if (!readFloat(value[i], pointer + "/" + std::to_string(i), out[static_cast<int>(i)])) {
                return false;
            }
        }
        return true;
    }

    bool readBool(const json& value, const std::string& pointer, bool& out) {
        if (!value.is_boolean())
            return fail(pointer, "expected true or false, got " + shortDump(value));
        out = value.get<bool>();
        return true;
    }

    bool readString(const json& value, const std::string& pointer, std::string& out) {
        if (!value.is_string()) return fail(pointer, "expected a string, got " + typeName(value));
        out = value.get<std::string>();
        return true;
    }

    // A non-negative integer in [lo, hi].
    bool readInt(const json& value, const std::string& pointer, int64_t lo, int64_t hi,
                 int64_t& out) {
        if (!value.is_number_integer()) {
            return fail(pointer, "expected an integer, got " + shortDump(value));
        }
        out = value.get<int64_t>();
        if (out < lo || out > hi) {
            return fail(pointer, "expected an integer in [" + std::to_string(lo) + ", " +
                                     std::to_string(hi) + "], got " + shortDump(value));
        }
        return true;
    }

    // One of |names| (mapped to the matching entry of |values|).
    template <typename E>
    bool readEnum(const json& value, const std::string& pointer,
                  std::initializer_list<std::pair<const char*, E>> options, E& out) {
        std::string list;
        for (const auto& option : options)
            list += (list.empty() ? "" : ", ") + std::string(option.first);
        if (!value.is_string()) {
            return fail(pointer, "expected one of " + list + ", got " + shortDump(value));
        }
        const std::string text = value.get<std::string>();
        for (const auto& option : options) {
            if (text == option.first) {
                out = option.second;
                return true;
            }
        }
        return fail(pointer, "expected one of " + list + ", got '" + text + "'");
    }

    static std::string typeName(const json& value) { return value.type_name(); }

    // |value| as JSON for a message, cut to 60 characters ("..." marks the cut).
    static std::string shortDump(const json& value) {
        std::string text = value.dump();
        return text.size() <= 60 ? text : text.substr(0, 57) + "...";
    }

private:
    std::string mPath;
    std::string mError;
};

bool readTransform(Reader& r, const json& value, const std::string& pointer, Transform& out) {
    if (value.contains("position") &&
        !r.readVec3(value["position"], pointer + "/position", out.position)) {
        return false;
    }
    if (value.contains("rotation") &&
        !r.readVec3(value["rotation"], pointer + "/rotation", out.rotationDegrees)) {
        return false;
    }
    if (value.contains("scale") && !r.readVec3(value["scale"], pointer + "/scale", out.scale)) {
        return false;
    }
    for (int axis = 0; axis < 3; ++axis) {
        if (!(std::abs(out.scale[axis]) >= kMinScale)) {
            return r.fail(pointer + "/scale/" + std::to_string(axis),
                          "expected a scale of at least 1e-06 in magnitude (0 flattens the "
                          "object and makes its normals undefined)");
        }
    }
    return true;
}

bool readCamera(Reader& r, const json& value, const std::string& p, Camera& c) {
    if (!r.onlyKeys(value, p,
                    {"position", "target", "fov_y", "near", "far", "width", "height", "hdr", "path",
                     "background", "deferred_shader"})) {
        return false;
    }
    if (value.contains("position") && !r.readVec3(value["position"], p + "/position", c.position))
        return false;
    if (value.contains("target") && !r.readVec3(value["target"], p + "/target", c.target))
        return false;
    if (value.contains("fov_y")) {
        if (!r.readPositive(value["fov_y"], p + "/fov_y", c.fovY)) return false;
        if (c.fovY >= 180.0f) return r.fail(p + "/fov_y", "expected a number < 180");
    }
    if (value.contains("near") && !r.readPositive(value["near"], p + "/near", c.nearPlane))
        return false;
    if (value.contains("far") && !r.readPositive(value["far"], p + "/far", c.farPlane))
        return false;
    if (c.farPlane <= c.nearPlane) return r.fail(p + "/far", "expected far > near");
    int64_t size = 0;
    if (value.contains("width")) {
        if (!r.readInt(value["width"], p + "/width", 1, kMaxImageSide, size)) return false;
        c.width = static_cast<uint32_t>(size);
    }
    if (value.contains("height")) {
        if (!r.readInt(value["height"], p + "/height", 1, kMaxImageSide, size)) return false;
        c.height = static_cast<uint32_t>(size);
    }
    if (uint64_t{c.width} * c.height > kMaxImagePixels) {
        return r.fail(p, "the image has " + std::to_string(uint64_t{c.width} * c.height) +
                             " pixels; at most " + std::to_string(kMaxImagePixels) +
                             " (4096 x 4096) are allowed");
    }
    if (value.contains("hdr") && !r.readBool(value["hdr"], p + "/hdr", c.hdr)) return false;
    if (value.contains("path") && !r.readEnum<RenderPath>(value["path"], p + "/path",
                                                          {{"forward", RenderPath::Forward},
                                                           {"deferred", RenderPath::Deferred},
                                                           {"single_pass", RenderPath::SinglePass}},
                                                          c.path)) {
        return false;
    }
    if (value.contains("background") &&
        !r.readColor(value["background"], p + "/background", c.background)) {
        return false;
    }
    if (value.contains("deferred_shader") &&
        !r.readString(value["deferred_shader"], p + "/deferred_shader", c.deferredShader)) {
        return false;
    }
    if (glm::length(c.target - c.position) == 0.0f) {
        return r.fail(p + "/target", "the camera target equals its position");
    }
    return true;
}

bool readProperty(Reader& r, const json& value, const std::string& p, PropertyValue& out) {
    if (value.is_number()) {
        float f = 0.0f;
        if (!r.readFloat(value, p, f)) return false;
        out = f;
        return true;
    }
    if (value.is_string()) {
        std::string text = value.get<std::string>();
        // A texture file is named relative to the scene file; keep it usable from anywhere.
        if (isTextureFile(text) && std::filesystem::path(text).is_relative()) {
            text =
                (std::filesystem::path(r.path()).parent_path() / text).lexically_normal().string();
        }
        out = std::move(text);
        return true;
    }
    if (value.is_array() && !value.empty() && value.size() <= 4) {
        glm::vec4 v(0.0f);
        if (value.size() == 3) v.w = 1.0f;
        for (size_t i = 0; i < value.size(); ++i) {
            if (!r.readFloat(value[i], p + "/" + std::to_string(i), v[static_cast<int>(i)]))
                return false;
        }
        out = v;
        return true;
    }
    return r.fail(p, "expected a number, an array of 1 to 4 numbers or a texture name, got " +
                         Reader::shortDump(value));
}

bool readMaterial(Reader& r, const json& value, const std::string& p, Material& m) {
    if (!r.onlyKeys(value, p, {"shader", "properties", "reference", "keywords"})) return false;
    if (value.contains("shader") && !r.readString(value["shader"], p + "/shader", m.shader))
        return false;
    if (value.contains("reference") &&
        !r.readString(value["reference"], p + "/reference", m.reference)) {
        return false;
    }
    if (value.contains("keywords")) {
        const json& keywords = value["keywords"];
        if (!keywords.is_array()) {
            return r.fail(p + "/keywords",
                          "expected an array of keyword names, got " + Reader::shortDump(keywords));
        }
        for (size_t i = 0; i < keywords.size(); ++i) {
            std::string keyword;
            if (!r.readString(keywords[i], p + "/keywords/" + std::to_string(i), keyword))
                return false;
            m.keywords.push_back(std::move(keyword));
        }
    }
    if (!value.contains("properties")) return true;
    const json& props = value["properties"];
    if (!props.is_object()) return r.fail(p + "/properties", "expected an object");
    for (const auto& [name, prop] : props.items()) {
        PropertyValue v;
        if (!readProperty(r, prop, p + "/properties/" + name, v)) return false;
        m.properties[name] = std::move(v);
    }
    return true;
}

// An array of exactly 4 numbers (a scale/offset).
bool readVec4(Reader& r, const json& value, const std::string& p, glm::vec4& out) {
    if (!value.is_array() || value.size() != 4)
        return r.fail(p, "expected an array of 4 numbers, got " + Reader::shortDump(value));
    for (size_t i = 0; i < 4; ++i) {
        if (!r.readFloat(value[i], p + "/" + std::to_string(i), out[static_cast<int>(i)]))
            return false;
    }
    return true;
}

// A lightmap colour: [r, g, b] linear HDR, each component >= 0.
bool readLightmapColor(Reader& r, const json& value, const std::string& p, glm::vec3& out) {
    if (!value.is_array() || value.size() != 3)
        return r.fail(p, "expected a colour [r, g, b], got " + Reader::shortDump(value));
    glm::vec4 c(0.0f);
    if (!r.readColor(value, p, c)) return false;
    if (glm::any(glm::lessThan(glm::vec3(c), glm::vec3(0.0f))))
        return r.fail(p, "expected components >= 0 (linear HDR), got " + Reader::shortDump(value));
    out = glm::vec3(c);
    return true;
}

// "directional": [x, y, z] or [x, y, z, w]: the dominant direction (any non-zero length) and
// the rebalancing factor w > 0 (default 1).
bool readLightmapDirection(Reader& r, const json& value, const std::string& p, glm::vec4& out) {
    if (!value.is_array() || value.size() < 3 || value.size() > 4)
        return r.fail(p, "expected [x, y, z] or [x, y, z, w], got " + Reader::shortDump(value));
    glm::vec4 d(0.0f, 0.0f, 0.0f, 1.0f);
    for (size_t i = 0; i < value.size(); ++i) {
        if (!r.readFloat(value[i], p + "/" + std::to_string(i), d[static_cast<int>(i)]))
            return false;
    }
    if (!(glm::length(glm::vec3(d)) > 1e-6f))
        return r.fail(p, "expected a direction of non-zero length");
    if (!(d.w > 0.0f)) return r.fail(p + "/3", "expected a rebalancing factor > 0");
    out = glm::vec4(glm::normalize(glm::vec3(d)), d.w);
    return true;
}

// A lightmap given as a PNG file: a string |value| must end in ".png" (|file| set to it,
// resolved against the scene file; else an error). Any other |value| leaves |file| empty.
bool readLightmapFile(Reader& r, const json& value, const std::string& p, std::string& file) {
    if (!value.is_string()) return true;
    std::string text = value.get<std::string>();
    if (!isTextureFile(text))
        return r.fail(p, "expected a PNG file (\"*.png\") or a value, got '" + text + "'");
    if (std::filesystem::path(text).is_relative())
        text = (std::filesystem::path(r.path()).parent_path() / text).lexically_normal().string();
    file = std::move(text);
    return true;
}

bool readLightmap(Reader& r, const json& value, const std::string& p, Lightmap& m) {
    if (!r.onlyKeys(value, p,
                    {"baked", "realtime", "directional", "shadowmask", "scale_offset",
                     "realtime_scale_offset"})) {
        return false;
    }
    for (auto [key, slot, file] : {std::tuple{"baked", &m.baked, &m.bakedFile},
                                   std::tuple{"realtime", &m.realtime, &m.realtimeFile}}) {
        if (!value.contains(key)) continue;
        if (!readLightmapFile(r, value[key], p + "/" + key, *file)) return false;
        glm::vec3 c(1.0f);
        if (file->empty() && !readLightmapColor(r, value[key], p + "/" + key, c)) return false;
        *slot = c;
    }
    if (!m.baked && !m.realtime)
        return r.fail(p, "a lightmap needs 'baked' (LIGHTMAP_ON), 'realtime' (DYNAMICLIGHTMAP_ON) "
                         "or both");
    if (value.contains("directional")) {
        if (!readLightmapFile(r, value["directional"], p + "/directional", m.directionalFile))
            return false;
        glm::vec4 d(0.0f, 0.0f, 1.0f, 1.0f);
        if (m.directionalFile.empty() &&
            !readLightmapDirection(r, value["directional"], p + "/directional", d)) {
            return false;
        }
        m.directional = d;
    }
    if (value.contains("shadowmask")) {
        if (!readLightmapFile(r, value["shadowmask"], p + "/shadowmask", m.shadowmaskFile))
            return false;
    }
    if (value.contains("shadowmask") && m.shadowmaskFile.empty()) {
        if (!r.readColor(value["shadowmask"], p + "/shadowmask", m.shadowmask)) return false;
        if (glm::any(glm::lessThan(m.shadowmask, glm::vec4(0.0f))) ||
            glm::any(glm::greaterThan(m.shadowmask, glm::vec4(1.0f)))) {
            return r.fail(p + "/shadowmask", "expected components in [0, 1] (baked occlusion)");
        }
    }
    if (value.contains("scale_offset") &&
        !readVec4(r, value["scale_offset"], p + "/scale_offset", m.scaleOffset)) {
        return false;
    }
    return !value.contains("realtime_scale_offset") ||
           readVec4(r, value["realtime_scale_offset"], p + "/realtime_scale_offset",
                    m.realtimeScaleOffset);
}

bool readObject(Reader& r, const json& value, const std::string& p, Object& o) {
    if (!r.onlyKeys(value, p,
                    {"name", "mesh", "position", "rotation", "scale", "material", "lightmap",
                     "light_probes"})) {
        return false;
    }
    if (value.contains("lightmap")) {
        Lightmap lightmap;
        if (!readLightmap(r, value["lightmap"], p + "/lightmap", lightmap)) return false;
        o.lightmap = lightmap;
    }
    if (value.contains("light_probes")) {
        bool probes = false;
        if (!r.readBool(value["light_probes"], p + "/light_probes", probes)) return false;
        o.lightProbes = probes;
    }
    if (value.contains("name") && !r.readString(value["name"], p + "/name", o.name)) return false;
    if (!value.contains("mesh")) return r.fail(p, "missing key 'mesh'");
    if (!r.readEnum<MeshKind>(
            value["mesh"], p + "/mesh",
            {{"sphere", MeshKind::Sphere}, {"cube", MeshKind::Cube}, {"plane", MeshKind::Plane}},
            o.mesh)) {
        return false;
    }
    if (!readTransform(r, value, p, o.transform)) return false;
    return !value.contains("material") ||
           readMaterial(r, value["material"], p + "/material", o.material);
}

// "shadows": "none" | "hard" | "soft" and the shadow settings of a light.
bool readLightShadows(Reader& r, const json& value, const std::string& p, Light& l) {
    if (value.contains("shadows") &&
        !r.readEnum<ShadowType>(value["shadows"], p + "/shadows",
                                {{"none", ShadowType::None},
                                 {"hard", ShadowType::Hard},
                                 {"soft", ShadowType::Soft}},
                                l.shadows)) {
        return false;
    }
    if (value.contains("shadow_strength")) {
        if (!r.readFloat(value["shadow_strength"], p + "/shadow_strength", l.shadowStrength))
            return false;
        if (l.shadowStrength < 0.0f || l.shadowStrength > 1.0f)
            return r.fail(p + "/shadow_strength", "expected a number in [0, 1]");
    }
    for (auto [key, out] : {std::pair{"shadow_bias", &l.shadowBias},
                            std::pair{"shadow_normal_bias", &l.shadowNormalBias}}) {
        if (!value.contains(key)) continue;
        if (!r.readFloat(value[key], p + "/" + key, *out)) return false;
        if (*out < 0.0f || *out > 10.0f) return r.fail(p + "/" + key, "expected a number in [0, 10]");
    }
    if (value.contains("shadow_near_plane") &&
        !r.readPositive(value["shadow_near_plane"], p + "/shadow_near_plane", l.shadowNearPlane)) {
        return false;
    }
    if (value.contains("shadow_resolution")) {
        int64_t texels = 0;
        if (!r.readInt(value["shadow_resolution"], p + "/shadow_resolution", 16, 4096, texels))
            return false;
        l.shadowResolution = static_cast<uint32_t>(texels);
    }
    return true;
}

bool readLight(Reader& r, const json& value, const std::string& p, Light& l) {
    if (!r.onlyKeys(value, p,
                    {"type", "color", "intensity", "position", "rotation", "range", "spot_angle",
                     "cookie", "cookie_size", "render_mode", "shadows", "shadow_strength",
                     "shadow_bias", "shadow_normal_bias", "shadow_near_plane",
                     "shadow_resolution"})) {
        return false;
    }
    if (!value.contains("type")) return r.fail(p, "missing key 'type'");
    if (!r.readEnum<LightType>(value["type"], p + "/type",
                               {{"directional", LightType::Directional},
                                {"point", LightType::Point},
                                {"spot", LightType::Spot}},
                               l.type)) {
        return false;
    }
    if (value.contains("color")) {
        glm::vec4 c;
        if (!r.readColor(value["color"], p + "/color", c)) return false;
        l.color = glm::vec3(c);
    }
    if (value.contains("intensity")) {
        if (!r.readFloat(value["intensity"], p + "/intensity", l.intensity)) return false;
        if (l.intensity < 0.0f) return r.fail(p + "/intensity", "expected a number >= 0");
    }
    if (!readTransform(r, value, p, l.transform)) return false;
    if (value.contains("range") && !r.readPositive(value["range"], p + "/range", l.range))
        return false;
    if (value.contains("spot_angle")) {
        if (!r.readPositive(value["spot_angle"], p + "/spot_angle", l.spotAngle)) return false;
        if (l.spotAngle >= 180.0f) return r.fail(p + "/spot_angle", "expected a number < 180");
    }
    if (value.contains("cookie") && !r.readString(value["cookie"], p + "/cookie", l.cookie))
        return false;
    if (isTextureFile(l.cookie) && l.type == LightType::Point) {
        return r.fail(p + "/cookie",
                      "a point light's cookie is a cube map; PNG cookies are for spot and "
                      "directional lights");
    }
    if (isTextureFile(l.cookie) && std::filesystem::path(l.cookie).is_relative()) {
        l.cookie =
            (std::filesystem::path(r.path()).parent_path() / l.cookie).lexically_normal().string();
    }
    if (value.contains("cookie_size") &&
        !r.readPositive(value["cookie_size"], p + "/cookie_size", l.cookieSize)) {
        return false;
    }
    if (value.contains("render_mode") &&
        !r.readEnum<LightRenderMode>(value["render_mode"], p + "/render_mode",
                                     {{"auto", LightRenderMode::Auto},
                                      {"important", LightRenderMode::Important},
                                      {"not_important", LightRenderMode::NotImportant}},
                                     l.renderMode)) {
        return false;
    }
    return readLightShadows(r, value, p, l);
}

// quality.shadow_cascades (1, 2, 4), shadow_cascade_splits (fractions of the shadow distance,
// increasing, in (0, 1): one for two cascades, three for four) and shadow_projection.
bool readCascades(Reader& r, const json& q, Scene& scene) {
    if (q.contains("shadow_cascades")) {
        int64_t count = 0;
        if (!r.readInt(q["shadow_cascades"], "/quality/shadow_cascades", 1, 4, count)) return false;
        if (count == 3) return r.fail("/quality/shadow_cascades", "expected 1, 2 or 4");
        scene.shadowCascades = static_cast<int>(count);
        if (count == 2) scene.cascadeSplits = glm::vec3(0.333f, 1.0f, 1.0f);
    }
    if (q.contains("shadow_cascade_splits")) {
        const json& splits = q["shadow_cascade_splits"];
        const size_t wanted = scene.shadowCascades == 4 ? 3 : scene.shadowCascades == 2 ? 1 : 0;
        if (!splits.is_array() || splits.size() != wanted) {
            return r.fail("/quality/shadow_cascade_splits",
                          "expected " + std::to_string(wanted) + " fractions for " +
                              std::to_string(scene.shadowCascades) + " cascades");
        }
        float previous = 0.0f;
        for (size_t i = 0; i < wanted; ++i) {
            const std::string pointer = "/quality/shadow_cascade_splits/" + std::to_string(i);
            float value = 0.0f;
            if (!r.readFloat(splits[i], pointer, value)) return false;
            if (value <= previous || value >= 1.0f)
                return r.fail(pointer, "expected increasing fractions in (0, 1)");
            scene.cascadeSplits[static_cast<glm::length_t>(i)] = value;
            previous = value;
        }
    }
    if (q.contains("shadow_projection")) {
        std::string fit;
        if (!r.readString(q["shadow_projection"], "/quality/shadow_projection", fit)) return false;
        if (fit != "stable_fit" && fit != "close_fit")
            return r.fail("/quality/shadow_projection", "expected \"stable_fit\" or \"close_fit\"");
        scene.stableFit = fit == "stable_fit";
    }
    return true;
}

bool readScene(Reader& r, const json& root, Scene& scene) {
    if (!r.onlyKeys(root, "", {"camera", "ambient", "quality", "lighting", "objects", "lights"}))
        return false;
    if (root.contains("lighting")) {
        const json& l = root["lighting"];
        if (!r.onlyKeys(l, "/lighting", {"mixed_mode"})) return false;
        if (l.contains("mixed_mode") &&
            !r.readEnum<MixedLightingMode>(
                l["mixed_mode"], "/lighting/mixed_mode",
                {{"baked_indirect", MixedLightingMode::BakedIndirect},
                 {"subtractive", MixedLightingMode::Subtractive},
                 {"shadowmask", MixedLightingMode::Shadowmask},
                 {"distance_shadowmask", MixedLightingMode::DistanceShadowmask}},
                scene.mixedLighting)) {
            return false;
        }
    }
    if (root.contains("camera") && !readCamera(r, root["camera"], "/camera", scene.camera))
        return false;
    if (root.contains("ambient")) {
        const json& a = root["ambient"];
        if (!r.onlyKeys(a, "/ambient", {"color"})) return false;
        glm::vec4 c;
        if (a.contains("color")) {
            if (!r.readColor(a["color"], "/ambient/color", c)) return false;
            scene.ambient = glm::vec3(c);
        }
    }
    if (root.contains("quality")) {
        const json& q = root["quality"];
        if (!r.onlyKeys(q, "/quality",
                        {"pixel_light_count", "shadow_distance", "shadow_cascades",
                         "shadow_cascade_splits", "shadow_projection"})) {
            return false;
        }
        if (!readCascades(r, q, scene)) return false;
        if (q.contains("shadow_distance") &&
            !r.readPositive(q["shadow_distance"], "/quality/shadow_distance", scene.shadowDistance)) {
            return false;
        }
        int64_t count = 0;
        if (q.contains("pixel_light_count")) {
            if (!r.readInt(q["pixel_light_count"], "/quality/pixel_light_count", 0, 64, count))
                return false;
            scene.pixelLightCount = static_cast<int>(count);
        }
    }
    for (auto [key, limit] :
         {std::pair{"objects", kMaxSceneObjects}, std::pair{"lights", kMaxSceneLights}}) {
        if (!root.contains(key)) continue;
        if (!root[key].is_array()) return r.fail(std::string("/") + key, "expected an array");
        if (root[key].size() > limit) {
            return r.fail(std::string("/") + key, std::to_string(root[key].size()) +
                                                      " entries; at most " + std::to_string(limit) +
                                                      " are allowed");
        }
    }
    if (root.contains("objects")) {
        for (size_t i = 0; i < root["objects"].size(); ++i) {
            Object o;
            if (!readObject(r, root["objects"][i], "/objects/" + std::to_string(i), o))
                return false;
            scene.objects.push_back(std::move(o));
        }
    }
    if (root.contains("lights")) {
        for (size_t i = 0; i < root["lights"].size(); ++i) {
            Light l;
            if (!readLight(r, root["lights"][i], "/lights/" + std::to_string(i), l)) return false;
            scene.lights.push_back(std::move(l));
        }
    }
    return true;
}

// The deepest [ / { nesting of |text| outside strings. JSON values are printed recursively in
// error messages, so depth is bounded before anything is parsed.
int nestingDepth(std::string_view text) {
    int depth = 0, deepest = 0;
    bool inString = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return deepest;
}

}  // namespace

Result<Scene> parseScene(std::string_view text, const std::string& path) {
    if (text.size() > kMaxSceneFileBytes) {
        return makeError(ErrorCode::InvalidInput,
                         path + ": /: the file has " + std::to_string(text.size()) +
                             " bytes; at most " + std::to_string(kMaxSceneFileBytes) +
                             " are allowed");
    }
    if (int depth = nestingDepth(text); depth > kMaxSceneNesting) {
        return makeError(ErrorCode::InvalidInput,
                         path + ": /: nested " + std::to_string(depth) + " levels deep; at most " +
                             std::to_string(kMaxSceneNesting) + " are allowed");
    }
    json root;
    try {
        root = json::parse(text.begin(), text.end());
    } catch (const json::exception& e) {
        // The parser quotes the token it stopped at, which can be the rest of the file.
        std::string reason = e.what();
        if (reason.size() > 200) reason = reason.substr(0, 197) + "...";
        return makeError(ErrorCode::InvalidInput, path + ": /: invalid JSON: " + reason);
    }
    Reader reader(path);
    Scene scene;
    if (!readScene(reader, root, scene)) return makeError(ErrorCode::InvalidInput, reader.error());
    return scene;
}

Result<Scene> loadScene(const std::string& path) {
    // One byte past the limit is read, so parseScene names the limit.
    Result<std::string> text = readFile(path, kMaxSceneFileBytes + 1);
    if (!text) {
        return makeError(ErrorCode::IoError,
                         path + ": cannot read the scene file (" + text.error().detail + ")");
    }
    return parseScene(*text, path);
}

bool isTextureFile(std::string_view name) {
    return name.size() > 4 && name.substr(name.size() - 4) == ".png";
}

}  // namespace varc::scene
