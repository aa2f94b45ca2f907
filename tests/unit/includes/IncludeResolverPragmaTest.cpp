// SPDX-License-Identifier: Apache-2.0
// IncludeResolver: which #pragma lines are collected, with their text and location.
#include <gtest/gtest.h>

#include "IncludeTestSupport.h"
#include "varc/includes/IncludeResolver.h"

namespace varc::includes {
namespace {

using testing::Harness;
using testing::lines;

struct Expected {
    std::string text;
    std::string path;
    uint32_t line;
    uint32_t column;
};

void expectPragmas(const Harness& h, const ExpandedSource& expanded,
                   const std::vector<Expected>& expected) {
    ASSERT_EQ(expanded.pragmas.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        SCOPED_TRACE(expected[i].text);
        EXPECT_EQ(expanded.pragmas[i].text, expected[i].text);
        EXPECT_EQ(expanded.pragmas[i].location,
                  (SourceLocation{h.id(expected[i].path), expected[i].line, expected[i].column}));
    }
}

TEST(IncludeResolver, CollectsPragmasOnlyFromRootAndIncludeWithPragmas) {
    Harness h;
    h.file("m.shader",
           lines({"#pragma target 3.0", "#include \"plain.cginc\"",
                  "  #  pragma   multi_compile _ A   // trailing",
                  "#include_with_pragmas \"shared.cginc\"", "// #pragma commented_out",
                  "/* #pragma block_commented */", "#if 0", "#pragma inside_if", "#endif"}))
        .file("plain.cginc",
              lines({"#pragma plain_ignored", "#include_with_pragmas \"behind_plain.cginc\""}))
        .file("behind_plain.cginc", "#pragma behind_plain_ignored\n")
        .file("shared.cginc",
              lines({"#pragma multi_compile_fwdadd", "#include \"nested.cginc\"",
                     "#include_with_pragmas \"chained.cginc\"", "/*", "#pragma in_comment", "*/"}))
        .file("nested.cginc", "#pragma nested_plain_ignored\n")
        .file("chained.cginc", "  #pragma chained\n");
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    expectPragmas(h, *expanded,
                  {{"target 3.0", "m.shader", 1, 1},
                   {"multi_compile _ A", "m.shader", 3, 3},
                   {"multi_compile_fwdadd", "shared.cginc", 1, 1},
                   {"chained", "chained.cginc", 1, 3},
                   {"inside_if", "m.shader", 8, 1}});
    // Spliced text keeps every pragma line, collected or not.
    EXPECT_NE(expanded->text.find("#pragma plain_ignored"), std::string::npos);
}

TEST(IncludeResolver, JoinsContinuedPragmaLines) {
    Harness h;
    h.file("m.shader", lines({"#pragma multi_compile A \\", "  B", "#pragma /* x */ vertex v"}));
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    expectPragmas(h, *expanded,
                  {{"multi_compile A   B", "m.shader", 1, 1}, {"vertex v", "m.shader", 3, 1}});
}

TEST(IncludeResolver, CollectsAFilesPragmasOncePerExpansion) {
    Harness h;
    h.file("m.shader",
           lines({"#include_with_pragmas \"p.cginc\"", "#include_with_pragmas \"p.cginc\""}))
        .file("p.cginc", "#pragma multi_compile _ A\n");
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    expectPragmas(h, *expanded, {{"multi_compile _ A", "p.cginc", 1, 1}});
}

TEST(IncludeResolver, CollectsPragmasOfGuardedFileEvenWhenItsSpliceIsSkipped) {
    Harness h;
    h.file("m.shader", lines({"#include \"p.cginc\"", "#include_with_pragmas \"p.cginc\""}))
        .file("p.cginc", lines({"#pragma once", "#pragma multi_compile _ A"}));
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    expectPragmas(h, *expanded,
                  {{"once", "p.cginc", 1, 1}, {"multi_compile _ A", "p.cginc", 2, 1}});
    EXPECT_EQ(testing::countOf(expanded->text, "multi_compile"), 1u);  // spliced once
}

}  // namespace
}  // namespace varc::includes
