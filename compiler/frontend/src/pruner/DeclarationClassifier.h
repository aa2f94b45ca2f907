// SPDX-License-Identifier: Apache-2.0
// Classifies one top-level declaration: kind, when it must be kept, names it defines and uses.
#pragma once

#include <string_view>
#include <vector>

#include "pruner/Declaration.h"
#include "pruner/ShaderTokenizer.h"
#include "varc/frontend/StagePruner.h"

namespace varc::frontend::pruner {

class DeclarationClassifier {
public:
    DeclarationClassifier(const std::vector<Token>& tokens, ShaderDialect dialect)
        : mTokens(tokens), mDialect(dialect) {}

    // Classifies the declaration |span| (from DeclarationSplitter, so brackets balance).
    //  * `T name(...) {...}` / `T name(...);` → Function defining `name`.
    //  * `struct S {...};` → Struct defining `S`; with declarators after `}` also a variable.
    //  * `typedef T Name;` → Typedef defining `Name`.
    //  * HLSL `cbuffer B : register(b0) {...}` → Block defining `B` and every member.
    //  * GLSL `uniform B {...} inst;` → Block defining `B` and `inst` (or, without an instance
    //    name, every member); always kept since glslang emits unused blocks.
    //  * `precision ...;` and anything unrecognised (`namespace`, DX effect blocks) → Always.
    //  * other declarations → Variable defining its declarator names, e.g. `k` and `j` for
    //    `static const float3 k[2] = {...}, j;`; semantics/`register(...)` after `:` and member
    //    names after `.` are not uses. See variableRetention() for when variables are kept.
    Declaration classify(const DeclarationSpan& span) const;

private:
    struct Statement {
        std::vector<std::string_view> names;  // declarators
        std::vector<std::string_view> uses;
        std::string_view type;  // first non-qualifier word
        bool isStatic = false;
        bool isConst = false;
        bool isGroupShared = false;
        bool hasStorage = false;  // GLSL uniform/in/out/buffer/shared/...
    };

    void classifyFunction(const DeclarationSpan& span, Declaration& decl) const;
    void classifyStruct(const DeclarationSpan& span, size_t first, Declaration& decl) const;
    void classifyBlock(const DeclarationSpan& span, size_t first, Declaration& decl) const;
    void classifyVariable(size_t first, size_t last, Declaration& decl) const;
    void classifyTypedef(size_t first, size_t last, Declaration& decl) const;
    Statement analyzeStatement(size_t begin, size_t end, bool typeGiven) const;
    bool isDeclaratorName(size_t index, size_t begin, size_t end, bool typeGiven) const;
    void addMembers(size_t open, size_t close, bool membersAreGlobal, Declaration& decl) const;
    Retention variableRetention(const Statement& statement) const;
    // Records |word| in |statement| if it is a qualifier; returns whether it was one.
    static bool noteQualifier(std::string_view word, Statement& statement);

    const std::vector<Token>& mTokens;
    ShaderDialect mDialect;
};

}  // namespace varc::frontend::pruner
