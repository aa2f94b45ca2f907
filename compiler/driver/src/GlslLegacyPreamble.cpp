// SPDX-License-Identifier: Apache-2.0
// Maps legacy GLSL built-ins onto declarations that Vulkan SPIR-V accepts.
#include "varc/driver/GlslLegacyPreamble.h"

#include <cctype>
#include <cstdlib>
#include <utility>

#include "varc/variants/PassKeywords.h"

namespace varc::driver {

namespace {

struct LegacyBuiltin {
    const char* name;         // the gl_ name the source uses
    const char* declaration;  // what replaces it, declared as varc_<suffix>
    StageMask stages;         // where it may be used
};

// Vertex attributes become inputs; fixed-function state becomes uniforms of the default block.
constexpr LegacyBuiltin kBuiltins[] = {
    {"gl_Vertex", "in vec4 varc_Vertex;", stageBit(Stage::Vertex)},
    {"gl_Normal", "in vec3 varc_Normal;", stageBit(Stage::Vertex)},
    {"gl_Color", "in vec4 varc_Color;", stageBit(Stage::Vertex)},
    {"gl_MultiTexCoord0", "in vec4 varc_MultiTexCoord0;", stageBit(Stage::Vertex)},
    {"gl_MultiTexCoord1", "in vec4 varc_MultiTexCoord1;", stageBit(Stage::Vertex)},
    {"gl_MultiTexCoord2", "in vec4 varc_MultiTexCoord2;", stageBit(Stage::Vertex)},
    {"gl_MultiTexCoord3", "in vec4 varc_MultiTexCoord3;", stageBit(Stage::Vertex)},
    {"gl_ModelViewProjectionMatrix", "uniform mat4 varc_ModelViewProjectionMatrix;", kAllStages},
    {"gl_ModelViewMatrix", "uniform mat4 varc_ModelViewMatrix;", kAllStages},
    {"gl_ProjectionMatrix", "uniform mat4 varc_ProjectionMatrix;", kAllStages},
    {"gl_NormalMatrix", "uniform mat3 varc_NormalMatrix;", kAllStages},
    {"gl_ModelViewMatrixInverseTranspose", "uniform mat4 varc_ModelViewMatrixInverseTranspose;",
     kAllStages},
    // A plain vec4 uniform, wrapped in the struct the source reads (`gl_LightModel.ambient`):
    // the runtime sets uniforms member by name, and a struct member would hide the vec4.
    {"gl_LightModel",
     "struct varc_LightModelParameters { vec4 ambient; };\n"
     "uniform vec4 varc_LightModelAmbient;\n"
     "#define varc_LightModel varc_LightModelParameters(varc_LightModelAmbient)",
     kAllStages},
    {"gl_FragColor", "out vec4 varc_FragColor;", stageBit(Stage::Fragment)},
};

// Texture functions of GLSL before 1.30, which Vulkan GLSL reads as types (texture2D is a
// separate-image type there): each becomes its generic overload.
constexpr std::pair<const char*, const char*> kLegacyTextureFunctions[] = {
    {"texture2D", "texture"},       {"texture2DProj", "textureProj"},
    {"texture2DLod", "textureLod"}, {"texture2DProjLod", "textureProjLod"},
    {"textureCube", "texture"},     {"textureCubeLod", "textureLod"},
    {"texture3D", "texture"},       {"texture3DLod", "textureLod"},
};

bool mentions(std::string_view source, std::string_view name) {
    for (size_t at = source.find(name); at != std::string_view::npos;
         at = source.find(name, at + 1)) {
        size_t end = at + name.size();
        char next = end < source.size() ? source[end] : ' ';
        bool identifierContinues = std::isalnum(static_cast<unsigned char>(next)) || next == '_';
        if (!identifierContinues) return true;
    }
    return false;
}

// Whether |source| calls |function|: the name as a whole identifier followed by '('.
bool calls(std::string_view source, std::string_view function) {
    for (size_t at = source.find(function); at != std::string_view::npos;
         at = source.find(function, at + 1)) {
        if (at > 0 &&
            (std::isalnum(static_cast<unsigned char>(source[at - 1])) || source[at - 1] == '_')) {
            continue;
        }
        size_t next = source.find_first_not_of(" \t", at + function.size());
        if (next != std::string_view::npos && source[next] == '(') return true;
    }
    return false;
}

// The number after `#version`, or kLegacyGlslVersion; sets |es| for "#version 300 es".
int declaredVersion(std::string_view source, bool& es) {
    es = false;
    size_t at = source.find("#version");
    if (at == std::string_view::npos) return kLegacyGlslVersion;
    size_t end = source.find('\n', at);
    std::string line(source.substr(at + 8, end == std::string_view::npos ? end : end - at - 8));
    es = line.find("es") != std::string::npos;
    return std::atoi(line.c_str());
}

bool directiveSetsNextLine(std::string_view source) {
    bool es = false;
    int version = declaredVersion(source, es);
    return es ? version >= 300 : version >= 330;
}

// Rewrites one "#line N rest" line to "#line N-1 rest"; other lines are returned unchanged.
std::string shiftLineDirective(std::string_view line) {
    size_t hash = line.find_first_not_of(" \t");
    if (hash == std::string_view::npos || line[hash] != '#') return std::string(line);
    size_t word = line.find_first_not_of(" \t", hash + 1);
    if (word == std::string_view::npos || line.substr(word, 4) != "line") return std::string(line);
    size_t number = line.find_first_not_of(" \t", word + 4);
    size_t numberEnd = line.find_first_not_of("0123456789", number);
    if (number == std::string_view::npos || numberEnd == number) return std::string(line);
    long value = std::atol(std::string(line.substr(number, numberEnd - number)).c_str());
    return std::string(line.substr(0, number)) + std::to_string(value - 1) +
           std::string(line.substr(numberEnd == std::string_view::npos ? line.size() : numberEnd));
}

}  // namespace

std::string toGlslLineConvention(std::string_view source) {
    if (directiveSetsNextLine(source)) return std::string(source);
    std::string result;
    result.reserve(source.size());
    while (!source.empty()) {
        size_t end = source.find('\n');
        std::string_view line = source.substr(0, end);
        result += shiftLineDirective(line);
        if (end == std::string_view::npos) break;
        result += '\n';
        source.remove_prefix(end + 1);
    }
    return result;
}

std::string legacyGlslPreamble(std::string_view source, Stage stage) {
    std::string text;
    for (const LegacyBuiltin& builtin : kBuiltins) {
        if (!hasStage(builtin.stages, stage) || !mentions(source, builtin.name)) continue;
        std::string name = builtin.name;
        text += std::string(builtin.declaration) + "\n";
        text += "#define " + name + " varc_" + name.substr(3) + "\n";
    }
    for (const auto& [legacy, generic] : kLegacyTextureFunctions) {
        if (calls(source, legacy)) {
            text += "#define " + std::string(legacy) + " " + generic + "\n";
        }
    }
    if (stage == Stage::Vertex) text += "#define varying out\n";
    if (stage == Stage::Fragment) text += "#define varying in\n";
    return text;
}

}  // namespace varc::driver
