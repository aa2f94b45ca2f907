// SPDX-License-Identifier: Apache-2.0
// SourcePathMap: the paths a pack records, relative to the project root and through prefix maps.
#include "varc/includes/SourcePathMap.h"

#include <gtest/gtest.h>

namespace varc::includes {
namespace {

TEST(SourcePathMap, WithoutRootOrRulesPathsAreRecordedAsRead) {
    SourcePathMap map;
    EXPECT_EQ(map.map("/src/game/a.shader"), "/src/game/a.shader");
    EXPECT_EQ(map.map("../x.cginc"), "../x.cginc");
}

TEST(SourcePathMap, AbsolutePathsInsideTheRootBecomeRelative) {
    SourcePathMap map("/src/game");
    EXPECT_EQ(map.map("/src/game/Assets/a.shader"), "Assets/a.shader");
    EXPECT_EQ(map.map("/src/game/./Assets/../Assets/a.shader"), "Assets/a.shader");
    EXPECT_EQ(map.map("/src/gamey/a.shader"), "/src/gamey/a.shader");  // not inside
    EXPECT_EQ(map.map("/opt/sdk/b.cginc"), "/opt/sdk/b.cginc");
    EXPECT_EQ(map.map("Assets/a.shader"), "Assets/a.shader");  // relative: as read
}

TEST(SourcePathMap, PrefixRulesMatchWholeComponentsAndTheLastOneWins) {
    SourcePathMap map("/src/game");
    ASSERT_TRUE(map.addRule("/opt/sdk=sdk"));
    EXPECT_EQ(map.map("/opt/sdk/inc/b.cginc"), "sdk/inc/b.cginc");
    EXPECT_EQ(map.map("/opt/sdkx/b.cginc"), "/opt/sdkx/b.cginc");
    ASSERT_TRUE(map.addRule("/opt/sdk/inc=include"));
    EXPECT_EQ(map.map("/opt/sdk/inc/b.cginc"), "include/b.cginc");
    ASSERT_TRUE(map.addRule("/src/game=/game"));  // a rule comes before the root
    EXPECT_EQ(map.map("/src/game/a.shader"), "/game/a.shader");
    ASSERT_TRUE(map.addRule("/empty="));
    EXPECT_EQ(map.map("/empty/a.shader"), "/a.shader");
}

TEST(SourcePathMap, RulesNeedAnEqualsSignAndAnOldPrefix) {
    SourcePathMap map;
    EXPECT_FALSE(map.addRule("/opt/sdk"));
    EXPECT_FALSE(map.addRule("=sdk"));
    EXPECT_EQ(map.map("/opt/sdk/a"), "/opt/sdk/a");
}

}  // namespace
}  // namespace varc::includes
