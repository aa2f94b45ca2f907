// SPDX-License-Identifier: Apache-2.0
// `varc validate --properties`: the metamorphic property checks (varc::properties) over every
// lit shader of the packs, as a table.
#pragma once

#include <iosfwd>

#include "varc/cli/Options.h"

namespace varc::cli {

// Checks every shader with a ForwardBase pass in --pack P... (docs/PROPERTIES.md), prints one
// row per shader with a column per relation (pass, FAIL, n/a), then each failure's shader,
// relation, case, variants, worst pixels and images (under --out, default validate-out); exit 1
// when a relation fails or a scene does not render, 2 when a pack or the device cannot be opened.
int runValidateProperties(const Options& options, std::ostream& out, std::ostream& err);

}  // namespace varc::cli
