// SPDX-License-Identifier: Apache-2.0
// The camera of a scene file.
#include "SceneReaders.h"

namespace varc::scene {

using nlohmann::json;

bool readCamera(JsonReader& r, const json& value, const std::string& p, Camera& c) {
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

}  // namespace varc::scene
