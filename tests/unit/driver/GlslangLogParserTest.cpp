// SPDX-License-Identifier: Apache-2.0
// parseGlslangLog maps glslang's "ERROR: file:line:" lines back to files, lines and columns.
#include <gtest/gtest.h>

#include "varc/driver/GlslangLogParser.h"

namespace varc::driver {
namespace {

class GlslangLogParserTest : public ::testing::Test {
protected:
    void SetUp() override {
        mSourceMap.addFile("a.shader", "line one\nline two\n");
        mSourceMap.addFile("inc/b.cginc", "float4 x;\nfloat4 y = foo + bar;\n");
    }
    includes::SourceMap mSourceMap;
};

TEST_F(GlslangLogParserTest, MapsFileIdLineAndRecoversColumnFromQuotedToken) {
    auto diagnostics = parseGlslangLog("ERROR: 1:2: 'bar' : undeclared identifier \n", mSourceMap);
    ASSERT_EQ(diagnostics.size(), 1u);
    EXPECT_EQ(diagnostics[0].severity, Severity::Error);
    EXPECT_EQ(diagnostics[0].location, (SourceLocation{1, 2, 18}));
    EXPECT_EQ(diagnostics[0].message, "undeclared identifier 'bar'");
}

TEST_F(GlslangLogParserTest, ColumnMatchesWholeWordsOnly) {
    // 'y' appears inside no other identifier before its declaration column.
    auto diagnostics = parseGlslangLog("WARNING: 1:2: 'y' : something odd\n", mSourceMap);
    ASSERT_EQ(diagnostics.size(), 1u);
    EXPECT_EQ(diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(diagnostics[0].location.column, 8u);
}

TEST_F(GlslangLogParserTest, UnknownTokenGivesColumnZero) {
    auto diagnostics = parseGlslangLog("ERROR: 0:1: '' : syntax error\n", mSourceMap);
    ASSERT_EQ(diagnostics.size(), 1u);
    EXPECT_EQ(diagnostics[0].location, (SourceLocation{0, 1, 0}));
    EXPECT_EQ(diagnostics[0].message, "syntax error");
}

TEST_F(GlslangLogParserTest, DropsSummaryLinesAndDuplicates) {
    auto diagnostics = parseGlslangLog(
        "ERROR: 1:2: 'foo' : undeclared identifier\n"
        "ERROR: 1:2: 'foo' : undeclared identifier\n"
        "(16): error at column 86, HLSL parsing failed.\n"
        "ERROR: 2 compilation errors.  No code generated.\n",
        mSourceMap);
    ASSERT_EQ(diagnostics.size(), 1u);
    EXPECT_EQ(diagnostics[0].location.column, 12u);
}

TEST_F(GlslangLogParserTest, UnmappableFileKeepsTextWithoutLocation) {
    auto diagnostics = parseGlslangLog("ERROR: 9:3: 'x' : bad\nLinking failed oddly\n", mSourceMap);
    ASSERT_EQ(diagnostics.size(), 2u);
    EXPECT_FALSE(diagnostics[0].location.isKnown());
    EXPECT_NE(diagnostics[0].message.find("9:3"), std::string::npos);
    EXPECT_EQ(diagnostics[1].message, "Linking failed oddly");
}

}  // namespace
}  // namespace varc::driver
