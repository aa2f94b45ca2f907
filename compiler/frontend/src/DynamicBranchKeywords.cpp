// SPDX-License-Identifier: Apache-2.0
// `#pragma dynamic_branch` keywords in program text: declared as uniforms, tested only by `if`.
#include "varc/frontend/DynamicBranchKeywords.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <optional>
#include <tuple>

namespace varc::frontend {

namespace {

bool isIdentifierStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }

bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// |line| with every comment character blanked (so columns stay), continuing a block comment
// when |inBlock| and leaving |inBlock| set when one is still open at the end.
std::string withoutComments(std::string_view line, bool& inBlock) {
    std::string code(line);
    for (size_t i = 0; i < code.size(); ++i) {
        if (inBlock) {
            if (code.compare(i, 2, "*/") == 0) {
                code[i] = code[i + 1] = ' ';
                ++i;
                inBlock = false;
            } else {
                code[i] = ' ';
            }
        } else if (code.compare(i, 2, "//") == 0) {
            std::fill(code.begin() + static_cast<std::ptrdiff_t>(i), code.end(), ' ');
            break;
        } else if (code.compare(i, 2, "/*") == 0) {
            code[i] = code[i + 1] = ' ';
            ++i;
            inBlock = true;
        }
    }
    return code;
}

// The conditional directive |code| opens ("if", "elif", "ifdef", "ifndef") and the offset where
// its condition starts; nullopt for any other line.
std::optional<std::pair<std::string, size_t>> conditionalDirective(std::string_view code) {
    size_t i = code.find_first_not_of(" \t");
    if (i == std::string_view::npos || code[i] != '#') return std::nullopt;
    i = code.find_first_not_of(" \t", i + 1);
    if (i == std::string_view::npos) return std::nullopt;
    size_t end = i;
    while (end < code.size() && isIdentifierChar(code[end])) ++end;
    std::string name(code.substr(i, end - i));
    if (name != "if" && name != "elif" && name != "ifdef" && name != "ifndef") return std::nullopt;
    return std::make_pair(name, end);
}

// `#line N F` (F numeric, as IncludeResolver writes it): the next line's number and file.
std::optional<std::pair<uint32_t, FileId>> lineDirective(std::string_view code) {
    size_t i = code.find_first_not_of(" \t");
    if (i == std::string_view::npos || code[i] != '#') return std::nullopt;
    i = code.find_first_not_of(" \t", i + 1);
    if (i == std::string_view::npos || code.compare(i, 4, "line") != 0) return std::nullopt;
    size_t number = code.find_first_not_of(" \t", i + 4);
    if (number == i + 4 || number == std::string_view::npos) return std::nullopt;  // `#lines`
    uint32_t line = 0;
    FileId file = kNoFile;
    const char* first = code.data() + number;
    const char* last = code.data() + code.size();
    auto parsed = std::from_chars(first, last, line);
    if (parsed.ec != std::errc() || parsed.ptr == first) return std::nullopt;
    while (parsed.ptr < last && (*parsed.ptr == ' ' || *parsed.ptr == '\t')) ++parsed.ptr;
    if (parsed.ptr < last) std::from_chars(parsed.ptr, last, file);
    return std::make_pair(line, file);
}

std::string conditionalMessage(const std::string& directive, const std::string& keyword) {
    std::string head;
    if (directive == "ifdef") {
        head = "'#ifdef " + keyword + "' is always false";
    } else if (directive == "ifndef") {
        head = "'#ifndef " + keyword + "' is always true";
    } else {
        head = "'#" + directive + "' reads " + keyword + " as an undefined macro";
    }
    return head + ": " + keyword +
           " is a dynamic_branch keyword, which is a uniform and never a macro (as in Unity), "
           "so this code does not follow the keyword at run time; test it with 'if (" +
           keyword + ")'";
}

// Where the scan is in the expanded text: the location the next physical line maps to.
struct ScanPosition {
    FileId file = kNoFile;
    uint32_t line = 1;  // physical line until a #line says otherwise
};

}  // namespace

std::vector<std::string> dynamicBranchKeywords(const variants::PassKeywords& keywords) {
    std::vector<std::string> names;
    for (const variants::KeywordSetDecl& set : keywords.dynamicBranches) {
        for (const std::string& keyword : set.keywords) {
            if (!keyword.empty() && std::find(names.begin(), names.end(), keyword) == names.end())
                names.push_back(keyword);
        }
    }
    return names;
}

std::string declareDynamicBranchUniforms(std::string_view text,
                                         const variants::PassKeywords& keywords,
                                         shaderlab::ProgramLanguage language) {
    const char* type = language == shaderlab::ProgramLanguage::Glsl ? "uniform int " : "int ";
    std::vector<std::string> declared;
    std::string out;
    for (const variants::KeywordSetDecl& set : keywords.dynamicBranches) {
        std::string line;
        for (const std::string& keyword : set.keywords) {
            if (keyword.empty() ||
                std::find(declared.begin(), declared.end(), keyword) != declared.end())
                continue;
            declared.push_back(keyword);
            line += (line.empty() ? "" : " ") + std::string(type) + keyword + ";";
        }
        if (line.empty()) continue;
        if (set.location.isKnown()) {
            out += "#line " + std::to_string(set.location.line) + " " +
                   std::to_string(set.location.file) + "\n";
        }
        out += line + "\n";
    }
    if (out.empty()) return std::string(text);
    return out + std::string(text);
}

void warnPreprocessorTestsOfDynamicBranches(std::string_view text,
                                            const std::vector<std::string>& names,
                                            std::vector<SourceLocation>& reported,
                                            DiagnosticSink& sink) {
    if (names.empty()) return;
    ScanPosition position;
    bool inBlock = false;
    std::string continued;  // the directive a trailing backslash continues onto this line
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = std::min(text.find('\n', start), text.size());
        std::string_view physical = text.substr(start, end - start);
        if (!physical.empty() && physical.back() == '\r') physical.remove_suffix(1);
        start = end + 1;
        const bool wasInBlock = inBlock;
        std::string code = withoutComments(physical, inBlock);
        if (!wasInBlock && continued.empty()) {
            if (auto line = lineDirective(code)) {
                position = {line->second, line->first};
                if (start > text.size()) break;
                continue;
            }
        }
        const uint32_t lineNumber = position.line++;
        std::string directive = continued;
        size_t conditionStart = 0;
        if (directive.empty() && !wasInBlock) {
            auto opened = conditionalDirective(code);
            if (opened) std::tie(directive, conditionStart) = *opened;
        }
        continued = !directive.empty() && !physical.empty() && physical.back() == '\\'
                        ? directive
                        : std::string();
        if (directive.empty()) continue;
        for (size_t i = conditionStart; i < code.size();) {
            if (!isIdentifierStart(code[i]) || (i > 0 && isIdentifierChar(code[i - 1]))) {
                ++i;
                continue;
            }
            size_t wordEnd = i;
            while (wordEnd < code.size() && isIdentifierChar(code[wordEnd])) ++wordEnd;
            std::string word = code.substr(i, wordEnd - i);
            if (std::find(names.begin(), names.end(), word) != names.end()) {
                SourceLocation at{position.file, lineNumber, static_cast<uint32_t>(i + 1)};
                if (std::find(reported.begin(), reported.end(), at) == reported.end()) {
                    reported.push_back(at);
                    sink.warning(at, conditionalMessage(directive, word));
                }
            }
            i = wordEnd;
        }
        if (start > text.size()) break;
    }
}

}  // namespace varc::frontend
