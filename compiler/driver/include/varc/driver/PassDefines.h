// SPDX-License-Identifier: Apache-2.0
// The macros varc defines before a program, as Unity does: API, target, pass, stage, keywords.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "varc/core/Stage.h"
#include "varc/driver/PredefinedMacro.h"
#include "varc/shaderlab/ShaderAst.h"

namespace varc::driver {

// What the predefined macros of one (pass, variant, stage) depend on.
struct DefineContext {
    std::string lightMode;  // Pass LightMode tag ("ForwardBase", ...; "" = none)
    std::string target;     // `#pragma target` ("3.0"); "" = Unity's default 2.5
    shaderlab::ProgramLanguage language = shaderlab::ProgramLanguage::Cg;
    Stage stage = Stage::Vertex;
    std::vector<std::string> keywords;  // the variant's keywords, sorted
    // `#pragma instancing_options` switches as written ("procedural:setup", "maxcount:50");
    // each documented one adds its macro (instancingOptionMacros) before the keywords.
    std::vector<std::string> instancingOptions;
};

// Unity's version number that varc's built-in library behaves like (2019.4).
inline constexpr int kUnityVersion = 201940;

// "3.0" -> 30, "4.5" -> 45, "" -> 25. Returns -1 for text that is not a shader model.
int shaderTargetNumber(std::string_view target);

// The UNITY_PASS_* macro for a LightMode tag (case-insensitive), or "" for none.
// "ForwardBase" -> UNITY_PASS_FORWARDBASE, "ForwardAdd" -> UNITY_PASS_FORWARDADD,
// "Deferred" -> UNITY_PASS_DEFERRED, "ShadowCaster" -> UNITY_PASS_SHADOWCASTER,
// "PrepassBase" -> UNITY_PASS_PREPASSBASE, "PrepassFinal" -> UNITY_PASS_PREPASSFINAL,
// "Meta" -> UNITY_PASS_META, "MotionVectors" -> UNITY_PASS_MOTIONVECTORS.
std::string passMacro(std::string_view lightMode);

// The macros for |context| in a fixed order (see docs/KEYWORDS.md, "Pass defines"): what the
// driver filters (dropUnobservedMacros) and adjusts (UserDefines::adopt) before writing the text.
std::vector<PredefinedMacro> predefinedMacros(const DefineContext& context);

// writePreamble(predefinedMacros(|context|)). Example for a ForwardAdd fragment program with POINT:
//   #define SHADER_API_VULKAN 1
//   #define SHADER_API_DESKTOP 1
//   #define SHADER_TARGET 30
//   #define UNITY_VERSION 201940
//   #define UNITY_PASS_FORWARDADD 1
//   #define SHADER_STAGE_FRAGMENT 1
//   #define POINT 1
std::string makePreamble(const DefineContext& context);

}  // namespace varc::driver
