// SPDX-License-Identifier: Apache-2.0
// CallSite: the default argument captures the caller's file and line.
#include "varc/core/CallSite.h"

#include <gtest/gtest.h>

#include <string_view>

namespace varc {
namespace {

CallSite whereCalled(CallSite where = CallSite::current()) { return where; }

TEST(CallSite, ADefaultArgumentNamesTheCaller) {
    unsigned line = __LINE__ + 1;
    CallSite site = whereCalled();
    EXPECT_EQ(site.line(), line);
    EXPECT_TRUE(std::string_view(site.fileName()).ends_with("CallSiteTest.cpp"));
}

}  // namespace
}  // namespace varc
