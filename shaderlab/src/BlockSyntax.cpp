// SPDX-License-Identifier: Apache-2.0
// Syntax shared by Shader, Category, SubShader and Pass bodies: Tags, LOD and block loops.
#include "BlockSyntax.h"

#include <algorithm>
#include <optional>
#include <string>

#include "ProgramKeyword.h"
#include "SurfacePragma.h"
#include "state/ValueSyntax.h"
#include "varc/core/Check.h"

namespace varc::shaderlab {

bool parseTags(TokenCursor& cursor, Tags& tags) {
    Token open;
    if (!cursor.expectSymbol('{', "after Tags", &open)) return false;
    return parseBlockItems(cursor, open, [&] {
        Token key, value;
        if (!cursor.expect(TokenKind::String, "a tag name string or '}' in Tags", key) ||
            !cursor.expectSymbol('=', "after tag name \"" + std::string(key.text) + "\"") ||
            !cursor.expect(TokenKind::String, "a tag value string", value)) {
            return false;
        }
        for (auto& [existingKey, existingValue] : tags) {
            if (equalsIgnoreAsciiCase(existingKey, key.text)) {
                existingValue = std::string(value.text);
                return true;
            }
        }
        tags.emplace_back(std::string(key.text), std::string(value.text));
        return true;
    });
}

bool parseLod(TokenCursor& cursor, int& lod) {
    Token number;
    if (!cursor.expect(TokenKind::Number, "an integer after LOD", number)) return false;
    std::optional<int> value = integerOf(number);
    if (!value) {  // negative levels are valid: Unity picks the first SubShader <= maximumLOD
        return cursor.fail(number.location,
                           "invalid LOD " + number.describe() + "; expected an integer");
    }
    lod = *value;
    return true;
}

bool reportUnexpectedCommand(TokenCursor& cursor, std::string_view scope) {
    const Token& token = cursor.peek();
    if (token.is(TokenKind::Identifier)) {
        return cursor.fail(token.location, "unknown ShaderLab command " + token.describe());
    }
    return cursor.unexpected("a command or '}' in " + std::string(scope));
}

bool parseIncludeBlock(TokenCursor& cursor, IncludeScopes& scopes) {
    const ProgramKeyword* program = findProgramKeyword(cursor.peek());
    VARC_CHECK(program) << "parseIncludeBlock without a program keyword";
    if (!program->isInclude) {
        // Outside a SubShader a program block has no place; SubShader bodies read surface
        // programs themselves (SubShaderParser).
        Token keyword = cursor.peek();
        SourceLocation where = keyword.location;
        cursor.next();
        std::optional<ProgramBlock> block = cursor.captureProgram(keyword, *program);
        if (!block) return false;
        if (std::optional<SourceLocation> surface = findSurfacePragma(*block)) {
            return cursor.fail(*surface, "a surface program ('#pragma surface') must be written "
                                         "directly inside a SubShader");
        }
        return cursor.fail(where, std::string(program->name) + " block must be inside a Pass");
    }
    Token keyword = cursor.next();
    std::optional<ProgramBlock> block = cursor.captureProgram(keyword, *program);
    if (!block) return false;
    scopes.addInclude(std::move(*block));
    return true;
}

}  // namespace varc::shaderlab
