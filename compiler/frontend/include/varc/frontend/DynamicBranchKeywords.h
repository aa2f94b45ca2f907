// SPDX-License-Identifier: Apache-2.0
// `#pragma dynamic_branch` keywords in program text: declared as uniforms, tested only by `if`.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/shaderlab/ShaderAst.h"
#include "varc/variants/PassKeywords.h"

namespace varc::frontend {

// Unity compiles a dynamic_branch keyword K into one program with a uniform integer K (1 when
// the keyword is enabled for the draw, else 0) that the code tests with `if (K)`; K is never a
// macro, so `#if K`, `#ifdef K` and `#if defined(K)` are false in that program (Unity's manual,
// shader-conditionals-choose-a-type). varc does the same (docs/KEYWORDS.md §12).

// The keywords of |keywords|'s dynamic_branch sets ("" entries left out), in declaration order,
// each once. Example: `dynamic_branch _ RED GREEN` + `dynamic_branch_local BLUE` ->
// {"RED", "GREEN", "BLUE"}.
std::vector<std::string> dynamicBranchKeywords(const variants::PassKeywords& keywords);

// |text| (an expanded program, which starts with a `#line`, as IncludeResolver writes it) with
// the declaration of each dynamic_branch keyword as a uniform integer in front: per
// dynamic_branch set, `#line L F` of its pragma, then its new keywords on that one line, so an
// error about a declaration (a name the program declares again) points at the pragma. HLSL and
// CG get `int K;` (a member of `$Global`), GLSL `uniform int K;` (glslang's default block).
// The original text follows unchanged, its own `#line` keeping every mapping. Returns |text|
// unchanged when there is no dynamic_branch keyword.
// Example, `#pragma dynamic_branch _ RED` at line 7 of file 2:
//   "#line 1 2\n..." -> "#line 7 2\nint RED;\n#line 1 2\n...".
std::string declareDynamicBranchUniforms(std::string_view text,
                                         const variants::PassKeywords& keywords,
                                         shaderlab::ProgramLanguage language);

// Reports a warning for every preprocessor conditional of |text| (an expanded program: its
// `#line` directives give the locations) that names one of |names| in its condition: `#if`,
// `#elif`, `#ifdef`, `#ifndef`. Unity leaves such a test constant (the keyword is no macro), so
// the code it guards does not follow the keyword at run time; the warning names the keyword,
// says which way the test always goes where the form tells (`#ifdef K` false, `#ifndef K`
// true) and suggests `if (K)`. Comments are skipped; a location is reported once even when
// several passes expand the same file, through |reported| (kept by the caller per shader).
// Example: "#line 3 1\n#ifdef RED\n" with {"RED"} -> warning at 1:3:8.
void warnPreprocessorTestsOfDynamicBranches(std::string_view text,
                                            const std::vector<std::string>& names,
                                            std::vector<SourceLocation>& reported,
                                            DiagnosticSink& sink);

}  // namespace varc::frontend
