// SPDX-License-Identifier: Apache-2.0
// Shared value syntax: render-state values (`One`, `2`, `[_Prop]`), integers and numbers.
#include "state/ValueSyntax.h"

#include <charconv>
#include <string>
#include <system_error>

namespace varc::shaderlab {
namespace {

// The longest list of accepted names spelled out in an "invalid value" message.
constexpr size_t kMaxListedNames = 12;

// from_chars rejects a leading '+'; ShaderLab numbers may carry one.
std::string_view withoutPlus(std::string_view text) {
    return (!text.empty() && text[0] == '+') ? text.substr(1) : text;
}

std::string invalidValueMessage(std::string_view command, std::span<const std::string_view> names,
                                const Token& token) {
    std::string message = "invalid " + std::string(command) + " value " + token.describe();
    if (names.empty() || names.size() > kMaxListedNames) return message;
    message += "; expected ";
    for (size_t i = 0; i < names.size(); ++i) {
        message += (i == 0 ? "" : ", ") + std::string(names[i]);
    }
    return message;
}

bool parsePropertyReference(TokenCursor& cursor, std::string_view command, StateValue& out) {
    cursor.next();  // '['
    Token name;
    std::string context = "a property name in " + std::string(command) + " '[...]'";
    if (!cursor.expect(TokenKind::Identifier, context, name)) return false;
    if (!cursor.expectSymbol(']', "after property name " + std::string(name.text))) return false;
    out = StateValue{{}, std::string(name.text)};
    return true;
}

}  // namespace

bool containsName(std::span<const std::string_view> names, std::string_view text) {
    for (std::string_view name : names) {
        if (equalsIgnoreAsciiCase(name, text)) return true;
    }
    return false;
}

bool parseStateValue(TokenCursor& cursor, std::string_view command,
                     std::span<const std::string_view> names, bool allowNumber, StateValue& out) {
    const Token& token = cursor.peek();
    if (token.isSymbol('[')) return parsePropertyReference(cursor, command, out);
    if (token.is(TokenKind::Number) && allowNumber) {
        out = StateValue{std::string(cursor.next().text), {}};
        return true;
    }
    if (token.is(TokenKind::Identifier) || token.is(TokenKind::Number)) {
        if (!containsName(names, token.text)) {
            return cursor.fail(token.location, invalidValueMessage(command, names, token));
        }
        out = StateValue{std::string(cursor.next().text), {}};
        return true;
    }
    return cursor.unexpected("a value for " + std::string(command));
}

std::optional<int> integerOf(const Token& token) {
    std::string_view text = withoutPlus(token.text);
    int value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

std::optional<float> floatOf(const Token& token) {
    std::string_view text = withoutPlus(token.text);
    float value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

}  // namespace varc::shaderlab
