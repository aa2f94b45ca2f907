// SPDX-License-Identifier: Apache-2.0
// Source rewrites that let glslang's HLSL front end accept what Unity's HLSL compilers accept.
#include "varc/frontend/HlslRewrites.h"

#include <optional>

#include "hlsl/HlslRewritePasses.h"
#include "pruner/ShaderTokenizer.h"
#include "varc/core/AsciiIdentifier.h"

namespace varc::frontend {

std::string rewriteHlslForGlslang(std::string_view text,
                                  const std::vector<std::string>& unmatchedCalls,
                                  bool scalarAnyAll) {
    pruner::ShaderTokenizer tokenizer;
    if (!tokenizer.tokenize(text)) return std::string(text);
    hlsl::RewriteState state(tokenizer);
    hlsl::scanDeclarationBodies(state);
    for (const std::string& function : unmatchedCalls) hlsl::castCallArguments(state, function);
    hlsl::castSwitchConditions(state);
    hlsl::copyWrittenUniforms(state);
    hlsl::copyWrittenUniformParameters(state);
    if (scalarAnyAll) hlsl::declareScalarAnyAll(state);
    hlsl::spellOutMatrixSwizzles(state);
    hlsl::truncateWideHexTokens(state);
    hlsl::dropEmptyMemberDeclarations(state);
    hlsl::splitSelfInitializations(state);
    hlsl::hoistCbufferResources(state);
    return state.apply(text);
}

std::string truncateWideHexLiterals(std::string_view text) {
    std::string result;
    result.reserve(text.size());
    size_t i = 0;
    while (i < text.size()) {
        std::string_view literal = (i == 0 || !isAsciiIdentifierChar(text[i - 1]))
                                       ? hlsl::hexLiteralAt(text.substr(i))
                                       : "";
        if (literal.empty()) {
            result += text[i++];
            continue;
        }
        std::optional<std::string> kept = hlsl::truncatedHexLiteral(literal);
        result += kept ? *kept : std::string(literal);
        i += literal.size();
    }
    return result;
}

std::string fixFrontFaceParameterTypes(std::string_view text) {
    if (text.find("SV_IsFrontFace") == std::string_view::npos &&
        text.find("VFACE") == std::string_view::npos) {
        return std::string(text);
    }
    pruner::ShaderTokenizer tokenizer;
    if (!tokenizer.tokenize(text)) return std::string(text);
    hlsl::RewriteState state(tokenizer);
    hlsl::makeFrontFaceParametersBool(state);
    hlsl::replaceFaceParameters(state);
    return state.apply(text);
}

}  // namespace varc::frontend
