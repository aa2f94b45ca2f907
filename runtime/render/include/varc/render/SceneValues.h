// SPDX-License-Identifier: Apache-2.0
// The built-in uniform values of SHADER_ABI.md §4 for a scene: per camera, per object, per light.
// Pure CPU: the renderer layers them (light, object, material, camera) for UniformBlockWriter.
#pragma once

#include "varc/pack/PackModel.h"
#include "varc/render/ShaderValues.h"
#include "varc/scene/CameraMatrices.h"
#include "varc/scene/ForwardLights.h"
#include "varc/scene/Scene.h"

namespace varc::render {

// UnityPerFrame + UnityPerCamera (§4.1, §4.2); time is 0 so renders are reproducible.
ShaderValues cameraValues(const scene::Scene& scene, const scene::CameraMatrices& camera);

// UnityPerDraw, UnityProbes (SH of |assignment.shLights| plus ambient), UnityVertexLights
// (§4.3–4.5), and the GLSL legacy matrices (§4.11).
ShaderValues objectValues(const scene::Scene& scene, const scene::Object& object,
                          const scene::CameraMatrices& camera,
                          const scene::ForwardLightAssignment& assignment);

// UnityLighting (§4.6) for one pixel light of a forward pass; nullptr = the ForwardBase pass
// without a main directional light (colour 0).
ShaderValues forwardLightValues(const scene::Light* light);

// |material| with the shader's Properties defaults (ShaderView::properties()) added for every
// property it does not set; a texture default "" becomes "gray" (Unity's fallback).
scene::Material withPropertyDefaults(scene::Material material,
                                     const std::vector<pack::ShaderProperty>& defaults);

// Material properties as given: floats, vectors; textures get `<name>_ST` = (1, 1, 0, 0) unless
// the material sets it. Texture names are returned through |textures| (property -> name).
ShaderValues materialValues(const scene::Material& material,
                            std::map<std::string, std::string>& textures);

// The per-draw state of dynamic_branch keywords, as Unity sends it: each of |dynamicKeywords|
// (PassView::dynamicKeywords or ShaderView::dynamicKeywords) set in |values| to 1 when
// |enabled| (the keywords the draw enables, e.g. the material's) lists it, else 0; names of
// |enabled| that are not dynamic are left alone (they select variants instead).
// Example: dynamic {"RED", "GREEN"}, enabled {"RED", "_FOG"} -> RED = 1, GREEN = 0.
void setDynamicBranchValues(ShaderValues& values, const std::vector<std::string>& dynamicKeywords,
                            const std::vector<std::string>& enabled);

}  // namespace varc::render
