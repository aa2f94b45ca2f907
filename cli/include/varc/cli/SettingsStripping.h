// SPDX-License-Identifier: Apache-2.0
// Graphics Settings' built-in stripping (lightmap, fog and instancing modes) as strip rules.
#pragma once

#include <optional>
#include <vector>

#include "varc/core/SourceLocation.h"
#include "varc/project/GraphicsSettings.h"
#include "varc/variants/StripRules.h"

namespace varc::cli {

// The rules |settings| imply for one shader (docs/PROJECTS.md, "Graphics Settings stripping"):
// - lightmap and fog modes only under Custom stripping (1): a variant is removed when it uses a
//   mode whose keep flag is 0 (a missing flag keeps). Automatic (0, Unity's default) would
//   analyse the scenes; varc keeps every mode then, a superset (docs/PROJECTS.md);
// - instancing: Strip All (1) removes INSTANCING_ON; Strip Unused (0, the default, also without
//   a settings file) removes it unless one of the shader's materials enables instancing
//   (|anyMaterialInstanced|); Keep All (2) keeps it.
// Each rule's location is |where| (the settings file, or none).
std::vector<variants::StripRule> settingsStripRules(
    const std::optional<project::GraphicsSettings>& settings, bool anyMaterialInstanced,
    SourceLocation where);

}  // namespace varc::cli
