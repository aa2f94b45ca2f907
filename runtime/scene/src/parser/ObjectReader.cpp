// SPDX-License-Identifier: Apache-2.0
// The objects of a scene file: transform, mesh, material properties and lightmaps.
#include <cmath>
#include <filesystem>

#include "SceneReaders.h"

namespace varc::scene {

using nlohmann::json;

bool readTransform(JsonReader& r, const json& value, const std::string& pointer, Transform& out) {
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

namespace {

bool readProperty(JsonReader& r, const json& value, const std::string& p, PropertyValue& out) {
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
                         JsonReader::shortDump(value));
}

bool readMaterial(JsonReader& r, const json& value, const std::string& p, Material& m) {
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
            return r.fail(p + "/keywords", "expected an array of keyword names, got " +
                                               JsonReader::shortDump(keywords));
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
bool readVec4(JsonReader& r, const json& value, const std::string& p, glm::vec4& out) {
    if (!value.is_array() || value.size() != 4)
        return r.fail(p, "expected an array of 4 numbers, got " + JsonReader::shortDump(value));
    for (size_t i = 0; i < 4; ++i) {
        if (!r.readFloat(value[i], p + "/" + std::to_string(i), out[static_cast<int>(i)]))
            return false;
    }
    return true;
}

// A lightmap colour: [r, g, b] linear HDR, each component >= 0.
bool readLightmapColor(JsonReader& r, const json& value, const std::string& p, glm::vec3& out) {
    if (!value.is_array() || value.size() != 3)
        return r.fail(p, "expected a colour [r, g, b], got " + JsonReader::shortDump(value));
    glm::vec4 c(0.0f);
    if (!r.readColor(value, p, c)) return false;
    if (glm::any(glm::lessThan(glm::vec3(c), glm::vec3(0.0f))))
        return r.fail(p,
                      "expected components >= 0 (linear HDR), got " + JsonReader::shortDump(value));
    out = glm::vec3(c);
    return true;
}

// "directional": [x, y, z] or [x, y, z, w]: the dominant direction (any non-zero length) and
// the rebalancing factor w > 0 (default 1).
bool readLightmapDirection(JsonReader& r, const json& value, const std::string& p, glm::vec4& out) {
    if (!value.is_array() || value.size() < 3 || value.size() > 4)
        return r.fail(p, "expected [x, y, z] or [x, y, z, w], got " + JsonReader::shortDump(value));
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
bool readLightmapFile(JsonReader& r, const json& value, const std::string& p, std::string& file) {
    if (!value.is_string()) return true;
    std::string text = value.get<std::string>();
    if (!isTextureFile(text))
        return r.fail(p, "expected a PNG file (\"*.png\") or a value, got '" + text + "'");
    if (std::filesystem::path(text).is_relative())
        text = (std::filesystem::path(r.path()).parent_path() / text).lexically_normal().string();
    file = std::move(text);
    return true;
}

bool readLightmap(JsonReader& r, const json& value, const std::string& p, Lightmap& m) {
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
        return r.fail(p,
                      "a lightmap needs 'baked' (LIGHTMAP_ON), 'realtime' (DYNAMICLIGHTMAP_ON) "
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

}  // namespace

bool readObject(JsonReader& r, const json& value, const std::string& p, Object& o) {
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

}  // namespace varc::scene
