// SPDX-License-Identifier: Apache-2.0
// One top-level declaration of a preprocessed program: its tokens, kind, names and references.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace varc::frontend::pruner {

// Token range of one top-level declaration as found by DeclarationSplitter, with the landmarks
// the classifier needs. Indices are into the tokenizer's token list.
struct DeclarationSpan {
    size_t begin = 0;                   // first token
    size_t end = 0;                     // one past the last token (`;` or `}`)
    std::optional<size_t> head;         // `name` of the first depth-0 `name(` before any `=`
    std::optional<size_t> firstBrace;   // first depth-0 `{`
    std::optional<size_t> firstAssign;  // first depth-0 `=`
    bool hasStruct = false;             // a depth-0 `struct` keyword before the end
};

enum class DeclarationKind { Empty, Function, Struct, Typedef, Variable, Block, Precision, Other };

// When a declaration is kept.
enum class Retention {
    Never,        // a stray `;`
    IfReachable,  // only when something kept names it (or it defines the entry point)
    GlobalGroup,  // HLSL loose uniform: all of them together, once one is reachable ($Global)
    Always,       // glslang emits it even when unused, or it could not be classified
};

struct Declaration {
    size_t begin = 0;
    size_t end = 0;
    DeclarationKind kind = DeclarationKind::Other;
    Retention retention = Retention::Always;
    bool hasBody = false;                   // functions: a definition, not a prototype
    std::vector<std::string_view> defines;  // global names it introduces
    std::vector<std::string_view> uses;     // identifiers it mentions (a superset of references)
};

}  // namespace varc::frontend::pruner
