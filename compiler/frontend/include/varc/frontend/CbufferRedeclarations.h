// SPDX-License-Identifier: Apache-2.0
// Finds a global that redeclares a cbuffer member with another type, which crashes glslang.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace varc::frontend {

// A file-scope variable whose name a file-scope cbuffer already declares with another type, in
// the original file's coordinates (through `#line <line> <fileId>`).
struct CbufferRedeclaration {
    std::string name;         // "_LightColor0"
    std::string type;         // as the global declares it: "fixed3"
    std::string memberType;   // as the cbuffer declares it: "half4"
    std::string cbufferName;  // "UnityLighting"; empty when the first declaration is a global
    size_t file = 0;          // the FileId of the last #line before the global (0 without one)
    size_t line = 0;          // 1-based line there
};

// glslang's HLSL front end dereferences a null pointer (TParseContextBase::growGlobalUniformBlock)
// when a global such as `fixed3 _LightColor0;` redeclares, with another type, a member of a
// cbuffer (varc's UnityShaderVariables.cginc declares `half4 _LightColor0` in cbuffer
// UnityLighting), which would end the whole build; found by the `build` fuzz target. This finds
// the first such global in the preprocessed HLSL |preprocessed| so the driver can report it
// instead; two globals of one name and different types (`float3 _A; float4 _A;`, also a crash)
// count too. Types are compared by shape: the float precisions (float, half, fixed, min16float,
// min10float) are one type, so `fixed4 _LightColor0;` (which glslang accepts) is not reported.
// nullopt when there is none. Example: "cbuffer B { half4 c; }; fixed3 c;" -> {"c", "fixed3",
// "half4", "B", 0, 1}.
std::optional<CbufferRedeclaration> findCbufferRedeclaration(std::string_view preprocessed);

}  // namespace varc::frontend
