// SPDX-License-Identifier: Apache-2.0
// Keeps the low 32 bits of hexadecimal literals wider than 32 bits.
//
// FXC keeps the low 32 bits of a hexadecimal literal too wide for its type (with a warning);
// glslang stops. This rewrite produces `0x76312589U` from `0x1376312589U`, in code tokens only. It
// never adds, removes or moves a line break, so every `#line` mapping still holds.
#include <cctype>

#include "HlslRewrite.h"
#include "HlslRewritePasses.h"
#include "varc/core/AsciiIdentifier.h"

namespace varc::frontend::hlsl {

namespace {

using pruner::TokenKind;

class WideHexLiteralRewrite : public HlslRewrite {
public:
    explicit WideHexLiteralRewrite(RewriteState& state) : HlslRewrite(state) {}

    // `0x1376312589U` -> `0x76312589U` (see truncatedHexLiteral).
    void run() {
        for (size_t i = 0; i < mTokens.size(); ++i) {
            if (mTokens[i].kind != TokenKind::Number) continue;
            if (auto kept = truncatedHexLiteral(mTokens[i].text)) {
                mReplacements.push_back({offsetOf(i), mTokens[i].text.size(), *kept});
            }
        }
    }
};

}  // namespace

// The literal at the start of |text| ("0x1376312589U + 1" -> "0x1376312589U"), or "".
std::string_view hexLiteralAt(std::string_view text) {
    if (text.size() < 3 || text[0] != '0' || (text[1] != 'x' && text[1] != 'X')) return {};
    size_t end = 2;
    while (end < text.size() && isAsciiIdentifierChar(text[end])) ++end;
    return text.substr(0, end);
}

// The DirectX compilers keep the low 32 bits of a hexadecimal literal too wide for its type
// (with a warning); glslang stops. "0x1376312589U" -> "0x76312589U"; nullopt when |literal|
// is not a hexadecimal literal of more than 32 significant bits.
std::optional<std::string> truncatedHexLiteral(std::string_view literal) {
    if (hexLiteralAt(literal).size() != literal.size()) return std::nullopt;
    size_t digitsEnd = 2;
    while (digitsEnd < literal.size() &&
           std::isxdigit(static_cast<unsigned char>(literal[digitsEnd]))) {
        ++digitsEnd;
    }
    std::string_view digits = literal.substr(2, digitsEnd - 2);
    while (digits.size() > 1 && digits.front() == '0') digits.remove_prefix(1);
    if (digits.size() <= 8) return std::nullopt;
    return std::string(literal.substr(0, 2)) + std::string(digits.substr(digits.size() - 8)) +
           std::string(literal.substr(digitsEnd));
}

void truncateWideHexTokens(RewriteState& state) { WideHexLiteralRewrite(state).run(); }

}  // namespace varc::frontend::hlsl
