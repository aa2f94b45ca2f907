// SPDX-License-Identifier: Apache-2.0
// PassPlan: what one generated surface pass needs, worked out once, and the helpers both the
// vertex and the fragment writers use.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "varc/frontend/SurfaceCodeGenerator.h"

namespace varc::frontend::surface {

using Alpha = shaderlab::SurfaceOptions::Alpha;

// What one generated pass needs, worked out once from the program, its facts and the pass.
struct PassPlan {
    const shaderlab::SurfaceProgram& program;
    const SurfaceFacts& facts;
    SurfacePassKind kind;
    bool tangentSpace;                // the surface function writes o.Normal (tangent space)
    std::array<bool, 4> texcoords{};  // uv_, uv2_, uv3_, uv4_ members read texcoord0..3
    bool color;
    bool screenPos;
    bool customInput;  // Input travels whole from the vertex modifier
    // The fragment program calls the surface function: always in the forward passes; in the
    // caster only for alphatest or a surface function that clips (else it writes depth only).
    bool surfaceCall;
    bool base() const { return kind == SurfacePassKind::ForwardBase; }
    bool add() const { return kind == SurfacePassKind::ForwardAdd; }
    bool caster() const { return kind == SurfacePassKind::ShadowCaster; }
    bool fog() const { return !caster() && !program.options.noFog; }
};

// 0 for `uv_NAME`, 1 for `uv2_NAME`, ... 3 for `uv4_NAME`; -1 for other members. |texture|
// receives the texture's name: `uv_MainTex` reads texture `_MainTex` (Unity's convention).
int uvSet(std::string_view member, std::string& texture);

// Whether |members| holds |name|.
bool hasMember(const std::vector<std::string>& members, std::string_view name);

}  // namespace varc::frontend::surface
