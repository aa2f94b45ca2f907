// SPDX-License-Identifier: Apache-2.0
// Parses the top level of a .shader file: `Shader "name" { ... }` and its Category blocks.
#include "ShaderParser.h"

#include <string>

#include "BlockSyntax.h"
#include "ProgramKeyword.h"
#include "PropertyParser.h"

namespace varc::shaderlab {

bool ShaderParser::parse(ShaderFile& shader) {
    if (!mCursor.peek().isKeyword("Shader")) {
        return mCursor.unexpected("'Shader' at the start of the file");
    }
    Token keyword = mCursor.next();
    shader.location = keyword.location;
    Token name, open;
    if (!mCursor.expect(TokenKind::String, "a shader name string after Shader", name) ||
        !mCursor.expectSymbol('{', "after Shader name", &open)) {
        return false;
    }
    shader.name = std::string(name.text);
    mScopes.enter();
    bool ok = parseBlockItems(mCursor, open, [&] { return parseShaderItem(shader); });
    mScopes.leave();
    if (!ok) return false;
    if (!mCursor.peek().is(TokenKind::EndOfFile)) {
        return mCursor.unexpected("end of file after the Shader block");
    }
    mScopes.assignTo(shader);
    for (SubShader& subShader : shader.subShaders) inheritLightMode(subShader);
    return true;
}

bool ShaderParser::parseShaderItem(ShaderFile& shader) {
    const Token& token = mCursor.peek();
    if (token.isKeyword("Properties")) {
        mCursor.next();
        return PropertyParser(mCursor).parse(shader.properties);
    }
    if (token.isKeyword("SubShader")) return mSubShaders.parse(mCursor.next(), shader.subShaders);
    if (token.isKeyword("Category")) {
        mCursor.next();
        return parseCategory(shader);
    }
    if (token.isKeyword("Fallback")) return parseFallback(shader);
    if (token.isKeyword("Dependency")) return parseDependency(shader);
    if (token.isKeyword("CustomEditor"))
        return parseStringArguments("CustomEditor", 1, &shader.customEditor);
    if (token.isKeyword("CustomEditorForRenderPipeline")) {
        return parseStringArguments("CustomEditorForRenderPipeline", 2, nullptr);
    }
    if (findProgramKeyword(token)) return parseIncludeBlock(mCursor, mScopes);
    if (RenderStateParser::isCommand(token)) {
        return mCursor.fail(token.location, "render state command " + token.describe() +
                                                " must be inside a Category, SubShader or Pass");
    }
    return reportUnexpectedCommand(mCursor, "Shader");
}

// `Category { <state, Tags, LOD> SubShader {...}* }`: its state, tags and LOD apply to the
// SubShaders inside, wherever they are written in the block.
bool ShaderParser::parseCategory(ShaderFile& shader) {
    Token open;
    if (!mCursor.expectSymbol('{', "after Category", &open)) return false;
    size_t first = shader.subShaders.size();
    CategoryState category;
    mScopes.enter();
    bool ok = parseBlockItems(mCursor, open, [&] { return parseCategoryItem(shader, category); });
    mScopes.leave();
    if (!ok) return false;
    for (size_t i = first; i < shader.subShaders.size(); ++i) {
        applyCategory(category, shader.subShaders[i]);
    }
    return true;
}

bool ShaderParser::parseCategoryItem(ShaderFile& shader, CategoryState& category) {
    const Token& token = mCursor.peek();
    if (token.isKeyword("SubShader")) return mSubShaders.parse(mCursor.next(), shader.subShaders);
    if (token.isKeyword("Tags")) {
        mCursor.next();
        return parseTags(mCursor, category.tags);
    }
    if (token.isKeyword("LOD")) {
        mCursor.next();
        return parseLod(mCursor, category.lod);
    }
    if (findProgramKeyword(token)) return parseIncludeBlock(mCursor, mScopes);
    CommandResult result = mStateParser.tryParse(category.state);
    if (result != CommandResult::NotACommand) return result == CommandResult::Parsed;
    return reportUnexpectedCommand(mCursor, "Category");
}

// Tags the SubShader does not set are appended; its LOD wins unless it is 0.
void ShaderParser::applyCategory(const CategoryState& category, SubShader& subShader) {
    for (const auto& [key, value] : category.tags) {
        bool overridden = false;
        for (const auto& own : subShader.tags) overridden |= equalsIgnoreAsciiCase(own.first, key);
        if (!overridden) subShader.tags.emplace_back(key, value);
    }
    if (subShader.lod == 0) subShader.lod = category.lod;
    for (Pass& pass : subShader.passes) pass.state = pass.state.inheritedFrom(category.state);
}

// A SubShader's `LightMode` (its own or its Category's) goes to each pass that sets none, as
// Unity's compiler writes a SubShader's tags into its passes' tags (docs/COMPATIBILITY.md,
// "LightMode on a SubShader"). `UsePass` entries keep the tags of the pass they name.
void ShaderParser::inheritLightMode(SubShader& subShader) {
    std::string lightMode = findTag(subShader.tags, "LightMode");
    if (lightMode.empty()) return;
    for (Pass& pass : subShader.passes) {
        if (pass.usePass.empty() && pass.lightMode().empty()) {
            pass.tags.emplace_back("LightMode", lightMode);
        }
    }
}

// `Fallback "Diffuse"` or `Fallback Off`.
bool ShaderParser::parseFallback(ShaderFile& shader) {
    shader.fallbackLocation = mCursor.next().location;
    if (mCursor.peek().isKeyword("Off")) {
        mCursor.next();
        shader.fallback.reset();
        shader.fallbackOff = true;
        return true;
    }
    Token name;
    if (!mCursor.expect(TokenKind::String, "a shader name string or Off after Fallback", name)) {
        return false;
    }
    shader.fallback = std::string(name.text);
    shader.fallbackOff = false;
    return true;
}

// `Dependency "BaseMapShader" = "Hidden/Base"`.
bool ShaderParser::parseDependency(ShaderFile& shader) {
    mCursor.next();
    Token key, value;
    if (!mCursor.expect(TokenKind::String, "a dependency name string after Dependency", key) ||
        !mCursor.expectSymbol('=', "after the dependency name") ||
        !mCursor.expect(TokenKind::String, "a shader name string after '='", value)) {
        return false;
    }
    shader.dependencies.emplace_back(std::string(key.text), std::string(value.text));
    return true;
}

// `CustomEditor "Name"` (|count| 1) and similar commands; the first string goes to |first|.
bool ShaderParser::parseStringArguments(std::string_view command, size_t count,
                                        std::string* first) {
    mCursor.next();
    for (size_t i = 0; i < count; ++i) {
        Token argument;
        std::string what = "a string argument to " + std::string(command);
        if (!mCursor.expect(TokenKind::String, what, argument)) return false;
        if (i == 0 && first) *first = std::string(argument.text);
    }
    return true;
}

}  // namespace varc::shaderlab
