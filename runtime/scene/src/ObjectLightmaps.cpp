// SPDX-License-Identifier: Apache-2.0
// ObjectLightmaps: an object's lightmap keywords from its lightmap and the mixed lighting mode.
#include "varc/scene/ObjectLightmaps.h"

namespace varc::scene {

ObjectLightmaps objectLightmaps(const Scene& scene, const Object& object) {
    ObjectLightmaps out;
    if (object.lightmap) {
        out.lightmap = object.lightmap->baked.has_value();
        out.dynamicLightmap = object.lightmap->realtime.has_value();
        out.dirLightmap = object.lightmap->directional.has_value();
    }
    out.lightProbes = object.usesLightProbes();
    switch (scene.mixedLighting) {
        case MixedLightingMode::BakedIndirect:
            break;
        case MixedLightingMode::Subtractive:
            out.shadowMixing = out.lightmap;
            break;
        case MixedLightingMode::Shadowmask:
            out.shadowmask = true;
            out.shadowMixing = true;
            break;
        case MixedLightingMode::DistanceShadowmask:
            out.shadowmask = true;
            break;
    }
    return out;
}

}  // namespace varc::scene
