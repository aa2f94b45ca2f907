// SPDX-License-Identifier: Apache-2.0
// ForwardLights: Unity's forward light assignment per object and SH from ambient plus lights
// (docs/LIGHTING.md §5, §9; keywords: docs/KEYWORDS.md §9).
#include "varc/scene/ForwardLights.h"

#include <algorithm>
#include <cmath>

#include "varc/scene/LightImportance.h"
#include "varc/scene/Mesh.h"

namespace varc::scene {
namespace {

// 1/(1 + 25 d²/r²): Unity's vertex-light attenuation, used for sorting and SH folding.
float distanceAttenuation(const Light& light, const glm::vec3& centre) {
    if (light.type == LightType::Directional) return 1.0f;
    const glm::vec3 d = light.transform.position - centre;
    return 1.0f / (1.0f + 25.0f * glm::dot(d, d) / (light.range * light.range));
}

}  // namespace

BoundingSphere worldBounds(const Object& object) {
    const glm::vec3 s = glm::abs(object.transform.scale);
    return {object.transform.position,
            builtinMesh(object.mesh).boundingRadius * std::max({s.x, s.y, s.z})};
}

float lightBrightnessAt(const Light& light, const glm::vec3& centre) {
    const float luminance = glm::dot(light.color, glm::vec3(0.2126f, 0.7152f, 0.0722f));
    return light.intensity * luminance * distanceAttenuation(light, centre);
}

ForwardLightAssignment assignForwardLights(const Scene& scene, const Object& object) {
    const BoundingSphere bounds = worldBounds(object);
    std::vector<RankedLight> sorted;
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        if (lightReaches(light, bounds))
            sorted.push_back(rankLight(static_cast<int>(i), light, bounds.centre));
    }
    sortByImportance(sorted);

    ForwardLightAssignment out;
    int pixelLights = 0;
    for (const RankedLight& c : sorted) {
        const Light& light = scene.lights[c.index];
        if (light.type == LightType::Directional &&
            light.renderMode != LightRenderMode::NotImportant) {
            // The first such light in the sorted order is the main light; with a cookie it
            // draws in an add pass and the base pass has none.
            if (!light.hasCookie()) out.mainDirectional = c.index;
            if (!light.hasCookie()) pixelLights = 1;
            break;
        }
    }
    std::vector<int> rest;
    for (const RankedLight& c : sorted) {
        if (c.index == out.mainDirectional) continue;
        const Light& light = scene.lights[c.index];
        const bool alwaysPixel = light.renderMode == LightRenderMode::Important ||
                                 (light.type == LightType::Directional && light.hasCookie());
        if (light.renderMode == LightRenderMode::NotImportant) {
            rest.push_back(c.index);
        } else if (alwaysPixel || pixelLights < scene.pixelLightCount) {
            out.addLights.push_back(c.index);
            ++pixelLights;
        } else {
            rest.push_back(c.index);
        }
    }
    for (int index : rest) {
        if (scene.lights[index].type == LightType::Point && out.vertexLights.size() < 4) {
            out.vertexLights.push_back(index);
        } else {
            out.shLights.push_back(index);
        }
    }
    return out;
}

std::array<std::array<float, 9>, 3> shCoefficients(const Scene& scene, const Object& object,
                                                   const std::vector<int>& shLights) {
    std::array<std::array<float, 9>, 3> sh{};
    for (int c = 0; c < 3; ++c) sh[c][0] = scene.ambient[c];
    const glm::vec3 centre = object.transform.position;
    for (int index : shLights) {
        const Light& light = scene.lights[index];
        glm::vec3 l = -light.forward();
        if (light.type != LightType::Directional) {
            const glm::vec3 toLight = light.transform.position - centre;
            const float length = glm::length(toLight);
            l = length > 1e-6f ? toLight / length : glm::vec3(0.0f, 1.0f, 0.0f);
        }
        const glm::vec3 color = light.finalColor() * distanceAttenuation(light, centre);
        for (int c = 0; c < 3; ++c) {
            const float k = color[c];
            sh[c][0] += 0.25f * k;
            sh[c][1] += 0.5f * k * l.y;
            sh[c][2] += 0.5f * k * l.z;
            sh[c][3] += 0.5f * k * l.x;
            sh[c][4] += 0.9375f * k * l.x * l.y;
            sh[c][5] += 0.9375f * k * l.y * l.z;
            sh[c][6] += 0.078125f * k * (3.0f * l.z * l.z - 1.0f);
            sh[c][7] += 0.9375f * k * l.x * l.z;
            sh[c][8] += 0.234375f * k * (l.x * l.x - l.y * l.y);
        }
    }
    return sh;
}

std::array<glm::vec4, 7> packedSH(const Scene& scene, const Object& object,
                                  const std::vector<int>& shLights) {
    const auto sh = shCoefficients(scene, object, shLights);
    std::array<glm::vec4, 7> packed{};
    for (int c = 0; c < 3; ++c) {
        packed[c] = glm::vec4(sh[c][3], sh[c][1], sh[c][2], sh[c][0] - sh[c][6]);
        packed[3 + c] = glm::vec4(sh[c][4], sh[c][5], 3.0f * sh[c][6], sh[c][7]);
    }
    packed[6] = glm::vec4(sh[0][8], sh[1][8], sh[2][8], 1.0f);
    return packed;
}

glm::vec3 shadeSH9(const std::array<glm::vec4, 7>& sh, const glm::vec3& n) {
    const glm::vec4 n4(n, 1.0f);
    const glm::vec4 vB(n.x * n.y, n.y * n.z, n.z * n.z, n.z * n.x);
    const float vC = n.x * n.x - n.y * n.y;
    glm::vec3 result;
    for (int c = 0; c < 3; ++c) {
        result[c] = glm::dot(sh[c], n4) + glm::dot(sh[3 + c], vB) + sh[6][c] * vC;
    }
    return result;
}

}  // namespace varc::scene
