// SPDX-License-Identifier: Apache-2.0
// Calls of one-parameter macros with an empty argument, which glslang's preprocessor refuses.
#pragma once

#include <string>
#include <string_view>

namespace varc::frontend {

// |text| (HLSL before preprocessing) with each call of a one-parameter function-like macro whose
// argument is empty or the lone token `##` replaced by the macro's body on the call's line, the
// parameter removed together with the `##` that pastes it:
//   "#define DECL(id) float _A##id;\nDECL()\nDECL(##)\n" ->
//   "#define DECL(id) float _A##id;\n float _A;\n float _A;\n"
// C99 and Unity's preprocessors take `DECL()` as one empty argument (older Unity versions spell
// it `DECL(##)`); glslang stops with "Too few args in Macro" or "unexpected '#'". The body
// replaces the call without its line continuations, so no line moves; the macros it names are
// expanded by the preprocessor as before. The definition used is the last one before the call;
// a body that pastes or stringises anything but the parameter leaves its calls alone.
std::string expandEmptyMacroArguments(std::string_view text);

}  // namespace varc::frontend
