// SPDX-License-Identifier: Apache-2.0
// SceneParser: the scene JSON format of docs/SCENES.md → Scene, with JSON-pointer error messages.
#include <algorithm>
#include <nlohmann/json.hpp>
#include <utility>

#include "parser/JsonReader.h"
#include "parser/SceneReaders.h"
#include "varc/core/FileRead.h"
#include "varc/scene/Scene.h"

namespace varc::scene {
namespace {

using nlohmann::json;

bool readScene(JsonReader& r, const json& root, Scene& scene) {
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
            !r.readPositive(q["shadow_distance"], "/quality/shadow_distance",
                            scene.shadowDistance)) {
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
    JsonReader reader(path);
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