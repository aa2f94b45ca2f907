// SPDX-License-Identifier: Apache-2.0
// `varc validate --properties`: the metamorphic property checks (varc::properties) over every
// lit shader of the packs, as a table.
#pragma once

#include <iosfwd>
#include <set>
#include <string>
#include <vector>

#include "varc/cli/Options.h"
#include "varc/properties/PropertyRunner.h"
#include "varc/reader/Pack.h"
#include "varc/render/Renderer.h"
#include "varc/vulkan/VulkanContext.h"

namespace varc::cli {

// Checks every shader with a ForwardBase pass in |packs| (opened from --pack P..., drawn by
// |renderer| on |context|; docs/PROPERTIES.md), prints one row per shader with a column per
// relation (pass, FAIL, n/a), then each failure's shader, relation, case, variants, worst pixels
// and images (under --out, default validate-out); exit 1 when a relation fails, a scene does not
// render, no shader is lit or the validation layer reported anything. With |only|, just the lit
// shaders named there (plain `varc validate`: materials without a reference model), and none
// lit is no error. With |reports|, each shader's report is appended there (for --report).
int runValidateProperties(const std::vector<reader::Pack>& packs, vulkan::VulkanContext& context,
                          render::Renderer& renderer, const ValidateOptions& options,
                          std::ostream& out, std::ostream& err,
                          const std::set<std::string>* only = nullptr,
                          std::vector<properties::ShaderReport>* reports = nullptr);

}  // namespace varc::cli
