// SPDX-License-Identifier: Apache-2.0
// Parses a `Properties { ... }` block into Property declarations.
#pragma once

#include <vector>

#include "lex/Token.h"
#include "lex/TokenCursor.h"
#include "varc/shaderlab/ShaderAst.h"

namespace varc::shaderlab {

// Grammar of one declaration:
//   [Attr]* _Name ("Display", Type) = Default
//   Type    = Color | Vector | Float | Int | Integer | Range(min, max) | 2D | 3D | Cube
//           | 2DArray | CubeArray | Any                      (case-insensitive)
//   Default = (x, y, z, w)            for Color/Vector (1 to 4 numbers)
//           | number                  for Float/Int/Integer/Range
//           | "name" [{ options }]    for textures; legacy options such as TexGen are skipped
class PropertyParser {
public:
    explicit PropertyParser(TokenCursor& cursor) : mCursor(cursor) {}

    // Parses `{ ... }` (the `Properties` keyword already consumed), appending to |out|.
    // Errors: "unknown property type 'Foo'", "expected a number as the default of property _X,
    // found \"a\"". Example:
    //   { [Gamma] _Metallic ("Metallic", Range(0, 1)) = 0 }
    //   -> {attributes {"Gamma"}, name "_Metallic", type Range, 0..1, defaultValue "0"}.
    bool parse(std::vector<Property>& out);

private:
    bool parseProperty(std::vector<Property>& out);
    bool parseAttributes(Property& property);
    bool parseType(Property& property);
    bool parseRange(Property& property);
    bool parseDefault(Property& property);
    bool parseVectorDefault(const Property& property, Token& last);
    bool parseNumberDefault(const Property& property, Token& last);
    bool parseTextureDefault(const Property& property, Token& last);
    bool expectNumber(std::string_view context, Token& out);

    TokenCursor& mCursor;
};

}  // namespace varc::shaderlab
