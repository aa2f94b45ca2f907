// SPDX-License-Identifier: Apache-2.0
// How Unity's built-in pipeline orders lights when it has to choose among them: the forward
// light assignment per object (ForwardLights.h) and the single-pass light buffer and per-object
// lists (VisibleLights.h) use the same order (docs/LIGHTING.md §9).
#pragma once

#include <vector>

#include "varc/scene/ForwardLights.h"
#include "varc/scene/Scene.h"

namespace varc::scene {

// A light (or light-buffer slot, whatever |index| counts) with what it is ordered by.
struct RankedLight {
    int index = 0;
    int rank = 0;             // importanceRank of its render mode
    float brightness = 0.0f;  // lightBrightnessAt where the choice is made
};

// Important 0, Auto 1, NotImportant 2: lower ranks are chosen first.
int importanceRank(LightRenderMode mode);

// |light| ranked at |centre|, under |index|.
RankedLight rankLight(int index, const Light& light, const glm::vec3& centre);

// Whether |light| can light anything inside |bounds|: directional lights always, point and spot
// lights when their range sphere intersects the bounding sphere.
bool lightReaches(const Light& light, const BoundingSphere& bounds);

// Importance, then decreasing brightness, then increasing index: a strict total order, so the
// result does not depend on the sort algorithm or the input order.
void sortByImportance(std::vector<RankedLight>& lights);

}  // namespace varc::scene
