// SPDX-License-Identifier: Apache-2.0
// Prunes a preprocessed program to the code one stage's entry point reaches.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace varc::frontend {

enum class ShaderDialect { Hlsl, Glsl };

struct PruneResult {
    std::string text;     // the pruned program, or the input when !pruned
    bool pruned = false;  // false: fell back to the input (could not parse safely)
    std::vector<std::string> keptFunctions;  // kept function names, original order, each once
};

// Keeps only what |entryPoint| reaches in |preprocessed| (the output of glslang's preprocessor:
// macros expanded, no #if left, `#line N` / `#line N M` directives), for |dialect|.
//
// Kept: the entry function and every overload of every function it calls, transitively; every
// global declaration named by something kept (global variables, `static const` tables, textures,
// samplers, cbuffer/tbuffer blocks whole, struct types through members and signatures, typedefs);
// every directive except #line, in place. The result compiles to the same SPIR-V as
// |preprocessed| up to result-id numbering (glslang also numbers removed code; compare after
// `spirv-opt --compact-ids`) and, in GLSL, unused constants. For that, declarations glslang
// emits even when unused are kept too:
//  * HLSL: loose uniforms (non-static, non-const, non-resource globals) all form the implicit
//    `$Global` block, so they are kept together as soon as one of them is reached.
//  * GLSL: every global variable except `const` ones (uniforms, in/out, interface blocks, private
//    globals), `precision` statements and default-layout declarations (`layout(...) in;`).
// Anything that cannot be classified is kept.
//
// Line mapping: input blank lines and removed code are dropped; a `#line <line>` or
// `#line <line> <source>` directive (the <source> exactly as the input wrote it, present once the
// input has named one) precedes every kept line that does not directly follow the previous one
// in the original numbering. The number uses the input's own convention, so whatever glslang
// decides for the #version (`#line N` naming the next or the current line), every kept line maps
// to its original (source, line). Lines before the input's first #line are instead placed at their
// original physical line with blank lines. The result depends only on what is kept and where it
// was: two inputs differing only in unreachable code give byte-identical text.
//
// Falls back (pruned=false, text=|preprocessed|, no keptFunctions) when |entryPoint| has no
// function definition, on unbalanced brackets, an unterminated declaration, comment or string, or
// a malformed #line.
//
// Example (HLSL, entry "vert"): the input
//   #line 1 0
//   float4x4 M;
//   sampler2D _MainTex;
//   float4 vert(float4 p : POSITION) : SV_POSITION
//   { return mul(M, p); }
//   float4 frag() : SV_Target { return tex2D(_MainTex, 0); }
// gives pruned=true, keptFunctions {"vert"} and
//   #line 1 0
//   float4x4 M;
//   #line 3 0
//   float4 vert(float4 p : POSITION) : SV_POSITION
//   { return mul(M, p); }
PruneResult pruneToEntryPoint(std::string_view preprocessed, std::string_view entryPoint,
                              ShaderDialect dialect);

}  // namespace varc::frontend
