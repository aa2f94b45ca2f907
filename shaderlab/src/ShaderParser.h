// SPDX-License-Identifier: Apache-2.0
// Parses the top level of a .shader file: `Shader "name" { ... }` and its Category blocks.
#pragma once

#include <optional>

#include "IncludeScopes.h"
#include "SubShaderParser.h"
#include "lex/Token.h"
#include "lex/TokenCursor.h"
#include "state/RenderStateParser.h"
#include "varc/shaderlab/ShaderAst.h"

namespace varc::shaderlab {

class ShaderParser {
public:
    explicit ShaderParser(TokenCursor& cursor)
        : mCursor(cursor), mStateParser(cursor), mSubShaders(cursor, mStateParser, mScopes) {}

    // Parses a whole file into |shader|: the Shader block and nothing after it but comments.
    // Returns false after reporting the first error. See parseShaderLab() for the grammar.
    bool parse(ShaderFile& shader);

private:
    // What a Category passes down to the SubShaders it encloses.
    struct CategoryState {
        RenderState state;
        Tags tags;
        int lod = 0;
    };

    bool parseShaderItem(ShaderFile& shader);
    bool parseCategory(ShaderFile& shader);
    bool parseCategoryItem(ShaderFile& shader, CategoryState& category);
    static void applyCategory(const CategoryState& category, SubShader& subShader);
    static void inheritLightMode(SubShader& subShader);
    bool parseFallback(ShaderFile& shader);
    bool parseDependency(ShaderFile& shader);
    bool parseStringArguments(std::string_view command, size_t count, std::string* first);

    TokenCursor& mCursor;
    IncludeScopes mScopes;
    RenderStateParser mStateParser;
    SubShaderParser mSubShaders;
};

}  // namespace varc::shaderlab
