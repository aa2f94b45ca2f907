// SPDX-License-Identifier: Apache-2.0
// Source rewrites that let glslang's HLSL front end accept what Unity's HLSL compilers accept.
#pragma once

#include <string>
#include <string_view>

namespace varc::compiler {

// Rewrites a preprocessed HLSL program (no macros left, `#line` directives allowed) so glslang
// compiles two constructs that the DirectX compilers accept and glslang refuses:
//
//  * `switch` on a non-integer: `switch (f)` -> `switch ((int)(f))`, the conversion the DirectX
//    compilers apply. A switch whose case labels carry a `u` suffix is left alone (its
//    condition is unsigned already).
//  * A loose uniform (a non-static, non-const global outside any cbuffer) written by the code:
//    DirectX treats such a global as a per-invocation copy initialised from the uniform. The
//    rewrite makes that copy explicit: after the declaration `float _Speed;` comes
//    ` static float _Speed_varcCopy = _Speed;` on the same line, and every other use of the name
//    (outside struct and cbuffer bodies, not after a `.`) is renamed to the copy. The uniform
//    keeps its name, so reflection and binding by name are unchanged. Arrays and declarations
//    with initialisers are left alone.
//
// No line is added or removed, so every `#line` mapping still holds. Returns |text| unchanged
// when there is nothing to rewrite or the text cannot be tokenised.
// Example: "float _T;\nfloat4 f() : SV_Target { _T *= 2; switch (_T) { default: break; }
// return _T; }" -> "float _T; static float _T_varcCopy = _T;\nfloat4 f() : SV_Target {
// _T_varcCopy *= 2; switch ((int)(_T_varcCopy)) { default: break; } return _T_varcCopy; }".
std::string rewriteHlslForGlslang(std::string_view text);

}  // namespace varc::compiler
