// SPDX-License-Identifier: Apache-2.0
// Source rewrites that let glslang's HLSL front end accept what Unity's HLSL compilers accept.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace varc::frontend {

// Rewrites a preprocessed HLSL program (no macros left, `#line` directives allowed) so glslang
// compiles constructs that the DirectX compilers accept and glslang refuses:
//
//  * `switch` on a non-integer: `switch (f)` -> `switch ((int)(f))`, the conversion the DirectX
//    compilers apply. A switch whose case labels carry a `u` suffix is left alone (its
//    condition is unsigned already).
//  * A uniform written by the code: a non-static, non-const global, or a member of a file-scope
//    cbuffer (Unity declares its built-ins such as _LightColor0 as loose globals; varc's library
//    groups them in cbuffers). DirectX treats a written global as a per-invocation copy
//    initialised from the uniform. The rewrite makes that copy explicit: after the declaration
//    `float _Speed;` (after the cbuffer's closing brace for a member) comes
//    ` static float _Speed_varcCopy = _Speed;` on the same line, and every other use of the name
//    (outside struct and cbuffer bodies, not after a `.`) is renamed to the copy. The uniform
//    keeps its name, so reflection and binding by name are unchanged. Arrays and declarations
//    with initialisers are left alone.
//  * A `uniform` function parameter written by the body (`float4 frag(v2f i, uniform float4
//    _Tint) { _Tint.a = 1; ... }`), which DirectX treats as a global and so as a per-invocation
//    copy: the body starts, on the line of its `{`, with ` float4 _Tint_varcCopy = _Tint;` and
//    its uses of the name are renamed to the copy. Other parameters are copies in glslang too.
//  * With |scalarAnyAll|: `any(x)` and `all(x)` of a scalar, which DirectX reads as `x != 0` and
//    glslang compiles to OpAny/OpAll on a scalar (invalid SPIR-V). Scalar overloads
//    `bool any(float v) { return v != 0; } ...` (bool, int, uint, float; any and all) are declared
//    before the first token, on its line; glslang picks them for scalars only. The caller asks
//    for them when the validator refused OpAny/OpAll on a scalar.
//
//  * Matrix swizzles of several elements, which glslang does not implement:
//    `M._m20_m21_m22` -> `float3(M[2][0], M[2][1], M[2][2])` (also the one-based `M._11_22`),
//    for a matrix named by one identifier.
//
//  * Hexadecimal literals wider than 32 bits keep their low 32 bits, as the DirectX compilers
//    do: `0x1376312589U` -> `0x76312589U`.
//  * Empty member declarations (a lone `;` in a struct or cbuffer, often a macro that expanded
//    to nothing) are removed.
//  * A local named in its own initializer, which HLSL puts in scope there (uninitialised):
//    `Out o = f(o, p);` -> `Out o; o = f(o, p);` (one declarator, not const or static).
//  * Textures, samplers and buffers declared in a file-scope cbuffer, which the DirectX
//    compilers take as globals and glslang as members (invalid in Vulkan): each declaration
//    moves to just before the `cbuffer` keyword, on that line, and is blanked where it was.
//  * Calls of the functions named in |unmatchedCalls| (those glslang found no overload for):
//    each argument is cast to its parameter's numeric type, `Linear01Depth(tex2D(t, uv))` ->
//    `Linear01Depth((float)(tex2D(t, uv)))`, the implicit truncation the DirectX compilers
//    apply. Functions with overloads, and out/inout, struct and resource parameters, are left.
//
// No line is added or removed, so every `#line` mapping still holds. Returns |text| unchanged
// when there is nothing to rewrite or the text cannot be tokenised.
// Example: "float _T;\nfloat4 f() : SV_Target { _T *= 2; switch (_T) { default: break; }
// return _T; }" -> "float _T; static float _T_varcCopy = _T;\nfloat4 f() : SV_Target {
// _T_varcCopy *= 2; switch ((int)(_T_varcCopy)) { default: break; } return _T_varcCopy; }".
std::string rewriteHlslForGlslang(std::string_view text,
                                  const std::vector<std::string>& unmatchedCalls = {},
                                  bool scalarAnyAll = false);

// |text| with each hexadecimal literal wider than 32 bits cut to its low 32 bits, anywhere
// (directives and comments included): for text before preprocessing, where glslang's
// preprocessor already refuses such a literal. "x = 0x1376312589U;" -> "x = 0x76312589U;".
std::string truncateWideHexLiterals(std::string_view text);

// |text| with every `T name : SV_IsFrontFace` parameter of a type other than bool declared bool
// (`uint facing : SV_IsFrontFace`, accepted by the DirectX compilers): Vulkan's FrontFacing
// built-in is a bool and glslang would emit invalid SPIR-V. A Direct3D 9 face parameter
// `half facing : VFACE` (a float: positive on front faces, negative on back faces, which glslang
// would take for an interpolator) becomes `bool facing_varcFrontFace : SV_IsFrontFace`, and the
// function body starts with `half facing = facing_varcFrontFace ? 1 : -1;` on the same line.
// Text without SV_IsFrontFace or VFACE is returned unchanged.
std::string fixFrontFaceParameterTypes(std::string_view text);

}  // namespace varc::frontend
