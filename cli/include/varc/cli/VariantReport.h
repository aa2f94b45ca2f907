// SPDX-License-Identifier: Apache-2.0
// The output of `varc variants`: a text listing in the spirit of Unity's "Show variants", or JSON.
#pragma once

#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "varc/frontend/ShaderLoader.h"
#include "varc/includes/SourceMap.h"

namespace varc::cli {

// A project's staged counts of one pass: {"declared":D,"materials":M,"settings":S,"rules":R}.
nlohmann::ordered_json stagesJson(const frontend::VariantStageCounts& counts);
// The same as text: "declared 96 -> materials 24 -> settings 12 -> rules 12".
std::string stagesText(const frontend::VariantStageCounts& counts);

// {"shaders":[{"file":F,"name":N,"passes":[{"index":0,"name":"","lightmode":"ForwardBase",
//   "keyword_sets":[["_","VERTEXLIGHT_ON"]],"variants":2,"list":[[],["VERTEXLIGHT_ON"]]}],
//   "variants":7}],"variants":7}
// "list" (every variant in enumeration order, keywords sorted) only when |withList|.
nlohmann::ordered_json variantsJson(const std::vector<frontend::LoadedShader>& shaders,
                                    bool withList);

// Per shader and pass: name, LightMode, each keyword set with its pragma line, the count (and
// the full space when skips or shortcut rules removed variants), then the totals.
void printVariantsText(const std::vector<frontend::LoadedShader>& shaders,
                       const includes::SourceMap& sourceMap, bool withList, std::ostream& out);

}  // namespace varc::cli
