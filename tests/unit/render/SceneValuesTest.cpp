// SPDX-License-Identifier: Apache-2.0
// SceneValues: the per-draw values of dynamic_branch keywords.
#include <gtest/gtest.h>

#include "varc/render/SceneValues.h"

namespace varc::render {
namespace {

float valueOf(const ShaderValues& values, std::string_view name) {
    const ShaderValue* value = values.find(name);
    return value && value->data.size() == 1 ? value->data[0] : -1.0f;
}

TEST(SceneValues, DynamicBranchKeywordsAreOneWhenEnabledAndZeroOtherwise) {
    ShaderValues values;
    values.set("_Color", 0.5f);
    setDynamicBranchValues(values, {"GREEN", "RED"}, {"RED", "_FOG", "HALF"});
    EXPECT_EQ(valueOf(values, "RED"), 1.0f);
    EXPECT_EQ(valueOf(values, "GREEN"), 0.0f);
    EXPECT_FALSE(values.find("_FOG"));  // not dynamic: it selects a variant instead
    EXPECT_FALSE(values.find("HALF"));
    EXPECT_EQ(valueOf(values, "_Color"), 0.5f);
    EXPECT_EQ(values.size(), 3u);
}

TEST(SceneValues, DynamicBranchValuesReplaceTheStateOfAnEarlierDraw) {
    ShaderValues values;
    setDynamicBranchValues(values, {"RED"}, {"RED"});
    setDynamicBranchValues(values, {"RED"}, {});
    EXPECT_EQ(valueOf(values, "RED"), 0.0f);
}

}  // namespace
}  // namespace varc::render
