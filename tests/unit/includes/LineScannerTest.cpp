// SPDX-License-Identifier: Apache-2.0
// LineScanner (private): logical lines, comment state, directive classification and guards.
#include <gtest/gtest.h>

#include "LineScanner.h"

namespace varc::includes {
namespace {

TEST(LineScanner, JoinsContinuationsIntoOneLogicalLine) {
    ScannedFile file = LineScanner::scan("a \\\n b\n#define X \\\r\n 1\nc");
    ASSERT_EQ(file.lines.size(), 3u);
    EXPECT_EQ(file.lines[0].firstLine, 0u);
    EXPECT_EQ(file.lines[0].lastLine, 1u);
    EXPECT_EQ(file.lines[1].firstLine, 2u);
    EXPECT_EQ(file.lines[1].lastLine, 3u);
    EXPECT_TRUE(file.lines[1].isDirective);
    EXPECT_EQ(file.lines[1].directive.kind, DirectiveKind::Define);
    EXPECT_EQ(file.lines[2].firstLine, 4u);
    EXPECT_EQ(file.physicalLine(3), " 1");
}

// Found by the include fuzzer: a backslash-newline that ends the file joins nothing, so every
// logical line stays within the physical lines (physicalLine() checks it).
TEST(LineScanner, AContinuationAtTheEndOfTheTextJoinsNoFurtherLine) {
    for (const char* text : {"#define X \\\n", "a\nb \\\r\n", "\\\n"}) {
        ScannedFile file = LineScanner::scan(text);
        ASSERT_FALSE(file.lines.empty()) << text;
        for (const LogicalLine& line : file.lines) {
            EXPECT_LT(line.lastLine, file.lineStarts.size()) << text;
            (void)file.physicalLine(line.lastLine);
        }
    }
}

TEST(LineScanner, TellsDirectivesFromCommentsAndCode) {
    ScannedFile file = LineScanner::scan(
        "/* #include \"a\" */\n"           // 0: comment only
        "/* open\n"                        // 1
        "#include \"b\"\n"                 // 2: inside the comment
        "*/ #include \"c\"\n"              // 3: comment closed, '#' is the first token
        "x /* open\n"                      // 4
        "*/ #include \"d\"\n"              // 5: "x" precedes on the logical line
        "  /**/ # include <e f> // c\n");  // 6
    ASSERT_EQ(file.lines.size(), 7u);
    EXPECT_FALSE(file.lines[0].isDirective);
    EXPECT_TRUE(file.lines[0].blank);
    EXPECT_FALSE(file.lines[2].isDirective);
    EXPECT_TRUE(file.lines[2].startsInComment);
    ASSERT_TRUE(file.lines[3].isDirective);
    EXPECT_EQ(file.lines[3].directive.argument, "c");
    EXPECT_TRUE(file.lines[3].startsInComment);
    EXPECT_FALSE(file.lines[5].isDirective);
    ASSERT_TRUE(file.lines[6].isDirective);
    EXPECT_EQ(file.lines[6].directive.kind, DirectiveKind::Include);
    EXPECT_EQ(file.lines[6].directive.argument, "e f");
    EXPECT_TRUE(file.lines[6].directive.angled);
    EXPECT_FALSE(file.unterminatedComment.has_value());
}

TEST(LineScanner, ReportsOffsetsAsLineAndColumn) {
    ScannedFile file = LineScanner::scan("x\n\t#include  \"n.h\"\n");
    ASSERT_EQ(file.lines.size(), 2u);
    const Directive& directive = file.lines[1].directive;
    ScannedFile::Position hash = file.position(directive.hashOffset);
    ScannedFile::Position name = file.position(directive.argumentOffset);
    EXPECT_EQ(hash.lineIndex, 1u);
    EXPECT_EQ(hash.column, 2u);
    EXPECT_EQ(name.column, 12u);  // tab, "#include", two blanks
}

TEST(LineScanner, ClassifiesConditionalsAndGuardCandidates) {
    ScannedFile file = LineScanner::scan(
        "#if !defined(A)\n#if defined(A)\n#ifdef B\n#elif C\n#else\n#endif\n#pragma  once \n");
    ASSERT_EQ(file.lines.size(), 7u);
    EXPECT_EQ(file.lines[0].directive.kind, DirectiveKind::If);
    EXPECT_EQ(file.lines[0].directive.argument, "A");
    EXPECT_EQ(file.lines[1].directive.argument, "");
    EXPECT_EQ(file.lines[2].directive.kind, DirectiveKind::Ifdef);
    EXPECT_EQ(file.lines[3].directive.kind, DirectiveKind::Else);
    EXPECT_EQ(file.lines[4].directive.kind, DirectiveKind::Else);
    EXPECT_EQ(file.lines[5].directive.kind, DirectiveKind::Endif);
    EXPECT_EQ(file.lines[6].directive.kind, DirectiveKind::Pragma);
    EXPECT_EQ(file.lines[6].directive.argument, "once");
}

TEST(LineScanner, DetectsMacroGuardLines) {
    ScannedFile file =
        LineScanner::scan("// c\n#ifndef A_H\n#define A_H\nint a;\n#endif // A_H\n\n");
    EXPECT_EQ(file.guard.kind, GuardKind::Macro);
    EXPECT_EQ(file.guard.macro, "A_H");
    EXPECT_EQ(file.guard.openLine, 1u);
    EXPECT_EQ(file.guard.closeLine, 4u);
}

TEST(LineScanner, RecordsUnterminatedBlockComment) {
    ScannedFile file = LineScanner::scan("a\nb /* open\nc\n");
    ASSERT_TRUE(file.unterminatedComment.has_value());
    EXPECT_EQ(*file.unterminatedComment, 4u);
    EXPECT_TRUE(file.lines[2].endsInComment);
}

}  // namespace
}  // namespace varc::includes
