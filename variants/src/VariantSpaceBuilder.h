// SPDX-License-Identifier: Apache-2.0
// Builds a VariantSpace from PassKeywords: keyword table, per-set options, compiled rules.
#pragma once

#include <optional>

#include "varc/core/Diagnostic.h"
#include "varc/variants/PassKeywords.h"
#include "varc/variants/VariantSpace.h"

namespace varc::variants {

// The friend of VariantSpace that fills in its private tables (VariantSpace::build calls it).
class VariantSpaceBuilder {
public:
    // See VariantSpace::build.
    static std::optional<VariantSpace> build(const PassKeywords& keywords, DiagnosticSink& sink);

private:
    static void addSetOptions(VariantSpace& space, const PassKeywords& keywords);
    static void addRules(VariantSpace& space, const PassKeywords& keywords);
    static void groupSets(VariantSpace& space, std::vector<size_t> parent);
};

}  // namespace varc::variants
