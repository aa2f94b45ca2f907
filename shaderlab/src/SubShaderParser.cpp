// SPDX-License-Identifier: Apache-2.0
// Parses `SubShader { ... }` blocks with their passes, UsePass and GrabPass entries.
#include "SubShaderParser.h"

#include <string>

#include "BlockSyntax.h"
#include "ProgramKeyword.h"
#include "SurfacePragma.h"

namespace varc::shaderlab {

bool SubShaderParser::parse(const Token& keyword, std::vector<SubShader>& out) {
    SubShader subShader;
    subShader.location = keyword.location;
    RenderState state;
    size_t index = out.size();
    Token open;
    if (!mCursor.expectSymbol('{', "after SubShader", &open)) return false;
    mScopes.enter();
    bool ok = parseBlockItems(mCursor, open, [&] { return parseItem(subShader, state, index); });
    mScopes.leave();
    if (!ok) return false;
    for (Pass& pass : subShader.passes) pass.state = pass.state.inheritedFrom(state);
    out.push_back(std::move(subShader));
    return true;
}

bool SubShaderParser::parseItem(SubShader& subShader, RenderState& state, size_t index) {
    const Token& token = mCursor.peek();
    if (token.isKeyword("Pass")) return parsePass(mCursor.next(), subShader, index);
    if (token.isKeyword("UsePass")) return parseUsePass(mCursor.next(), subShader);
    if (token.isKeyword("GrabPass")) return parseGrabPass();
    if (token.isKeyword("Tags")) {
        mCursor.next();
        return parseTags(mCursor, subShader.tags);
    }
    if (token.isKeyword("LOD")) {
        mCursor.next();
        return parseLod(mCursor, subShader.lod);
    }
    if (const ProgramKeyword* program = findProgramKeyword(token)) {
        if (program->isInclude) return parseIncludeBlock(mCursor, mScopes);
        return parseSurface(mCursor.next(), subShader, index);
    }
    CommandResult result = mStateParser.tryParse(state);
    if (result != CommandResult::NotACommand) return result == CommandResult::Parsed;
    return reportUnexpectedCommand(mCursor, "SubShader");
}

bool SubShaderParser::parsePass(const Token& keyword, SubShader& subShader, size_t index) {
    Pass pass;
    pass.location = keyword.location;
    Token open;
    if (!mCursor.expectSymbol('{', "after Pass", &open)) return false;
    mScopes.enter();
    bool ok = parseBlockItems(mCursor, open, [&] { return parsePassItem(pass); });
    if (ok) mScopes.addPass(index, subShader.passes.size());
    mScopes.leave();
    if (!ok) return false;
    subShader.passes.push_back(std::move(pass));
    return true;
}

bool SubShaderParser::parsePassItem(Pass& pass) {
    const Token& token = mCursor.peek();
    if (token.isKeyword("Tags")) {
        mCursor.next();
        return parseTags(mCursor, pass.tags);
    }
    if (token.isKeyword("Name")) {
        mCursor.next();
        Token name;
        if (!mCursor.expect(TokenKind::String, "a pass name string after Name", name)) return false;
        pass.name = std::string(name.text);
        return true;
    }
    if (const ProgramKeyword* program = findProgramKeyword(token)) {
        if (program->isInclude) return parseIncludeBlock(mCursor, mScopes);
        return parseProgram(mCursor.next(), pass);
    }
    if (token.isKeyword("LOD")) return parseIgnoredPassLod();
    CommandResult result = mStateParser.tryParse(pass.state);
    if (result != CommandResult::NotACommand) return result == CommandResult::Parsed;
    return reportUnexpectedCommand(mCursor, "Pass");
}

// `LOD` belongs to a SubShader; Unity accepts it inside a Pass and ignores it there. varc reads
// the number (so a malformed one is still an error) and warns that it has no effect.
bool SubShaderParser::parseIgnoredPassLod() {
    Token keyword = mCursor.next();
    int ignored = 0;
    if (!parseLod(mCursor, ignored)) return false;
    mCursor.sink().warning(keyword.location,
                           "LOD inside a Pass has no effect (it belongs to the SubShader); "
                           "ignored, as in Unity");
    return true;
}

bool SubShaderParser::parseProgram(const Token& keyword, Pass& pass) {
    if (pass.program) {
        return mCursor.fail(keyword.location, "a Pass can hold only one program block; " +
                                                  std::string(keyword.text) + " is the second");
    }
    std::optional<ProgramBlock> block =
        mCursor.captureProgram(keyword, *findProgramKeyword(keyword));
    if (!block) return false;
    pass.program = std::move(*block);
    return true;
}

// A program directly in a SubShader: a surface program when it has `#pragma surface`, kept as
// a placeholder pass (Pass::surface) the compiler generates the passes of.
bool SubShaderParser::parseSurface(const Token& keyword, SubShader& subShader, size_t index) {
    const ProgramKeyword& kind = *findProgramKeyword(keyword);
    std::optional<ProgramBlock> block = mCursor.captureProgram(keyword, kind);
    if (!block) return false;
    std::optional<SourceLocation> pragma = findSurfacePragma(*block);
    if (!pragma) {
        return mCursor.fail(keyword.location,
                            std::string(kind.name) + " block must be inside a Pass");
    }
    std::optional<SurfaceProgram> surface = parseSurfaceProgram(*block, *pragma, mCursor.sink());
    if (!surface) return false;
    Pass pass;
    pass.location = keyword.location;
    pass.surface = std::move(*surface);
    mScopes.addPass(index, subShader.passes.size());
    subShader.passes.push_back(std::move(pass));
    return true;
}

// `UsePass "Shader/PASSNAME"`: a pass borrowed from another shader, by reference.
bool SubShaderParser::parseUsePass(const Token& keyword, SubShader& subShader) {
    Token reference;
    if (!mCursor.expect(TokenKind::String, "a \"Shader/PASSNAME\" string after UsePass",
                        reference)) {
        return false;
    }
    Pass pass;
    pass.usePass = std::string(reference.text);
    pass.location = keyword.location;
    subShader.passes.push_back(std::move(pass));
    return true;
}

// `GrabPass { }` or `GrabPass { "_Name" }`: screen grabs are not compiled, so the body is skipped.
bool SubShaderParser::parseGrabPass() {
    mCursor.next();
    Token open;
    if (!mCursor.expectSymbol('{', "after GrabPass", &open)) return false;
    return mCursor.skipBlock(open);
}

}  // namespace varc::shaderlab
