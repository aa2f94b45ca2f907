// SPDX-License-Identifier: Apache-2.0
#include "varc/render/SinglePassValues.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace varc::render {

glm::vec2 spotFadeConstants(float spotAngleDegrees) {
    const float outer = glm::radians(0.5f * spotAngleDegrees);
    const float outerCos = std::cos(outer);
    const float innerCos = std::cos(std::atan(46.0f / 64.0f * std::tan(outer)));
    const float a = 1.0f / std::max(innerCos - outerCos, 0.001f);
    return {a, -outerCos * a};
}

ShaderValues lightBufferValues(const scene::Scene& scene, const scene::VisibleLightSet& visible) {
    std::vector<glm::vec4> colors(scene::kMaxVisibleLights, glm::vec4(0.0f));
    std::vector<glm::vec4> positions = colors, attenuations = colors, spotDirections = colors;
    for (size_t slot = 0; slot < visible.slots.size() && slot < colors.size(); ++slot) {
        const scene::Light& light = scene.lights[static_cast<size_t>(visible.slots[slot])];
        colors[slot] = glm::vec4(light.finalColor(), 0.0f);
        spotDirections[slot] = glm::vec4(-light.forward(), 0.0f);
        if (light.type == scene::LightType::Directional) {
            positions[slot] = glm::vec4(-light.forward(), 0.0f);
            attenuations[slot] = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
            continue;
        }
        positions[slot] = glm::vec4(light.transform.position, 1.0f);
        glm::vec2 spot(0.0f, 1.0f);
        if (light.type == scene::LightType::Spot) spot = spotFadeConstants(light.spotAngle);
        attenuations[slot] =
            glm::vec4(1.0f / std::max(light.range * light.range, 1e-5f), 0.0f, spot.x, spot.y);
    }
    ShaderValues values;
    values.setArray("_VisibleLightColors", colors);
    values.setArray("_VisibleLightDirectionsOrPositions", positions);
    values.setArray("_VisibleLightAttenuations", attenuations);
    values.setArray("_VisibleLightSpotDirections", spotDirections);
    return values;
}

ShaderValues drawLightValues(const scene::ObjectLightList& list) {
    glm::vec4 first(0.0f), second(0.0f);
    for (size_t k = 0; k < list.slots.size() && k < scene::kMaxLightsPerObject; ++k) {
        auto component = static_cast<glm::length_t>(k % 4);
        (k < 4 ? first : second)[component] = static_cast<float>(list.slots[k]);
    }
    ShaderValues values;
    values.set("unity_LightIndicesOffsetAndCount",
               glm::vec4(0.0f, static_cast<float>(list.count), 0.0f, 0.0f));
    values.set("unity_4LightIndices0", first);
    values.set("unity_4LightIndices1", second);
    return values;
}

}  // namespace varc::render
