// SPDX-License-Identifier: Apache-2.0
// Merges identical compile diagnostics from many variants into one, with a variant count.
#include "DiagnosticGrouper.h"

namespace varc::driver {

void DiagnosticGrouper::add(const std::vector<Diagnostic>& diagnostics,
                            SourceLocation contextLocation, const std::string& context,
                            const std::vector<uint64_t>& variantIds) {
    for (const Diagnostic& diagnostic : diagnostics) {
        Key key{static_cast<int>(diagnostic.severity), diagnostic.location.file,
                diagnostic.location.line, diagnostic.location.column, diagnostic.message};
        auto [it, inserted] = mIndex.emplace(key, mGroups.size());
        if (inserted) {
            mGroups.push_back({diagnostic, contextLocation, context, {}});
            if (diagnostic.severity == Severity::Error) ++mErrors;
        }
        mGroups[it->second].variants.insert(variantIds.begin(), variantIds.end());
    }
}

void DiagnosticGrouper::flush(DiagnosticSink& sink) const {
    for (const Group& group : mGroups) {
        Diagnostic diagnostic = group.diagnostic;
        std::string note = group.context;
        if (group.variants.size() > 1) {
            note += "; " + std::to_string(group.variants.size()) + " variants affected";
        }
        diagnostic.notes.push_back({group.contextLocation, note});
        sink.report(std::move(diagnostic));
    }
}

}  // namespace varc::driver
