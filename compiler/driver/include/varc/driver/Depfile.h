// SPDX-License-Identifier: Apache-2.0
// Make-style dependency files (`varc build --depfile`), for build systems such as CMake/Ninja.
#pragma once

#include <string>
#include <vector>

namespace varc::driver {

// "out.svpack: a.shader My\ Lighting.cginc\n": |target| followed by every dependency, with
// spaces, '#' and '$' escaped the way Make and Ninja read them. Dependencies keep their order;
// duplicates are dropped.
std::string makeDepfile(const std::string& target, const std::vector<std::string>& dependencies);

}  // namespace varc::driver
