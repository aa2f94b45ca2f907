// SPDX-License-Identifier: Apache-2.0
// LightVolume: the geometry a deferred light is drawn with (issue #6). Point lights draw a sphere
// around their range, spot lights a square pyramid around their cone, directional lights (and
// volumes the camera cannot see whole) a full-screen quad. Pure CPU, like DeferredValues.h.
//
// A convex volume is drawn one side only, so each pixel is shaded at most once:
//  - camera outside: front faces with ZTest LEqual (the volume's surface in front of the
//    G-buffer depth), the shaded pixels are those whose surface lies behind the front face;
//  - camera inside (the near plane may cut the front faces): back faces with ZTest GEqual.
// Both keep the background unlit (its depth is the far plane). A volume that reaches past the far
// plane while the camera is inside would lose its clipped back faces: it falls back to the quad.
#pragma once

#include <array>
#include <glm/glm.hpp>

#include "varc/scene/CameraMatrices.h"
#include "varc/scene/Mesh.h"
#include "varc/scene/Scene.h"

namespace varc::render {

enum class LightVolumeDraw {
    FullScreenQuad,  // the pass's own state; the rays come in through NORMAL (_LightAsQuad = 1)
    FrontFaces,      // Cull Back, ZTest LEqual
    BackFaces,       // Cull Front, ZTest GEqual
};

// Icosphere whose every face plane lies at distance >= 1 from the origin: scaled by r it holds
// the whole ball of radius r.
const scene::Mesh& unitSphereVolume();

// Square pyramid, apex at the origin, base at z = 1 with corners (±1, ±1, 1): scaled by
// (r·tan(a/2), r·tan(a/2), r) it holds a spot cone of angle a cut at range r.
const scene::Mesh& unitPyramidVolume();

struct LightVolume {
    LightVolumeDraw draw = LightVolumeDraw::FullScreenQuad;
    const scene::Mesh* mesh = nullptr;  // null for the quad
    glm::mat4 objectToWorld{1.0f};
};

// How |light| is drawn by |camera|: the volume, its transform and which faces. The camera counts
// as inside when its position lies within the near plane's corner distance of the volume.
LightVolume chooseLightVolume(const scene::Light& light, const scene::Camera& camera,
                              const scene::CameraMatrices& matrices);

}  // namespace varc::render
