// SPDX-License-Identifier: Apache-2.0
// What the pass generator of a surface program needs to know about the user's code.
#include "varc/frontend/SurfaceAnalysis.h"

#include <algorithm>
#include <regex>

#include "varc/core/Trim.h"

namespace varc::frontend {

namespace {

bool isIdentifierChar(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f'; }

size_t skipSpaces(std::string_view text, size_t i) {
    while (i < text.size() && isSpace(text[i])) ++i;
    return i;
}

// The characters isSpace() accepts (no \v), for trim().
constexpr std::string_view kSpaces = " \t\r\n\f";

// The position of the next whole-word |word| in |text| at or after |from|, or npos.
size_t findWord(std::string_view text, std::string_view word, size_t from) {
    while (from < text.size()) {
        size_t at = text.find(word, from);
        if (at == std::string_view::npos) return at;
        bool startOk = at == 0 || !isIdentifierChar(text[at - 1]);
        size_t end = at + word.size();
        bool endOk = end >= text.size() || !isIdentifierChar(text[end]);
        if (startOk && endOk) return at;
        from = at + 1;
    }
    return std::string_view::npos;
}

// The position of the bracket closing the one at |open| (text[open] is '(' '{' or '['), or npos.
size_t matching(std::string_view text, size_t open) {
    char opener = text[open];
    char closer = opener == '(' ? ')' : opener == '{' ? '}' : ']';
    int depth = 0;
    for (size_t i = open; i < text.size(); ++i) {
        if (text[i] == opener) ++depth;
        if (text[i] == closer && --depth == 0) return i;
    }
    return std::string_view::npos;
}

// Splits |text| at top-level (outside brackets) |separator|s.
std::vector<std::string_view> splitTopLevel(std::string_view text, char separator) {
    std::vector<std::string_view> parts;
    int depth = 0;
    size_t start = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (c == '(' || c == '[' || c == '{') ++depth;
        if (c == ')' || c == ']' || c == '}') --depth;
        if (c == separator && depth == 0) {
            parts.push_back(text.substr(start, i - start));
            start = i + 1;
        }
    }
    parts.push_back(text.substr(start));
    return parts;
}

// The identifiers of |declaration| in order ("inout SurfaceOutput o" -> inout, SurfaceOutput, o),
// up to a `:` semantic or an array size.
std::vector<std::string_view> identifiersOf(std::string_view declaration) {
    std::vector<std::string_view> words;
    size_t i = 0;
    while (i < declaration.size()) {
        char c = declaration[i];
        if (c == ':' || c == '[' || c == '=') break;
        if (!isIdentifierChar(c)) {
            ++i;
            continue;
        }
        size_t start = i;
        while (i < declaration.size() && isIdentifierChar(declaration[i])) ++i;
        words.push_back(declaration.substr(start, i - start));
    }
    return words;
}

// Where the function |name| is defined: the positions of its '(' and its body's '{', or nullopt.
std::optional<std::pair<size_t, size_t>> findDefinition(std::string_view text,
                                                        std::string_view name) {
    for (size_t at = findWord(text, name, 0); at != std::string_view::npos;
         at = findWord(text, name, at + 1)) {
        size_t open = skipSpaces(text, at + name.size());
        if (open >= text.size() || text[open] != '(') continue;
        size_t close = matching(text, open);
        if (close == std::string_view::npos) return std::nullopt;
        size_t next = skipSpaces(text, close + 1);
        if (next < text.size() && text[next] == ':') {  // a return semantic
            next = skipSpaces(text, next + 1);
            while (next < text.size() && isIdentifierChar(text[next])) ++next;
            next = skipSpaces(text, next);
        }
        if (next < text.size() && text[next] == '{') return std::make_pair(open, next);
    }
    return std::nullopt;
}

std::optional<std::string_view> structBody(std::string_view text, std::string_view name) {
    for (size_t at = findWord(text, "struct", 0); at != std::string_view::npos;
         at = findWord(text, "struct", at + 1)) {
        size_t nameAt = skipSpaces(text, at + 6);
        if (text.substr(nameAt, name.size()) != name) continue;
        size_t open = skipSpaces(text, nameAt + name.size());
        if (nameAt + name.size() < text.size() && isIdentifierChar(text[nameAt + name.size()])) {
            continue;
        }
        if (open >= text.size() || text[open] != '{') continue;
        size_t close = matching(text, open);
        if (close == std::string_view::npos) return std::nullopt;
        return text.substr(open + 1, close - open - 1);
    }
    return std::nullopt;
}

// The type of a parameter declaration: the identifier before its name, qualifiers skipped.
std::string parameterType(std::string_view parameter) {
    std::vector<std::string_view> words = identifiersOf(parameter);
    if (words.size() < 2) return "";
    return std::string(words[words.size() - 2]);
}

std::string parameterName(std::string_view parameter) {
    std::vector<std::string_view> words = identifiersOf(parameter);
    return words.empty() ? "" : std::string(words.back());
}

// Whether |body| assigns |object|.Normal (`o.Normal = ...`, `o.Normal += ...`).
bool assignsNormal(std::string_view body, std::string_view object) {
    for (size_t at = findWord(body, object, 0); at != std::string_view::npos;
         at = findWord(body, object, at + 1)) {
        size_t i = skipSpaces(body, at + object.size());
        if (i >= body.size() || body[i] != '.') continue;
        i = skipSpaces(body, i + 1);
        if (body.substr(i, 6) != "Normal" ||
            (i + 6 < body.size() && isIdentifierChar(body[i + 6]))) {
            continue;
        }
        i = skipSpaces(body, i + 6);
        if (i < body.size() && std::string_view("+-*/").find(body[i]) != std::string_view::npos) {
            ++i;
        }
        if (i < body.size() && body[i] == '=' && (i + 1 >= body.size() || body[i + 1] != '=')) {
            return true;
        }
    }
    return false;
}

bool readLightingShape(const std::vector<std::string>& parameters, LightingShape& shape) {
    bool gi = !parameters.empty() &&
              parameterType(parameters.back()).find("UnityGI") != std::string::npos;
    if (gi && parameters.size() == 2)
        shape = LightingShape::Gi;
    else if (gi && parameters.size() == 3)
        shape = LightingShape::GiViewDir;
    else if (!gi && parameters.size() == 3)
        shape = LightingShape::Legacy;
    else if (!gi && parameters.size() == 4)
        shape = LightingShape::LegacyViewDir;
    else
        return false;
    return true;
}

// Fills the vertex modifier's facts. Returns false after reporting a missing function.
bool readVertexFunction(const shaderlab::SurfaceProgram& program, SurfaceFacts& facts,
                        DiagnosticSink& sink) {
    const std::string& name = program.options.vertexFunction;
    if (name.empty()) return true;
    auto parameters = functionParameters(facts.programText, name);
    if (!parameters || parameters->empty() || parameters->size() > 2) {
        sink.error(program.pragma, "the vertex function '" + name + "' of '#pragma surface' " +
                                       (parameters ? "has neither the shape 'void " + name +
                                                         "(inout appdata_full v)' nor '(inout "
                                                         "appdata_full v, out Input o)'"
                                                   : "is not defined"));
        return false;
    }
    std::string type = parameterType(parameters->front());
    if (!type.empty()) facts.vertexInputType = type;
    facts.vertexWritesInput = parameters->size() == 2;
    return true;
}

}  // namespace

bool SurfaceFacts::hasInputMember(std::string_view name) const {
    return std::find(inputMembers.begin(), inputMembers.end(), name) != inputMembers.end();
}

bool SurfaceFacts::mentions(std::string_view name) const {
    return findWord(programText, name, 0) != std::string_view::npos;
}

std::string withoutComments(std::string_view text) {
    std::string out(text);
    size_t i = 0;
    while (i < out.size()) {
        if (out[i] == '"') {  // a string literal: skip it whole
            size_t end = i + 1;
            while (end < out.size() && out[end] != '"' && out[end] != '\n') {
                end += out[end] == '\\' ? 2 : 1;
            }
            i = end + 1;
        } else if (out.compare(i, 2, "//") == 0) {
            while (i < out.size() && out[i] != '\n') out[i++] = ' ';
        } else if (out.compare(i, 2, "/*") == 0) {
            size_t end = out.find("*/", i + 2);
            end = end == std::string::npos ? out.size() : end + 2;
            for (; i < end; ++i) {
                if (out[i] != '\n') out[i] = ' ';
            }
        } else {
            ++i;
        }
    }
    return out;
}

// Blanks every `#pragma` line of |text| (keeping the newline): `alphatest:_Cutoff` on the
// `#pragma surface` line does not declare `_Cutoff`.
void blankPragmaLines(std::string& text) {
    size_t start = 0;
    while (start < text.size()) {
        size_t end = std::min(text.find('\n', start), text.size());
        size_t first = skipSpaces(std::string_view(text).substr(0, end), start);
        if (first < end && text[first] == '#') {
            size_t word = skipSpaces(std::string_view(text).substr(0, end), first + 1);
            if (text.compare(word, 6, "pragma") == 0) {
                std::fill(text.begin() + static_cast<std::ptrdiff_t>(start),
                          text.begin() + static_cast<std::ptrdiff_t>(end), ' ');
            }
        }
        start = end + 1;
    }
}

std::optional<std::vector<std::string>> functionParameters(std::string_view text,
                                                           std::string_view name) {
    auto definition = findDefinition(text, name);
    if (!definition) return std::nullopt;
    size_t open = definition->first;
    std::string_view list = text.substr(open + 1, matching(text, open) - open - 1);
    std::vector<std::string> parameters;
    if (trim(list, kSpaces).empty() || trim(list, kSpaces) == "void") return parameters;
    for (std::string_view part : splitTopLevel(list, ','))
        parameters.emplace_back(trim(part, kSpaces));
    return parameters;
}

std::optional<std::vector<std::string>> structMembers(std::string_view text,
                                                      std::string_view name) {
    std::optional<std::string_view> body = structBody(text, name);
    if (!body) return std::nullopt;
    std::string code;  // the body without preprocessor lines
    size_t start = 0;
    while (start < body->size()) {
        size_t end = std::min(body->find('\n', start), body->size());
        std::string_view line = body->substr(start, end - start);
        std::string_view trimmed = trim(line, kSpaces);
        if (trimmed.empty() || trimmed[0] != '#') code.append(line).push_back('\n');
        start = end + 1;
    }
    std::vector<std::string> members;
    std::vector<std::string_view> declarations = splitTopLevel(code, ';');
    declarations.pop_back();  // after the last ';': INTERNAL_DATA or nothing
    for (std::string_view declaration : declarations) {
        std::vector<std::string_view> declarators = splitTopLevel(declaration, ',');
        for (size_t i = 0; i < declarators.size(); ++i) {
            std::vector<std::string_view> words = identifiersOf(declarators[i]);
            if (words.empty() || (i == 0 && words.size() < 2)) continue;
            members.emplace_back(words.back());
        }
    }
    return members;
}

namespace {

// The Input member with a face semantic, if any (SurfaceFacts::faceMember).
void readFaceMember(std::string_view inputBody, SurfaceFacts& facts) {
    static const std::regex kFace(R"((\w+)\s+(\w+)\s*:\s*(VFACE|SV_IsFrontFace)\b)",
                                  std::regex::icase);
    std::string body(inputBody);
    std::smatch match;
    if (!std::regex_search(body, match, kFace)) return;
    facts.faceIsBool = match[1].str() == "bool";
    facts.faceMember = match[2].str();
    // HLSL semantics are case-insensitive; the generated code names the one written.
    facts.faceSemantic = match[3].str();
}

}  // namespace

std::optional<SurfaceFacts> analyzeSurface(const shaderlab::SurfaceProgram& program,
                                           std::string_view text, DiagnosticSink& sink) {
    SurfaceFacts facts;
    facts.programText = withoutComments(text);
    blankPragmaLines(facts.programText);
    const std::string& source = facts.programText;
    auto surf = functionParameters(source, program.function);
    if (!surf || surf->size() != 2) {
        sink.error(program.pragma, "the surface function '" + program.function +
                                       "' of '#pragma surface' " +
                                       (surf ? "must have the shape 'void " + program.function +
                                                   "(Input IN, inout SurfaceOutput o)'"
                                             : "is not defined"));
        return std::nullopt;
    }
    facts.outputType = parameterType((*surf)[1]);
    auto definition = findDefinition(source, program.function);
    size_t bodyOpen = definition->second;
    std::string_view body =
        std::string_view(source).substr(bodyOpen, matching(source, bodyOpen) - bodyOpen);
    facts.writesNormal = assignsNormal(body, parameterName((*surf)[1]));
    facts.surfaceDiscards = findWord(body, "clip", 0) != std::string_view::npos ||
                            findWord(body, "discard", 0) != std::string_view::npos;
    facts.inputMembers = structMembers(source, "Input").value_or(std::vector<std::string>{});
    std::optional<std::string_view> inputBody = structBody(source, "Input");
    facts.inputHasInternalData =
        inputBody && findWord(*inputBody, "INTERNAL_DATA", 0) != std::string_view::npos;
    if (inputBody) readFaceMember(*inputBody, facts);
    facts.outputMembers =
        structMembers(source, facts.outputType).value_or(std::vector<std::string>{});
    if (!readVertexFunction(program, facts, sink)) return std::nullopt;
    facts.vertexInputMembers =
        structMembers(source, facts.vertexInputType)
            .value_or(std::vector<std::string>{"vertex", "tangent", "normal", "texcoord",
                                               "texcoord1", "texcoord2", "texcoord3", "color"});
    std::string lighting = "Lighting" + program.lightingModel;
    auto parameters = functionParameters(source, lighting);
    if (!parameters || !readLightingShape(*parameters, facts.lighting)) {
        sink.error(program.pragma,
                   "the lighting function '" + lighting + "' of lighting model '" +
                       program.lightingModel + "' " +
                       (parameters ? "has a shape varc cannot call: (s, gi), (s, viewDir, gi), "
                                     "(s, lightDir, atten) or (s, lightDir, viewDir, atten)"
                                   : "is not defined (varc's include files define Lambert, "
                                     "BlinnPhong, Standard and StandardSpecular)"));
        return std::nullopt;
    }
    facts.hasGiFunction = findDefinition(source, lighting + "_GI").has_value();
    return facts;
}

}  // namespace varc::frontend
