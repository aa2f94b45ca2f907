// SPDX-License-Identifier: Apache-2.0
// Finds textures and samplers declared as struct members, which glslang cannot compile for Vulkan.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace varc::frontend {

// A struct member of a texture or sampler type, in the original file's coordinates (through the
// preprocessed text's `#line <line> <fileId>` directives).
struct OpaqueStructMember {
    std::string structName;  // "TextureAndSampler"
    std::string type;        // "Texture2D", "SamplerState", ...
    std::string member;      // the member's name
    size_t file = 0;         // the FileId of the last #line before it (0 without one)
    size_t line = 0;         // 1-based line there
};

// glslang's HLSL texture-sampler transform (EShTexSampTransUpgradeTextureRemoveSampler, which
// gives Vulkan combined image samplers) turns global textures into sampled images but leaves a
// struct member typed as a plain image, so a struct holding a `Texture2D` and a `SamplerState`
// that reaches a sample call yields an invalid module. The driver calls this after the validator
// refused glslang's module, to name the construct at the user's line instead of the validator's
// instruction. Returns the first member (in text order) of any struct whose type is one of
// HLSL's separate texture or sampler objects (`Texture2D`, `Texture2DArray<float4>`,
// `TextureCube`, `SamplerState`, `SamplerComparisonState`, ...), or nullopt. Cg's combined
// `sampler2D` and storage textures (`RWTexture2D`) compile inside structs and are not reported.
// Example: "struct S { Texture2D t; SamplerState s; };" -> {"S", "Texture2D", "t"}.
std::optional<OpaqueStructMember> findOpaqueStructMember(std::string_view preprocessed);

// |preprocessed| with every struct member of type Texture1D, Texture2D, Texture3D or TextureCube
// (template arguments included) declared as the matching Cg combined sampler (sampler1D,
// sampler2D, sampler3D, samplerCUBE), padded with blanks so every later column stays put. Under
// the texture-sampler transform a global texture is such a combined sampler, so assigning it to
// the member, and sampling the member (`.Sample(s, uv)`, `tex2D`), then type-check; the struct's
// SamplerState members are left as written (the transform ignores the sampler argument). The
// driver retries with this text only after the validator refused glslang's module. Unchanged
// when there is no such member. Example: "struct S { Texture2D<float4> t; };" ->
// "struct S { sampler2D        t; };".
std::string combineStructTextureMembers(std::string_view preprocessed);

}  // namespace varc::frontend
