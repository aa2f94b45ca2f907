// SPDX-License-Identifier: Apache-2.0
// The commands that read a built pack through the runtime library: `varc info`, `varc extract`,
// `varc lookup` and `varc merge`. They never compile anything; a pack that fails to open is exit
// code 2.
#pragma once

#include <iosfwd>

#include "varc/cli/Options.h"

namespace varc::cli {

// Per shader and pass: LightMode, keyword sets, variants and distinct programs per stage, plus
// the pack's sizes and toolchain. --json gives the `varc variants --json` structure with
// "programs": {"vertex": V, "fragment": F} per pass.
int runInfo(const InfoOptions& options, std::ostream& out, std::ostream& err);

// Writes every program as DIR/program-NNNN-<stage>.spv and DIR/manifest.json mapping
// shader/pass/variant/stage to those files.
int runExtract(const ExtractOptions& options, std::ostream& out, std::ostream& err);

// Finds the variant for a keyword set or a light description under a selection policy and
// prints it with its programs. Exit 1 when the shader, the pass or (under the policy) a variant
// is not found.
int runLookup(const LookupOptions& options, std::ostream& out, std::ostream& err);

// Joins the partial packs of `varc build --shard K/N` (MergeOptions::parts) into the pack the
// whole build writes (MergeOptions::outputPath), byte for byte. Exit 1 when the parts do not
// make one build or their programs do not fit together; nothing is written then.
int runMerge(const MergeOptions& options, std::ostream& out, std::ostream& err);

}  // namespace varc::cli
