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
    // Deferred LDR: the light buffer holds exp2(-c) in 8 bits and the frame is -log2 of it, so one
    // buffer LSB near 0.5 is 1/(0.5·ln 2) ≈ 2.9 LSB of the frame. The buffer is rounded once per
    // G-buffer write and twice per light (the shader's exp2 output, the DstColor·Zero blend); a GPU
    // exp2 landing on the other side of a rounding boundary in two of them moves a pixel by up to
    // 6 LSB. The mean signed error (±0.25 LSB) still catches any systematic difference.
    if (scene.camera.path == scene::RenderPath::Deferred && !scene.camera.hdr) {
        tolerance.interiorLsb = tolerance.edgeLsb = 6.0f;
    }
    return tolerance;
}

}  // namespace varc::reference
