// SPDX-License-Identifier: Apache-2.0
// Splits the token stream of a preprocessed program into top-level declarations.
#pragma once

#include <optional>
#include <vector>

#include "pruner/Declaration.h"
#include "pruner/ShaderTokenizer.h"
#include "varc/frontend/StagePruner.h"

namespace varc::frontend::pruner {

class DeclarationSplitter {
public:
    DeclarationSplitter(const std::vector<Token>& tokens, ShaderDialect dialect)
        : mTokens(tokens), mDialect(dialect) {}

    // Splits all tokens into consecutive top-level declarations. A declaration ends at a
    // depth-0 `;`, or at the `}` closing a function body (a depth-0 `name(...)` before the `{`,
    // no `=` and no `struct`), or, in HLSL, at the `}` (plus an optional `;`) of a `cbuffer`,
    // `tbuffer`, `namespace`, `class`, `interface` or `technique` block. Other braces (struct
    // bodies, interface blocks, initializer lists) continue to the next depth-0 `;`.
    // Returns nullopt on unbalanced brackets or tokens left without a terminator.
    // Example: `struct S { float a; }; float4 f(S s) : SV_Target { return 0; } float b;`
    // gives three spans: `struct ... ;`, `float4 f ... }`, `float b ;`.
    std::optional<std::vector<DeclarationSpan>> split() const;

private:
    std::optional<DeclarationSpan> splitOne(size_t begin) const;
    bool endsAtClosingBrace(size_t begin) const;

    const std::vector<Token>& mTokens;
    ShaderDialect mDialect;
};

}  // namespace varc::frontend::pruner
