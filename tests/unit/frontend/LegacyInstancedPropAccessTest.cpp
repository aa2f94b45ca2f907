// SPDX-License-Identifier: Apache-2.0
// expandLegacyInstancedPropAccess: Unity 5.6's one-argument UNITY_ACCESS_INSTANCED_PROP.
#include <gtest/gtest.h>

#include "varc/frontend/LegacyInstancedPropAccess.h"

namespace varc::frontend {
namespace {

TEST(LegacyInstancedPropAccess, OneArgumentCallsGetABlockName) {
    EXPECT_EQ(expandLegacyInstancedPropAccess(
                  "float4 c = UNITY_ACCESS_INSTANCED_PROP(_Color) * UNITY_ACCESS_INSTANCED_PROP ( "
                  "_Tint[f(1, 2)] );"),
              "float4 c = UNITY_ACCESS_INSTANCED_PROP(UnityLegacyInstancedProps, _Color) * "
              "UNITY_ACCESS_INSTANCED_PROP (UnityLegacyInstancedProps,  _Tint[f(1, 2)] );");
}

TEST(LegacyInstancedPropAccess, TwoArgumentCallsOtherNamesAndBrokenCallsStayAsWritten) {
    for (std::string text :
         {"UNITY_ACCESS_INSTANCED_PROP(Props, _Color)", "MY_UNITY_ACCESS_INSTANCED_PROP(_Color)",
          "UNITY_ACCESS_INSTANCED_PROPS(_Color)", "UNITY_ACCESS_INSTANCED_PROP()",
          "UNITY_ACCESS_INSTANCED_PROP(_Color", "#define A UNITY_ACCESS_INSTANCED_PROP\n",
          "UNITY_ACCESS_INSTANCED_PROP(Props, f(_Color))"}) {
        EXPECT_EQ(expandLegacyInstancedPropAccess(text), text) << text;
    }
}

}  // namespace
}  // namespace varc::frontend
