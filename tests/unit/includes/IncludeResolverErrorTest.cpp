// SPDX-License-Identifier: Apache-2.0
// IncludeResolver: missing files, cycles, malformed directives and include-stack notes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "IncludeTestSupport.h"
#include "varc/includes/IncludeResolver.h"

namespace varc::includes {
namespace {

using testing::Harness;
using testing::lines;

const char* kIncludedFromHere = "in file included from here";

TEST(IncludeResolver, MissingFileListsSearchedDirs) {
    Harness h;
    h.includeDir("inc").includeDir("lib/../inc2").includeDir("inc").builtinDir("builtin");
    h.file("shaders/main.shader", lines({"float a;", "#include \"x.cginc\""}));
    auto expanded = h.expandFile("shaders/main.shader");
    EXPECT_FALSE(expanded.has_value());
    ASSERT_EQ(h.diagnostics.diagnostics().size(), 1u);
    const Diagnostic& error = h.diagnostics.diagnostics()[0];
    EXPECT_EQ(error.severity, Severity::Error);
    EXPECT_EQ(error.message,
              "cannot find include file \"x.cginc\"; searched: shaders, inc, inc2, builtin");
    EXPECT_EQ(error.location, (SourceLocation{h.id("shaders/main.shader"), 2, 10}));
    EXPECT_TRUE(error.notes.empty());
}

TEST(IncludeResolver, MissingAngledFileIsNamedAsWritten) {
    Harness h;
    h.file("main.shader", "  #include <x.h>\n");
    EXPECT_FALSE(h.expandFile("main.shader").has_value());
    ASSERT_EQ(h.diagnostics.diagnostics().size(), 1u);
    EXPECT_EQ(h.diagnostics.diagnostics()[0].message,
              "cannot find include file <x.h>; searched: .");
    EXPECT_EQ(h.diagnostics.diagnostics()[0].location.column, 12u);
}

TEST(IncludeResolver, MissingFileInsideConditionalBecomesErrorDirective) {
    Harness h;
    h.file("m.shader", lines({"#if defined(SHADER_API_METAL)", "  #include \"Metal.cginc\"",
                              "#endif", "after"}));
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_TRUE(h.diagnostics.diagnostics().empty());
    EXPECT_EQ(expanded->text,
              lines({"#line 1 0", "#if defined(SHADER_API_METAL)",
                     "#error varc: cannot find include file \"Metal.cginc\"", "#endif", "after"}));
    EXPECT_TRUE(h.mapsBack(*expanded));
    EXPECT_TRUE(expanded->dependencies.empty());
}

TEST(IncludeResolver, MissingFileInsideAGuardedFileIsStillAnError) {
    Harness h;
    h.file("m.shader", "#include \"a.h\"\n")
        .file("a.h",
              lines({"#ifndef A_H", "#define A_H", "#include \"AutoLight.cginc\"", "#endif"}));
    EXPECT_FALSE(h.expandFile("m.shader").has_value());
    ASSERT_EQ(h.diagnostics.errorCount(), 1u);
    EXPECT_EQ(h.diagnostics.diagnostics()[0].location, (SourceLocation{h.id("a.h"), 3, 10}));
}

TEST(IncludeResolver, ReportsCycleWithFullChain) {
    Harness h;
    h.file("s/main.shader", lines({"// main", "#include \"a.cginc\""}))
        .file("s/a.cginc", lines({"#include \"sub/b.cginc\""}))
        .file("s/sub/b.cginc", lines({"float b;", "  #include \"../a.cginc\""}));
    EXPECT_FALSE(h.expandFile("s/main.shader").has_value());
    ASSERT_EQ(h.diagnostics.diagnostics().size(), 1u);
    const Diagnostic& error = h.diagnostics.diagnostics()[0];
    EXPECT_EQ(error.message, "include cycle: a.cginc -> sub/b.cginc -> ../a.cginc");
    EXPECT_EQ(error.location, (SourceLocation{h.id("s/sub/b.cginc"), 2, 12}));
    ASSERT_EQ(error.notes.size(), 2u);
    EXPECT_EQ(error.notes[0].location, (SourceLocation{h.id("s/a.cginc"), 1, 10}));
    EXPECT_EQ(error.notes[0].message, kIncludedFromHere);
    EXPECT_EQ(error.notes[1].location, (SourceLocation{h.id("s/main.shader"), 2, 10}));
    EXPECT_EQ(error.notes[1].message, kIncludedFromHere);
}

TEST(IncludeResolver, ReportsFileIncludingItselfAsCycle) {
    Harness h;
    h.file("m.shader", "#include \"self.h\"\n").file("self.h", "x\n#include \"self.h\"\n");
    EXPECT_FALSE(h.expandFile("m.shader").has_value());
    ASSERT_EQ(h.diagnostics.diagnostics().size(), 1u);
    EXPECT_EQ(h.diagnostics.diagnostics()[0].message, "include cycle: self.h -> self.h");
    EXPECT_EQ(h.diagnostics.diagnostics()[0].location, (SourceLocation{h.id("self.h"), 2, 10}));
}

TEST(IncludeResolver, ReportsMalformedIncludeWithColumn) {
    struct Case {
        std::string line;
        std::string message;
        uint32_t column;
    };
    std::vector<Case> cases = {
        {"#include", "expected \"FILENAME\" or <FILENAME> after #include", 9},
        {"#include   // nothing", "expected \"FILENAME\" or <FILENAME> after #include", 9},
        {"#include MY_FILE", "expected \"FILENAME\" or <FILENAME> after #include", 10},
        {"#  include \"abc", "missing terminating \" character in #include", 12},
        {"#include <abc", "missing terminating > character in #include", 10},
        {"#include \"\"", "empty filename in #include", 10},
        {"#include_with_pragmas", "expected \"FILENAME\" or <FILENAME> after #include_with_pragmas",
         22},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.line);
        Harness h;
        h.file("m.shader", "float a;\n" + c.line + "\n");
        EXPECT_FALSE(h.expandFile("m.shader").has_value());
        ASSERT_EQ(h.diagnostics.diagnostics().size(), 1u);
        EXPECT_EQ(h.diagnostics.diagnostics()[0].message, c.message);
        EXPECT_EQ(h.diagnostics.diagnostics()[0].location,
                  (SourceLocation{h.id("m.shader"), 2, c.column}));
    }
}

TEST(IncludeResolver, ErrorNotesCarryTheIncludeStackInnermostFirst) {
    Harness h;
    h.file("m.shader", lines({"a", "b", "#include \"a.h\""}))
        .file("a.h", lines({"", "  #include \"sub/b.h\""}))
        .file("sub/b.h", lines({"#include \"c.h\" "}));
    EXPECT_FALSE(h.expandFile("m.shader").has_value());
    ASSERT_EQ(h.diagnostics.diagnostics().size(), 1u);
    const Diagnostic& error = h.diagnostics.diagnostics()[0];
    EXPECT_EQ(error.message, "cannot find include file \"c.h\"; searched: sub");
    EXPECT_EQ(error.location, (SourceLocation{h.id("sub/b.h"), 1, 10}));
    std::vector<SourceLocation> noteLocations;
    for (const DiagnosticNote& note : error.notes) {
        EXPECT_EQ(note.message, kIncludedFromHere);
        noteLocations.push_back(note.location);
    }
    EXPECT_THAT(noteLocations, ::testing::ElementsAre(SourceLocation{h.id("a.h"), 2, 12},
                                                      SourceLocation{h.id("m.shader"), 3, 10}));
    EXPECT_EQ(h.sourceMap.format(error.notes[0].location), "a.h:2:12");
}

TEST(IncludeResolver, KeepsGoingToReportEveryError) {
    Harness h;
    h.file("m.shader", lines({"#include \"one.h\"", "#include", "#include \"two.h\""}));
    EXPECT_FALSE(h.expandFile("m.shader").has_value());
    ASSERT_EQ(h.diagnostics.errorCount(), 3u);
    EXPECT_EQ(h.diagnostics.diagnostics()[0].location.line, 1u);
    EXPECT_EQ(h.diagnostics.diagnostics()[1].location.line, 2u);
    EXPECT_EQ(h.diagnostics.diagnostics()[2].location.line, 3u);
}

TEST(IncludeResolver, WarnsAboutTokensAfterTheNameButSplices) {
    Harness h;
    h.file("m.shader", "#include \"b.h\" junk\n").file("b.h", "B\n");
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    ASSERT_EQ(h.diagnostics.diagnostics().size(), 1u);
    EXPECT_EQ(h.diagnostics.diagnostics()[0].severity, Severity::Warning);
    EXPECT_EQ(h.diagnostics.diagnostics()[0].message, "extra tokens at end of #include directive");
    EXPECT_EQ(h.diagnostics.diagnostics()[0].location.column, 16u);
    EXPECT_NE(expanded->text.find("B\n"), std::string::npos);
}

TEST(IncludeResolver, ReportsUnterminatedCommentInIncludedFile) {
    Harness h;
    h.file("m.shader", "#include \"b.h\"\nafter\n").file("b.h", "x\n  /* never closed\n");
    EXPECT_FALSE(h.expandFile("m.shader").has_value());
    ASSERT_EQ(h.diagnostics.diagnostics().size(), 1u);
    EXPECT_EQ(h.diagnostics.diagnostics()[0].message, "unterminated /* comment");
    EXPECT_EQ(h.diagnostics.diagnostics()[0].location, (SourceLocation{h.id("b.h"), 2, 3}));
    EXPECT_EQ(h.diagnostics.diagnostics()[0].notes.size(), 1u);
}

TEST(IncludeResolver, ReportsErrorColumnsOnARootsFirstLineFromItsOrigin) {
    Harness h;
    h.file("s.shader", lines({"Pass {", "    CGPROGRAM #include \"nope.h\"", "    ENDCG"}));
    auto expanded = h.expand({h.root("s.shader", " #include \"nope.h\"\n", 2, 14)});
    EXPECT_FALSE(expanded.has_value());
    ASSERT_EQ(h.diagnostics.diagnostics().size(), 1u);
    EXPECT_EQ(h.diagnostics.diagnostics()[0].location, (SourceLocation{h.id("s.shader"), 2, 24}));
}

}  // namespace
}  // namespace varc::includes
