// SPDX-License-Identifier: Apache-2.0
// DiagnosticList bookkeeping.
#include "varc/core/Diagnostic.h"

#include <algorithm>

namespace varc {

const char* severityName(Severity severity) {
    switch (severity) {
        case Severity::Note: return "note";
        case Severity::Warning: return "warning";
        case Severity::Error: return "error";
    }
    return "error";
}

size_t DiagnosticList::errorCount() const {
    return static_cast<size_t>(std::count_if(mDiagnostics.begin(), mDiagnostics.end(),
                                             [](const Diagnostic& d) {
                                                 return d.severity == Severity::Error;
                                             }));
}

}  // namespace varc
