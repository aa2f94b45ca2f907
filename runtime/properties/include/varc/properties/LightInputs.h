// SPDX-License-Identifier: Apache-2.0
// LightInputs: whether a shader's lit passes read any light input, decided from the pack's
// reflection (uniform block members and resources by name), with no Vulkan device.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "varc/pack/ProgramReflection.h"
#include "varc/reader/ShaderView.h"

namespace varc::properties {

// The names the renderer fills from the scene's lights (LightInputs.cpp lists them, with where
// varc's built-in includes declare each), sorted. A trailing '*' marks a prefix
// ("_CameraGBufferTexture*").
const std::vector<std::string_view>& lightInputNames();

// True when |name| is a light input: one of lightInputNames(), or one prefixed "sampler" (the
// separate sampler of a texture, "sampler_LightTexture0"). Example: "_LightColor0" -> true,
// "_MainTex" -> false.
bool isLightInput(std::string_view name);

// The light inputs |program| reads: members of its uniform and push-constant blocks and its
// resources that are light inputs, sorted, each once. Reflection lists a block whole when a
// program reads any member of it (an unread block is pruned), so a member counts with its block.
std::vector<std::string> lightInputsRead(const pack::ProgramReflection& program);

// One variant's programs (every stage), for lightInputsOf().
struct VariantReflection {
    std::string description;  // VariantView::describe(), for findings
    std::vector<pack::ProgramReflection> programs;
};

// One pass of a shader, for lightInputsOf().
struct PassReflection {
    std::string lightMode;  // "ForwardBase", "ForwardAdd", ...
    std::vector<VariantReflection> variants;
};

// True for the LightModes Unity draws once per light: ForwardAdd (ASCII case-insensitive).
// Deferred light passes carry no LightMode; the property checks draw only shaders with a
// ForwardBase pass, so they are not classified here.
bool drawnPerLight(std::string_view lightMode);

// What the reflection of a shader's lit passes says about its light inputs.
struct LightInputReport {
    std::vector<std::string> read;  // the light inputs any program reads, sorted, each once
    // Per-light passes (drawnPerLight) with variants that read no light input: "ForwardAdd
    // variant shader 'X' pass 1 ... {POINT} reads no light input (2 of 5 variants)", one a pass.
    std::vector<std::string> findings;
    bool lit() const { return !read.empty(); }
};

// Classifies |passes|: the shader is lit when any program of any pass reads a light input;
// a per-light pass any of whose variants reads none is a finding. Pure: synthetic reflection
// data in unit tests. Example: one ForwardBase variant whose fragment program has a block
// member "_LightColor0" -> read = {"_LightColor0"}, lit(), no findings.
LightInputReport lightInputsOf(const std::vector<PassReflection>& passes);

// The reflection of |shader|'s ForwardBase and ForwardAdd passes (every such pass, every
// variant, every stage), for lightInputsOf().
std::vector<PassReflection> litPassReflections(const reader::ShaderView& shader);

// How the reflection and the renders combine (docs/PROPERTIES.md, "Models"): |inputs| from
// lightInputsOf(), |responds| when some key light drawn alone changes 2% of the pixels by more
// than 1/64. notLit: the light relations are n/a (only when no light input is read and the image
// does not respond). litFailures: the reasons `lit` fails beyond its own measurement: a response
// without a light input (the list misses a path), and each finding.
struct LightModelDecision {
    bool notLit = false;
    std::vector<std::string> litFailures;
};
LightModelDecision decideLightModel(const LightInputReport& inputs, bool responds);

}  // namespace varc::properties
