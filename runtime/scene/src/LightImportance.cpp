// SPDX-License-Identifier: Apache-2.0
// LightImportance: the order in which lights are chosen (docs/LIGHTING.md §9).
#include "varc/scene/LightImportance.h"

#include <algorithm>

namespace varc::scene {

int importanceRank(LightRenderMode mode) {
    switch (mode) {
        case LightRenderMode::Important:
            return 0;
        case LightRenderMode::Auto:
            return 1;
        case LightRenderMode::NotImportant:
            return 2;
    }
    return 1;
}

RankedLight rankLight(int index, const Light& light, const glm::vec3& centre) {
    return {index, importanceRank(light.renderMode), lightBrightnessAt(light, centre)};
}

bool lightReaches(const Light& light, const BoundingSphere& bounds) {
    if (light.type == LightType::Directional) return true;
    return glm::distance(light.transform.position, bounds.centre) < light.range + bounds.radius;
}

void sortByImportance(std::vector<RankedLight>& lights) {
    std::sort(lights.begin(), lights.end(), [](const RankedLight& a, const RankedLight& b) {
        if (a.rank != b.rank) return a.rank < b.rank;
        if (a.brightness != b.brightness) return a.brightness > b.brightness;
        return a.index < b.index;
    });
}

}  // namespace varc::scene
