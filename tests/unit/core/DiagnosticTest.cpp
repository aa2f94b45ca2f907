// SPDX-License-Identifier: Apache-2.0
// DiagnosticList counts errors apart from warnings and notes.
#include "varc/core/Diagnostic.h"

#include <gtest/gtest.h>

namespace varc {
namespace {

TEST(DiagnosticList, CountsOnlyErrors) {
    DiagnosticList list;
    list.warning({0, 1, 1}, "w");
    EXPECT_FALSE(list.hasErrors());
    list.error({0, 2, 3}, "e");
    EXPECT_EQ(list.errorCount(), 1u);
    EXPECT_EQ(list.diagnostics().size(), 2u);
    EXPECT_EQ(list.diagnostics()[1].location, (SourceLocation{0, 2, 3}));
}

TEST(Diagnostic, SeverityNamesAsCompilersPrintThem) {
    EXPECT_STREQ(severityName(Severity::Note), "note");
    EXPECT_STREQ(severityName(Severity::Warning), "warning");
    EXPECT_STREQ(severityName(Severity::Error), "error");
}

}  // namespace
}  // namespace varc
