// SPDX-License-Identifier: Apache-2.0
// Parses a `Properties { ... }` block into Property declarations.
#include "PropertyParser.h"

#include <string>
#include <string_view>

#include "state/ValueSyntax.h"

namespace varc::shaderlab {
namespace {

struct TypeName {
    std::string_view name;
    PropertyType type;
};

constexpr TypeName kTypeNames[] = {
    {"Color", PropertyType::Color},         {"Vector", PropertyType::Vector},
    {"Float", PropertyType::Float},         {"Int", PropertyType::Int},
    {"Integer", PropertyType::Integer},     {"Range", PropertyType::Range},
    {"2D", PropertyType::Texture2D},        {"3D", PropertyType::Texture3D},
    {"Cube", PropertyType::Cube},           {"2DArray", PropertyType::Texture2DArray},
    {"CubeArray", PropertyType::CubeArray}, {"Any", PropertyType::Any},
};

// A Color/Vector default holds at most four components.
constexpr size_t kMaxComponents = 4;

bool isVectorType(PropertyType type) {
    return type == PropertyType::Color || type == PropertyType::Vector;
}

bool isNumberType(PropertyType type) {
    return type == PropertyType::Float || type == PropertyType::Int ||
           type == PropertyType::Integer || type == PropertyType::Range;
}

}  // namespace

bool PropertyParser::parse(std::vector<Property>& out) {
    Token open;
    if (!mCursor.expectSymbol('{', "after Properties", &open)) return false;
    while (true) {
        BlockStep step = mCursor.blockStep(open);
        if (step == BlockStep::End) return true;
        if (step == BlockStep::Failed) return false;
        if (!parseProperty(out)) return false;
    }
}

bool PropertyParser::parseProperty(std::vector<Property>& out) {
    Property property;
    if (!parseAttributes(property)) return false;
    Token name, display;
    if (!mCursor.expect(TokenKind::Identifier, "a property name or '}' in Properties", name) ||
        !mCursor.expectSymbol('(', "after property name " + std::string(name.text)) ||
        !mCursor.expect(TokenKind::String, "a display name string", display) ||
        !mCursor.expectSymbol(',', "after the display name")) {
        return false;
    }
    property.name = std::string(name.text);
    property.displayName = std::string(display.text);
    property.location = name.location;
    if (!parseType(property) ||
        !mCursor.expectSymbol(')', "after the type of property " + property.name) ||
        !mCursor.expectSymbol('=', "before the default of property " + property.name) ||
        !parseDefault(property)) {
        return false;
    }
    out.push_back(std::move(property));
    return true;
}

// `[Gamma] [Toggle(_FOO_ON)] [Header(Some text)]`, each kept as written without brackets.
bool PropertyParser::parseAttributes(Property& property) {
    while (mCursor.peek().isSymbol('[')) {
        Token open = mCursor.next();
        std::optional<std::string> text = mCursor.captureAttribute(open);
        if (!text) return false;
        property.attributes.push_back(std::move(*text));
    }
    return true;
}

bool PropertyParser::parseType(Property& property) {
    Token type;
    if (!mCursor.expect(TokenKind::Identifier, "a property type", type)) return false;
    for (const TypeName& entry : kTypeNames) {
        if (type.isKeyword(entry.name)) {
            property.type = entry.type;
            return property.type != PropertyType::Range || parseRange(property);
        }
    }
    return mCursor.fail(type.location, "unknown property type " + type.describe());
}

// `Range(min, max)` after the `Range` keyword.
bool PropertyParser::parseRange(Property& property) {
    Token min, max;
    if (!mCursor.expectSymbol('(', "after Range") || !expectNumber("as Range minimum", min) ||
        !mCursor.expectSymbol(',', "between Range minimum and maximum") ||
        !expectNumber("as Range maximum", max) || !mCursor.expectSymbol(')', "after Range")) {
        return false;
    }
    std::optional<float> minValue = floatOf(min), maxValue = floatOf(max);
    if (!minValue || !maxValue) {
        const Token& bad = minValue ? max : min;
        return mCursor.fail(bad.location, "Range bound " + bad.describe() + " is out of range");
    }
    property.rangeMin = *minValue;
    property.rangeMax = *maxValue;
    return true;
}

bool PropertyParser::parseDefault(Property& property) {
    Token first = mCursor.peek();
    Token last;
    bool ok = isVectorType(property.type)   ? parseVectorDefault(property, last)
              : isNumberType(property.type) ? parseNumberDefault(property, last)
                                            : parseTextureDefault(property, last);
    if (!ok) return false;
    property.defaultValue = mCursor.sourceBetween(first, last);
    return true;
}

// `(1, 1, 1, 1)`: one to four numbers.
bool PropertyParser::parseVectorDefault(const Property& property, Token& last) {
    std::string context = "the default of property " + property.name;
    if (!mCursor.expectSymbol('(', "to start " + context)) return false;
    for (size_t count = 1;; ++count) {
        Token component;
        if (!expectNumber("in " + context, component)) return false;
        if (mCursor.peek().isSymbol(')')) break;
        if (count == kMaxComponents) return mCursor.unexpected("')' after four components");
        if (!mCursor.expectSymbol(',', "between components of " + context)) return false;
    }
    last = mCursor.next();
    return true;
}

bool PropertyParser::parseNumberDefault(const Property& property, Token& last) {
    return expectNumber("as the default of property " + property.name, last);
}

// `"white" {}`, `"" { TexGen CubeReflect }` or just `"bump"`.
bool PropertyParser::parseTextureDefault(const Property& property, Token& last) {
    std::string what = "a texture name string as the default of property " + property.name;
    if (!mCursor.expect(TokenKind::String, what, last)) return false;
    if (!mCursor.peek().isSymbol('{')) return true;
    Token open = mCursor.next();
    return mCursor.skipBlock(open, &last);
}

bool PropertyParser::expectNumber(std::string_view context, Token& out) {
    return mCursor.expect(TokenKind::Number, "a number " + std::string(context), out);
}

}  // namespace varc::shaderlab
