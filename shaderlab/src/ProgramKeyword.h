// SPDX-License-Identifier: Apache-2.0
// The keywords that open verbatim program blocks (CGPROGRAM, HLSLINCLUDE, ...) and their ends.
#pragma once

#include <string_view>

#include "lex/Token.h"
#include "varc/shaderlab/ShaderAst.h"

namespace varc::shaderlab {

struct ProgramKeyword {
    std::string_view name;     // canonical spelling: "CGPROGRAM"
    std::string_view endWord;  // "ENDCG"
    ProgramLanguage language;
    bool isInclude;  // CGINCLUDE/HLSLINCLUDE/GLSLINCLUDE
};

// The program keyword |token| spells (case-insensitive), or nullptr.
// Example: findProgramKeyword(identifier "HLSLINCLUDE") -> {HLSLINCLUDE, ENDHLSL, Hlsl, true}.
const ProgramKeyword* findProgramKeyword(const Token& token);

}  // namespace varc::shaderlab
