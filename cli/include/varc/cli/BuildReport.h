// SPDX-License-Identifier: Apache-2.0
// The staged summary `varc build` prints: declared variants -> after filters -> distinct
// programs per stage -> compiled modules -> bytes.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <vector>

#include "varc/driver/CompileDriver.h"
#include "varc/frontend/ShaderLoader.h"

namespace varc::cli {

// What a build's SPIR-V amounts to. A shard's placeholders (programs another shard builds,
// varc/pack/PartialPack.h) are not modules and count nowhere.
struct PackSizes {
    uint64_t modules = 0;        // distinct SPIR-V modules
    uint64_t rawSpirvBytes = 0;  // every variant's stages, as if stored separately
    uint64_t uniqueSpirvBytes = 0;
    uint64_t packBytes = 0;
};

// Per pass, in the spirit of Unity's Editor.log block:
//   Compiling shader "Custom/X" pass 1 "FORWARD" (LightMode ForwardAdd)
//       Full variant space:           5
//       After skips and rules:        5
//       Distinct programs:            vertex 1, fragment 5
//       Compiled SPIR-V modules:      vertex 1, fragment 5
//       Stage-independent keywords:   VERTEXLIGHT_ON (fragment)
// then a totals line with the sizes and the output path.
void printBuildReport(const std::vector<frontend::LoadedShader>& shaders,
                      const driver::BuildOutput& build, const PackSizes& sizes, double seconds,
                      std::ostream& out);

// The same as JSON: {"passes":[{"shader":..,"pass":..,"declared":..,"variants":..,
//   "sources":{"vertex":V,...},"programs":{...},"unaffected":{"VERTEXLIGHT_ON":["fragment"]}}],
//  "programs":N,"compiled_sources":N,"bytes":{"raw":..,"unique":..,"pack":..},"seconds":..}
nlohmann::ordered_json buildReportJson(const std::vector<frontend::LoadedShader>& shaders,
                                       const driver::BuildOutput& build, const PackSizes& sizes,
                                       double seconds);

}  // namespace varc::cli
