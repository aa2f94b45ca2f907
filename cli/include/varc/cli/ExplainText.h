// SPDX-License-Identifier: Apache-2.0
// The text form of `varc explain`'s report (ExplainReport.h).
#pragma once

#include <iosfwd>
#include <nlohmann/json.hpp>

namespace varc::cli {

// Prints |report| (from explainJson) for people. Example (seed000's ForwardAdd pass):
//   Shader "Custom/My First Lighting Shader" pass 1 (LightMode ForwardAdd): 5 variants
//   Keyword sets (the first declared varies slowest):
//     set 0: multi_compile_fwdadd (shortcut) at My First Lighting Shader.shader:45
//            POINT DIRECTIONAL SPOT POINT_COOKIE DIRECTIONAL_COOKIE
//            changes the fragment program
//   vertex: 1 program
//     program 0: 5 variants: #0 POINT, #1 DIRECTIONAL, ...
void printExplainText(const nlohmann::ordered_json& report, std::ostream& out);

}  // namespace varc::cli
