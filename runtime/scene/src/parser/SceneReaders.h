// SPDX-License-Identifier: Apache-2.0
// The readers of the parts of a scene file (docs/SCENES.md), shared by parseScene.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "JsonReader.h"
#include "varc/scene/Scene.h"

namespace varc::scene {

// Each reads |value| (found at JSON pointer |p|) into its last argument; false after reporting
// the first error to |r|.

// "position", "rotation" and "scale" of |value| into |out| (a scale must be at least 1e-06).
bool readTransform(JsonReader& r, const nlohmann::json& value, const std::string& pointer,
                   Transform& out);
// The "camera" object.
bool readCamera(JsonReader& r, const nlohmann::json& value, const std::string& p, Camera& c);
// One entry of "objects": mesh, transform, material and lightmaps.
bool readObject(JsonReader& r, const nlohmann::json& value, const std::string& p, Object& o);
// One entry of "lights", its shadow settings included.
bool readLight(JsonReader& r, const nlohmann::json& value, const std::string& p, Light& l);
// quality.shadow_cascades, shadow_cascade_splits and shadow_projection of |q| into |scene|.
bool readCascades(JsonReader& r, const nlohmann::json& q, Scene& scene);

}  // namespace varc::scene
