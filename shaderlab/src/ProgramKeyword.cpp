// SPDX-License-Identifier: Apache-2.0
// The keywords that open verbatim program blocks (CGPROGRAM, HLSLINCLUDE, ...) and their ends.
#include "ProgramKeyword.h"

namespace varc::shaderlab {
namespace {

constexpr ProgramKeyword kProgramKeywords[] = {
    {"CGPROGRAM", "ENDCG", ProgramLanguage::Cg, false},
    {"CGINCLUDE", "ENDCG", ProgramLanguage::Cg, true},
    {"HLSLPROGRAM", "ENDHLSL", ProgramLanguage::Hlsl, false},
    {"HLSLINCLUDE", "ENDHLSL", ProgramLanguage::Hlsl, true},
    {"GLSLPROGRAM", "ENDGLSL", ProgramLanguage::Glsl, false},
    {"GLSLINCLUDE", "ENDGLSL", ProgramLanguage::Glsl, true},
};

}  // namespace

const ProgramKeyword* findProgramKeyword(const Token& token) {
    for (const ProgramKeyword& keyword : kProgramKeywords) {
        if (token.isKeyword(keyword.name)) return &keyword;
    }
    return nullptr;
}

}  // namespace varc::shaderlab
