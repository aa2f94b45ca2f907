// SPDX-License-Identifier: Apache-2.0
// The in-memory model of a pack, shared by the writer (compiler) and the reader (runtime).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "varc/core/Stage.h"
#include "varc/pack/PackRenderState.h"
#include "varc/pack/ProgramReflection.h"
#include "varc/variants/VariantKey.h"

namespace varc::pack {

// A variant's program in a stage slot that has none.
inline constexpr uint32_t kNoProgram = 0xffffffffu;

// Where a program came from, for runtime error messages (variant -> program -> file:line).
struct SourceInfo {
    std::string file;                       // the .shader (or .glsl) file of the program block
    uint32_t line = 0;                      // line of the program block (CGPROGRAM), 1-based
    std::vector<std::string> dependencies;  // every file included while compiling it
    friend bool operator==(const SourceInfo&, const SourceInfo&) = default;
};

// One compiled stage program. Programs are shared by every variant that compiles to them.
struct PackProgram {
    Stage stage = Stage::Vertex;
    std::string entryPoint;       // "vert"
    std::vector<uint32_t> spirv;  // the module's words
    ProgramReflection reflection;
    SourceInfo source;
    friend bool operator==(const PackProgram&, const PackProgram&) = default;
};

struct PackVariant {
    variants::VariantKey key;  // bits index PackPass::keywordTable
    // Per stage slot: index into PackContents::programs, or kNoProgram.
    std::array<uint32_t, kStageCount> programs{kNoProgram, kNoProgram, kNoProgram, kNoProgram,
                                               kNoProgram};
    friend bool operator==(const PackVariant&, const PackVariant&) = default;
};

// A declared keyword set: `#pragma multi_compile_local _ FOO BAR` is
// {"multi_compile_local", {"", "FOO", "BAR"}} ("" = the no-keyword option). A
// `dynamic_branch[_local]` set makes no variants and its keywords are not in the keyword table:
// each is a uniform integer of the pass's programs, named like the keyword, that a draw sets to
// 1 when it enables the keyword and to 0 otherwise (docs/KEYWORDS.md §12).
struct DeclaredSet {
    std::string directive;
    std::vector<std::string> keywords;
    friend bool operator==(const DeclaredSet&, const DeclaredSet&) = default;
};

// Whether |directive| declares dynamic_branch keywords ("dynamic_branch", "dynamic_branch_local").
inline bool isDynamicBranchDirective(std::string_view directive) {
    return directive.starts_with("dynamic_branch");
}

struct PackPass {
    uint32_t index = 0;     // the pass's position in its source shader
    std::string name;       // `Name "..."`, "" if none
    std::string lightMode;  // the LightMode tag, "" if none
    std::vector<std::pair<std::string, std::string>> tags;  // declaration order
    PackRenderState state;
    std::vector<std::string> keywordTable;  // sorted, unique, <= 256; bit i = keyword i
    std::vector<DeclaredSet> sets;          // variant sets in declaration order, then the
                                            // dynamic_branch sets in declaration order
    std::vector<PackVariant> variants;      // Unity's enumeration order; keys unique
    friend bool operator==(const PackPass&, const PackPass&) = default;
};

// What a ShaderLab property holds by default: Float (Float, Range, Int, Integer), Vector,
// Color or a texture (2D, 3D, Cube, arrays).
enum class PropertyKind : uint8_t { Float = 0, Vector = 1, Color = 2, Texture = 3 };
inline constexpr uint32_t kPropertyKindCount = 4;

// One entry of a shader's `Properties` block, with its default value.
struct ShaderProperty {
    std::string name;  // "_Color"
    PropertyKind kind = PropertyKind::Float;
    std::array<float, 4> value{};  // Float: value[0]; Vector, Color: xyzw; Texture: 0
    std::string texture;           // Texture: the default's name ("white", "bump", ...; "" none)
    friend bool operator==(const ShaderProperty&, const ShaderProperty&) = default;
};

struct PackShader {
    std::string name;  // `Shader "Custom/Name"`
    std::vector<PackPass> passes;
    std::vector<ShaderProperty> properties;  // declaration order
    friend bool operator==(const PackShader&, const PackShader&) = default;
};

struct ToolVersion {
    std::string name;     // "varc", "glslang", "SPIRV-Tools", "zstd"
    std::string version;  // "0.1.0"
    friend bool operator==(const ToolVersion&, const ToolVersion&) = default;
};

// Everything a pack holds. The writer renumbers programs in first-use order (shader, pass,
// variant in enumeration order, stage) after merging equal ones, and drops unused programs; a
// reader's decodePack() returns that normalised form.
struct PackContents {
    std::vector<ToolVersion> toolchain;
    uint64_t inputsHash = 0;  // hash of every input of the build (sources, options, versions)
    std::vector<PackShader> shaders;
    std::vector<PackProgram> programs;
    friend bool operator==(const PackContents&, const PackContents&) = default;
};

}  // namespace varc::pack
