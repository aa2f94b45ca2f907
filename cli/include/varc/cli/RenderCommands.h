// SPDX-License-Identifier: Apache-2.0
// `varc render` and `varc validate`: draw scenes with pack variants on Vulkan (lavapipe by
// default) and compare them with the independent CPU reference (issue #5).
#pragma once

#include <iosfwd>

#include "varc/cli/Options.h"

namespace varc::cli {

// Renders --scene with the packs to -o PNG; with --reference/--diff also renders the CPU
// reference, writes it and the diff, and exits 1 when the comparison fails.
int runRender(const RenderOptions& options, std::ostream& out, std::ostream& err);

// Renders every *.json scene under --scenes (default tests/scenes/forward), compares each with
// the reference, writes render/reference/diff PNGs to --out (default validate-out), prints a
// table (scene, draws, variants, max/mean error, pass/fail); exit 1 on any failure.
int runValidate(const ValidateOptions& options, std::ostream& out, std::ostream& err);

}  // namespace varc::cli
