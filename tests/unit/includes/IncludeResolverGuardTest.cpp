// SPDX-License-Identifier: Apache-2.0
// IncludeResolver: include guards (#pragma once, #ifndef/#define/#endif) and conditional depth.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "IncludeTestSupport.h"
#include "varc/includes/IncludeResolver.h"

namespace varc::includes {
namespace {

using testing::Harness;
using testing::lines;

// How many times the file at |path| was spliced, counted by its line 1 in the output.
size_t splices(const Harness& h, const ExpandedSource& expanded, const std::string& path) {
    size_t count = 0;
    for (const testing::MappedLine& line : testing::linesFrom(expanded.text, h.sourceMap, path)) {
        if (line.line == 1) ++count;
    }
    return count;
}

TEST(IncludeResolver, SplicesGuardedFileOnce) {
    Harness h;
    h.file("m.shader", lines({"#include \"g.h\"", "mid", "#include \"g.h\"", "end"}))
        .file("g.h", lines({"#ifndef G_H", "#define G_H", "G", "#endif"}));
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_EQ(expanded->text, lines({"#line 1 0", "#line 1 1", "#ifndef G_H", "#define G_H", "G",
                                     "#endif", "#line 2 0", "mid", "#line 4 0", "end"}));
}

TEST(IncludeResolver, SplicesPragmaOnceFileOnce) {
    Harness h;
    h.file("m.shader", lines({"#include \"g.h\"", "#include \"g.h\"", "end"}))
        .file("g.h", lines({"// comment first", "", "#pragma once", "G"}));
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_EQ(splices(h, *expanded, "g.h"), 1u);
    EXPECT_TRUE(h.mapsBack(*expanded));
}

TEST(IncludeResolver, RecognisesIfNotDefinedGuardSpellings) {
    std::vector<std::string> openers = {"#ifndef G", "#if !defined(G)", "#if !defined G",
                                        "#  if ! defined ( G )", "#if !defined(G) // x"};
    for (const std::string& opener : openers) {
        SCOPED_TRACE(opener);
        Harness h;
        h.file("m.shader", lines({"#include \"g.h\"", "#include \"g.h\""}))
            .file("g.h", lines({"/* licence", "   text */", "", opener, "// why", "#define G 1",
                                "G", "#if defined(X)", "x", "#else", "y", "#endif", "#endif // G",
                                "// trailing"}));
        auto expanded = h.expandFile("m.shader");
        ASSERT_TRUE(expanded.has_value());
        EXPECT_EQ(splices(h, *expanded, "g.h"), 1u);
    }
}

TEST(IncludeResolver, SplicesFilesThatAreNotWhollyGuardedEveryTime) {
    std::vector<std::string> bodies = {
        lines({"U"}),
        lines({"#ifndef G", "#define G", "#endif", "float after;"}),
        lines({"float before;", "#ifndef G", "#define G", "#endif"}),
        lines({"#ifndef G", "#define G", "x", "#else", "y", "#endif"}),
        lines({"#ifndef G", "#define OTHER", "#endif"}),
        lines({"#ifndef G", "x", "#define G", "#endif"}),
        lines({"#if !defined(G) && defined(H)", "#define G", "#endif"}),
        lines({"#ifndef G", "#define G"}),
        lines({"int a;", "#pragma once"}),
    };
    for (const std::string& body : bodies) {
        SCOPED_TRACE(body);
        Harness h;
        h.file("m.shader", lines({"#include \"g.h\"", "#include \"g.h\""})).file("g.h", body);
        auto expanded = h.expandFile("m.shader");
        ASSERT_TRUE(expanded.has_value());
        EXPECT_EQ(splices(h, *expanded, "g.h"), 2u);
    }
}

TEST(IncludeResolver, GuardedFileFirstIncludedInsideIfIsSplicedAgain) {
    Harness h;
    h.file("m.shader", lines({"#if defined(A)", "#include \"g.h\"", "#endif", "#include \"g.h\"",
                              "#include \"g.h\""}))
        .file("g.h", lines({"#ifndef G", "#define G", "G", "#endif"}));
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    // Once inside #if A, once unconditionally; the third include is then a no-op.
    EXPECT_EQ(splices(h, *expanded, "g.h"), 2u);
    EXPECT_TRUE(h.mapsBack(*expanded));
}

TEST(IncludeResolver, CountsConditionalDepthAcrossFiles) {
    Harness h;
    h.file("m.shader", lines({"#ifdef A", "#include \"mid.h\"", "#endif", "#include \"g.h\""}))
        .file("mid.h", "#include \"g.h\"\n")
        .file("g.h", lines({"#pragma once", "G"}));
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_EQ(splices(h, *expanded, "g.h"), 2u);
}

TEST(IncludeResolver, DoesNotCountAFilesOwnGuardAsConditional) {
    Harness h;
    h.file("m.shader", lines({"#include \"a.h\"", "#include \"g.h\""}))
        .file("a.h", lines({"#if !defined(A_H)", "#define A_H", "#include \"g.h\"", "#endif"}))
        .file("g.h", lines({"#ifndef G_H", "#define G_H", "G", "#endif"}));
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_EQ(splices(h, *expanded, "g.h"), 1u);
}

TEST(IncludeResolver, WrapsPragmaOnceFileThatMayBeSplicedTwice) {
    Harness h;
    h.file("m.shader", lines({"#if A", "#include \"g.h\"", "#endif", "#include \"g.h\""}))
        .file("g.h", lines({"#pragma once", "G"}));
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_EQ(expanded->text,
              lines({"#line 1 0", "#if A", "#ifndef VARC_ONCE_1", "#define VARC_ONCE_1",
                     "#line 1 1", "#pragma once", "G", "#endif // VARC_ONCE_1", "#line 3 0",
                     "#endif", "#ifndef VARC_ONCE_1", "#define VARC_ONCE_1", "#line 1 1",
                     "#pragma once", "G", "#endif // VARC_ONCE_1"}));
    EXPECT_TRUE(h.mapsBack(*expanded));
}

TEST(IncludeResolver, GuardedFileIncludingItselfIsNotACycle) {
    Harness h;
    h.file("m.shader", "#include \"a.h\"\n")
        .file("a.h", lines({"#ifndef A_H", "#define A_H", "#include \"b.h\"", "A", "#endif"}))
        .file("b.h", lines({"#pragma once", "#include \"a.h\"", "#include \"b.h\"", "B"}));
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_TRUE(h.diagnostics.diagnostics().empty());
    EXPECT_EQ(splices(h, *expanded, "a.h"), 1u);
    EXPECT_EQ(splices(h, *expanded, "b.h"), 1u);
    EXPECT_TRUE(h.mapsBack(*expanded));
}

TEST(IncludeResolver, GuardedWholeFileRootCountsAsSpliced) {
    Harness h;
    h.file("root.cginc", lines({"#ifndef ROOT", "#define ROOT", "#include \"b.h\"", "R", "#endif"}))
        .file("b.h", "#include \"root.cginc\"\nB\n");
    auto expanded = h.expandFile("root.cginc");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_EQ(splices(h, *expanded, "root.cginc"), 1u);
    EXPECT_THAT(expanded->dependencies, ::testing::ElementsAre("b.h"));
}

}  // namespace
}  // namespace varc::includes
