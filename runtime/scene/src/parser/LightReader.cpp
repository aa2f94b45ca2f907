// SPDX-License-Identifier: Apache-2.0
// The lights of a scene file and the shadow cascade settings.
#include "SceneReaders.h"

namespace varc::scene {

using nlohmann::json;

namespace {

// "shadows": "none" | "hard" | "soft" and the shadow settings of a light.
bool readLightShadows(JsonReader& r, const json& value, const std::string& p, Light& l) {
    if (value.contains("shadows") &&
        !r.readEnum<ShadowType>(
            value["shadows"], p + "/shadows",
            {{"none", ShadowType::None}, {"hard", ShadowType::Hard}, {"soft", ShadowType::Soft}},
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
        if (*out < 0.0f || *out > 10.0f)
            return r.fail(p + "/" + key, "expected a number in [0, 10]");
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

}  // namespace

bool readLight(JsonReader& r, const json& value, const std::string& p, Light& l) {
    if (!r.onlyKeys(
            value, p,
            {"type", "color", "intensity", "position", "rotation", "range", "spot_angle", "cookie",
             "cookie_size", "render_mode", "shadows", "shadow_strength", "shadow_bias",
             "shadow_normal_bias", "shadow_near_plane", "shadow_resolution"})) {
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
bool readCascades(JsonReader& r, const json& q, Scene& scene) {
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

}  // namespace varc::scene
