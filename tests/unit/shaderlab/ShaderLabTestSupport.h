// SPDX-License-Identifier: Apache-2.0
// Test helpers for the ShaderLab parser: trim-margin text, parse-and-collect, fixture reading.
#pragma once

#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

#include "varc/core/Diagnostic.h"
#include "varc/shaderlab/ShaderLabParser.h"

namespace varc::shaderlab::testing {

// The FileId every inline test text is parsed as.
inline constexpr FileId kTestFile = 7;

// Strips the margin of an indented raw string: the first line when empty, the last line when
// blank, and on every other line the leading blanks and one '|'.
//   trimMargin(R"(
//       |Shader "A" {
//       |}
//   )") == "Shader \"A\" {\n}\n"
inline std::string trimMargin(std::string_view text) {
    std::string out;
    size_t start = 0;
    bool first = true;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        bool last = end == std::string_view::npos;
        std::string_view line = text.substr(start, last ? std::string_view::npos : end - start);
        size_t bar = line.find_first_not_of(" \t");
        bool blank = bar == std::string_view::npos;
        if (!((first || last) && blank)) {
            if (blank)
                line = {};
            else if (line[bar] == '|')
                line = line.substr(bar + 1);
            out.append(line).append("\n");
        }
        if (last) break;
        first = false;
        start = end + 1;
    }
    return out;
}

// The outcome of one parse: the AST (or nullopt) and every diagnostic reported.
struct ParseOutcome {
    std::optional<ShaderFile> shader;
    DiagnosticList diagnostics;

    // The first diagnostic's message, or "" when there is none.
    std::string firstMessage() const {
        return diagnostics.diagnostics().empty() ? "" : diagnostics.diagnostics()[0].message;
    }
    SourceLocation firstLocation() const {
        return diagnostics.diagnostics().empty() ? SourceLocation{}
                                                 : diagnostics.diagnostics()[0].location;
    }
};

inline ParseOutcome parse(std::string_view text) {
    ParseOutcome outcome;
    outcome.shader = parseShaderLab(text, kTestFile, outcome.diagnostics);
    return outcome;
}

// Parses `Shader "T" { SubShader { Pass { <passBody> } } }`, all on line 1.
inline ParseOutcome parsePassBody(std::string_view passBody) {
    return parse("Shader \"T\" { SubShader { Pass { " + std::string(passBody) + " } } }");
}

// Reads a whole file; "" when it cannot be read (tests then fail on their expectations).
inline std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Line |line| (1-based) of |text| without its newline.
inline std::string lineOf(std::string_view text, uint32_t line) {
    size_t start = 0;
    for (uint32_t i = 1; i < line && start != std::string_view::npos; ++i) {
        start = text.find('\n', start);
        if (start != std::string_view::npos) ++start;
    }
    if (start == std::string_view::npos) return {};
    size_t end = text.find('\n', start);
    return std::string(text.substr(start, end == std::string_view::npos ? end : end - start));
}

// The first line of |text| (up to the first '\n').
inline std::string firstLine(std::string_view text) {
    return std::string(text.substr(0, text.find('\n')));
}

}  // namespace varc::shaderlab::testing
