// SPDX-License-Identifier: Apache-2.0
// Merges identical compile diagnostics from many variants into one, with a variant count.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "varc/core/Diagnostic.h"

namespace varc::driver {

// An error in a shared include shows up in every variant that compiles it; users want it once:
//   My Lighting.cginc:40:5: error: undeclared identifier 'foo'
//   a.shader:30:3: note: in the fragment stage of pass 1 ... keywords: POINT; 5 variants affected
class DiagnosticGrouper {
public:
    // Adds |diagnostics| found while compiling a program used by the variants |variantIds| (any
    // ids unique per variant, e.g. pass << 32 | variant); |context| describes where (stage, pass,
    // shader, keywords of the first variant). A variant met again, say through its other stage,
    // is counted once.
    void add(const std::vector<Diagnostic>& diagnostics, SourceLocation contextLocation,
             const std::string& context, const std::vector<uint64_t>& variantIds);
    bool hasErrors() const { return mErrors > 0; }
    // Reports every group, in first-seen order, with its context note.
    void flush(DiagnosticSink& sink) const;

private:
    struct Group {
        Diagnostic diagnostic;
        SourceLocation contextLocation;
        std::string context;
        std::set<uint64_t> variants;
    };
    using Key = std::tuple<int, uint32_t, uint32_t, uint32_t, std::string>;
    std::vector<Group> mGroups;
    std::map<Key, size_t> mIndex;
    size_t mErrors = 0;
};

}  // namespace varc::driver
