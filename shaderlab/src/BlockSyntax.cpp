// SPDX-License-Identifier: Apache-2.0
// Syntax shared by Shader, Category, SubShader and Pass bodies: Tags, LOD and block loops.
#include "BlockSyntax.h"

#include <algorithm>
#include <optional>
#include <string>

#include "ProgramKeyword.h"
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
    if (!value || *value < 0) {
        return cursor.fail(number.location, "invalid LOD " + number.describe() +
                                                "; expected a non-negative integer");
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

// The location of a `#pragma surface` line in |block|, if it has one.
std::optional<SourceLocation> findSurfacePragma(const ProgramBlock& block) {
    std::string_view text = block.text;
    SourceLocation location = block.origin;
    size_t lineStart = 0;
    while (lineStart <= text.size()) {
        size_t end = std::min(text.find('\n', lineStart), text.size());
        std::string_view line = text.substr(lineStart, end - lineStart);
        size_t hash = line.find_first_not_of(" \t\r");
        if (hash != std::string_view::npos && line[hash] == '#') {
            std::string_view rest = line.substr(hash + 1);
            rest.remove_prefix(std::min(rest.find_first_not_of(" \t"), rest.size()));
            if (rest.starts_with("pragma")) {
                rest.remove_prefix(6);
                rest.remove_prefix(std::min(rest.find_first_not_of(" \t"), rest.size()));
                if (rest.starts_with("surface") &&
                    (rest.size() == 7 || rest[7] == ' ' || rest[7] == '\t' || rest[7] == '\r')) {
                    uint32_t column = static_cast<uint32_t>(hash) + 1;
                    if (location.line == block.origin.line) column += block.origin.column - 1;
                    return SourceLocation{location.file, location.line, column};
                }
            }
        }
        lineStart = end + 1;
        ++location.line;
    }
    return std::nullopt;
}

bool parseIncludeBlock(TokenCursor& cursor, IncludeScopes& scopes) {
    const ProgramKeyword* program = findProgramKeyword(cursor.peek());
    VARC_CHECK(program) << "parseIncludeBlock without a program keyword";
    if (!program->isInclude) {
        // A program directly in a SubShader is a surface shader, which Unity turns into passes
        // with its code generator; varc has none, so it says so at the `#pragma surface`.
        Token keyword = cursor.peek();
        SourceLocation where = keyword.location;
        cursor.next();
        std::optional<ProgramBlock> block = cursor.captureProgram(keyword, *program);
        if (!block) return false;
        if (std::optional<SourceLocation> surface = findSurfacePragma(*block)) {
            return cursor.fail(*surface,
                               "surface shaders ('#pragma surface') are not supported: varc "
                               "compiles vertex and fragment programs; write the lighting as "
                               "Pass blocks with '#pragma vertex' and '#pragma fragment'");
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
