// SPDX-License-Identifier: Apache-2.0
// VisibleLights: the single-pass forward path's light rules (seed 003; docs/LIGHTING.md §9.3):
// which lights of a scene are visible and fill the 16-slot light buffer, and which of them touch
// each object, in the order the per-object light index lists hold them. Rules only, no shading:
// the GPU renderer and the CPU reference both follow them.
#pragma once

#include <vector>

#include "varc/scene/Scene.h"

namespace varc::scene {

inline constexpr int kMaxVisibleLights = 16;     // slots of _LightBuffer
inline constexpr int kMaxLightsPerObject = 8;    // unity_4LightIndices0 and 1
inline constexpr int kMaxPixelLightsPerObject = 4;  // unity_4LightIndices0: per pixel

struct VisibleLightSet {
    std::vector<int> slots;    // scene light index per light-buffer slot (<= 16), in slot order
    std::vector<int> dropped;  // visible lights beyond the 16 slots, least important last
};

// The lights the camera can see, in buffer order: a directional light is always visible; a
// point or spot light when its range sphere intersects the camera's view frustum (the cone is
// not used). Ordered by importance (Important, Auto, NotImportant), then by decreasing
// brightness seen from the camera position (lightBrightnessAt), then by scene order. The first
// kMaxVisibleLights take the buffer slots; the rest are dropped from every index list.
VisibleLightSet selectVisibleLights(const Scene& scene);

struct ObjectLightList {
    int count = 0;             // unity_LightIndicesOffsetAndCount.y: slotted lights touching it
    std::vector<int> slots;    // the first min(count, 8) of them: [0, 4) per pixel, [4, 8) per vertex
    bool operator==(const ObjectLightList&) const = default;
};

// The buffer slots of |visible| whose light reaches |object| (the forward culling rule of
// LIGHTING.md §9.1: a point or spot light whose range sphere misses the object's bounding
// sphere is ignored), ordered by importance, then by decreasing brightness at the object's
// centre, then by slot. Example: three visible point lights of which two reach the object give
// count 2 and those two slots, the brighter first.
ObjectLightList objectLightList(const Scene& scene, const VisibleLightSet& visible,
                                const Object& object);

}  // namespace varc::scene
