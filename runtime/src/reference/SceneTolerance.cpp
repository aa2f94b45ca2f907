// SPDX-License-Identifier: Apache-2.0
#include "varc/reference/SceneTolerance.h"

namespace varc::reference {

Tolerance toleranceFor(const scene::Scene& scene) {
    Tolerance tolerance;
    for (const scene::Light& light : scene.lights) {
        if (light.type != scene::LightType::Directional || light.cookie != "none") {
            tolerance.interiorLsb = tolerance.edgeLsb = 2.0f;
        }
    }
    return tolerance;
}

}  // namespace varc::reference
