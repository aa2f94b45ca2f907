// SPDX-License-Identifier: Apache-2.0
#include "varc/driver/PropertyDefaults.h"

#include <cctype>
#include <charconv>
#include <string_view>
#include <vector>

#include "varc/core/Trim.h"

namespace varc::driver {

namespace {

using shaderlab::PropertyType;

bool parseNumber(std::string_view text, float& out) {
    text = trim(text);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    const char* end = text.data() + text.size();
    auto [last, error] = std::from_chars(text.data(), end, out);
    return error == std::errc() && last == end;
}

// "(1, 0.5, 0, 1)" -> up to four numbers.
bool parseVector(std::string_view text, std::array<float, 4>& out) {
    text = trim(text);
    if (text.size() < 2 || text.front() != '(' || text.back() != ')') return false;
    text = text.substr(1, text.size() - 2);
    size_t count = 0;
    while (true) {
        size_t comma = text.find(',');
        if (count == 4 || !parseNumber(text.substr(0, comma), out[count])) return false;
        ++count;
        if (comma == std::string_view::npos) break;
        text.remove_prefix(comma + 1);
    }
    return count >= 2;
}

// "\"white\" {}" (the braces may hold legacy options) -> white.
bool parseTexture(std::string_view text, std::string& out) {
    text = trim(text);
    if (text.empty() || text.front() != '"') return false;
    size_t close = text.find('"', 1);
    if (close == std::string_view::npos) return false;
    out = std::string(text.substr(1, close - 1));
    return true;
}

const char* typeName(PropertyType type) {
    switch (type) {
        case PropertyType::Color:
            return "Color";
        case PropertyType::Vector:
            return "Vector";
        case PropertyType::Float:
            return "Float";
        case PropertyType::Int:
            return "Int";
        case PropertyType::Integer:
            return "Integer";
        case PropertyType::Range:
            return "Range";
        case PropertyType::Texture2D:
            return "2D";
        case PropertyType::Texture3D:
            return "3D";
        case PropertyType::Cube:
            return "Cube";
        case PropertyType::Texture2DArray:
            return "2DArray";
        case PropertyType::CubeArray:
            return "CubeArray";
        case PropertyType::Any:
            return "Any";
    }
    return "?";
}

}  // namespace

Result<pack::ShaderProperty> toPackProperty(const shaderlab::Property& property) {
    pack::ShaderProperty out;
    out.name = property.name;
    const char* expected = nullptr;
    switch (property.type) {
        case PropertyType::Float:
        case PropertyType::Int:
        case PropertyType::Integer:
        case PropertyType::Range:
            out.kind = pack::PropertyKind::Float;
            if (!parseNumber(property.defaultValue, out.value[0])) expected = "a number";
            break;
        case PropertyType::Color:
        case PropertyType::Vector:
            out.kind = property.type == PropertyType::Color ? pack::PropertyKind::Color
                                                            : pack::PropertyKind::Vector;
            if (!parseVector(property.defaultValue, out.value)) expected = "(x, y, z, w)";
            break;
        case PropertyType::Texture2D:
        case PropertyType::Texture3D:
        case PropertyType::Cube:
        case PropertyType::Texture2DArray:
        case PropertyType::CubeArray:
        case PropertyType::Any:
            out.kind = pack::PropertyKind::Texture;
            if (!parseTexture(property.defaultValue, out.texture)) expected = "\"name\" {}";
            break;
    }
    if (expected) {
        return makeError(ErrorCode::InvalidInput,
                         "the default of " + property.name + " (" + typeName(property.type) +
                             ") should be " + expected + ", not '" + property.defaultValue + "'");
    }
    return out;
}

}  // namespace varc::driver
