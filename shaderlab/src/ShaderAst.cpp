// SPDX-License-Identifier: Apache-2.0
// Helpers over the parsed .shader AST.
#include "varc/shaderlab/ShaderAst.h"

#include "lex/Token.h"

namespace varc::shaderlab {

std::string findTag(const Tags& tags, const std::string& key) {
    for (const auto& [name, value] : tags) {
        if (equalsIgnoreAsciiCase(name, key)) return value;
    }
    return {};
}

}  // namespace varc::shaderlab
