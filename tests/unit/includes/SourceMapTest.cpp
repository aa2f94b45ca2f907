// SPDX-License-Identifier: Apache-2.0
// SourceMap: ids by normalised path, line lookup and location formatting.
#include <gtest/gtest.h>

#include "varc/includes/SourceMap.h"

namespace varc::includes {
namespace {

TEST(SourceMap, GivesDenseIdsAndReusesThemForTheSameNormalisedPath) {
    SourceMap map;
    FileId a = map.addFile("dir/a.h", "first");
    FileId b = map.addFile("b.h", "b");
    EXPECT_EQ(a, 0u);
    EXPECT_EQ(b, 1u);
    EXPECT_EQ(map.addFile("dir/./x/../a.h", "second"), a);
    EXPECT_EQ(map.contents(a), "first");
    EXPECT_EQ(map.path(a), "dir/a.h");
    EXPECT_EQ(map.size(), 2u);
    EXPECT_EQ(map.find("./dir/a.h"), a);
    EXPECT_FALSE(map.find("c.h").has_value());
}

TEST(SourceMap, ReturnsLineTextWithoutLineEnds) {
    SourceMap map;
    FileId id = map.addFile("a.h", "one\r\ntwo\n\nlast");
    EXPECT_EQ(map.lineText(id, 1), "one");
    EXPECT_EQ(map.lineText(id, 2), "two");
    EXPECT_EQ(map.lineText(id, 3), "");
    EXPECT_EQ(map.lineText(id, 4), "last");
    EXPECT_EQ(map.lineText(id, 5), "");
    EXPECT_EQ(map.lineText(id, 0), "");
    EXPECT_EQ(map.lineText(kNoFile, 1), "");
    FileId trailing = map.addFile("b.h", "x\n");
    EXPECT_EQ(map.lineText(trailing, 1), "x");
    EXPECT_EQ(map.lineText(trailing, 2), "");
}

TEST(SourceMap, FormatsLocationsClangStyle) {
    SourceMap map;
    FileId id = map.addFile("shaders/My Lighting.cginc", "x\n");
    EXPECT_EQ(map.format({id, 12, 5}), "shaders/My Lighting.cginc:12:5");
    EXPECT_EQ(map.format({id, 12, 0}), "shaders/My Lighting.cginc:12");
    EXPECT_EQ(map.format({kNoFile, 12, 5}), "<unknown>");
    EXPECT_EQ(map.format({}), "<unknown>");
}

}  // namespace
}  // namespace varc::includes
