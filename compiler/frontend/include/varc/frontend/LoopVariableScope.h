// SPDX-License-Identifier: Apache-2.0
// The DirectX compilers' scope for a variable declared in a `for` header.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace varc::frontend {

// fxc (and so Unity) puts a variable declared in a `for` header in the enclosing block, as
// Direct3D 9 HLSL did: code after the loop may use it, and a second loop may declare it again
// (warning X3078). glslang scopes it to the loop like C++ and reports "unknown variable".
// For each name in |unknownNames| (the names glslang reported unknown), this declares the loop
// variable once at its first loop, in that loop's block, and turns every header declaration of
// it in that block into an assignment:
//   "{ for (int i = 0; i < 2; i++) a += i; for (i = 1; i < 3; i++) b += i; }" ->
//   "{ int i; for ( i = 0; i < 2; i++) a += i; for (i = 1; i < 3; i++) b += i; }".
// Left alone: headers that declare several variables (`int i = 0, j = 0`), a loop whose type
// differs from the first one's, and blocks that also declare the name outside a `for` header.
// No line is added or removed. Returns |text| unchanged when nothing applies.
std::string hoistLoopVariables(std::string_view text, const std::vector<std::string>& unknownNames);

}  // namespace varc::frontend
