// SPDX-License-Identifier: Apache-2.0
// `varc explain`: why a pass's variants exist and which keywords change which stage's program.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "varc/driver/CompileDriver.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/includes/SourceMap.h"

namespace varc::cli {

// What to explain about one built pass.
struct ExplainRequest {
    const frontend::LoadedShader* shader = nullptr;
    const frontend::LoadedPass* pass = nullptr;
    const driver::CompiledPass* compiled = nullptr;  // built with keepPrunedSources
    const driver::BuildOutput* build = nullptr;
    // --variant: one variant (index into compiled->variants) to explain in detail.
    std::optional<size_t> variant;
    // --diff: two variants (indices) whose pruned sources to compare per stage.
    std::optional<std::pair<size_t, size_t>> diff;
};

// The report as JSON (the --json output; the text output prints it):
//   shader, pass, light_mode, variants: the pass
//   sets: per keyword set in declaration order: directive, shortcut (bool), location
//     ("path:line"), keywords ("_" = none), stages (whose program the set's choice changes)
//   stages: per stage the pass has: its distinct programs (after pruning and dedup), each with
//     the program id and the variants (enumeration indices and keywords) that share it
//   variant (with request.variant): index, keywords, the origin of each set's choice, the
//     program per stage and how many variants share it, nearest (variants one set's choice
//     away, and the stages whose program differs)
//   diff (with request.diff): per stage whether the pruned sources are the same, else a line
//     diff ("-" only in the first, "+" only in the second)
nlohmann::ordered_json explainJson(const ExplainRequest& request,
                                   const includes::SourceMap& sourceMap);

// The index in |compiled|'s variants whose keywords are exactly |keywords| (after dropping
// undeclared ones: Unity's requested ∩ declared), or nullopt.
std::optional<size_t> findVariant(const frontend::LoadedPass& pass,
                                  const driver::CompiledPass& compiled,
                                  const std::vector<std::string>& keywords);

}  // namespace varc::cli
