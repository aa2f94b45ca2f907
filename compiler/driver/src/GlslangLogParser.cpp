// SPDX-License-Identifier: Apache-2.0
// Turns glslang's info log into Diagnostics located in the original files.
#include "varc/driver/GlslangLogParser.h"

#include <cctype>
#include <charconv>
#include <optional>

#include "varc/core/Trim.h"

namespace varc::driver {

namespace {

std::optional<uint32_t> parseNumber(std::string_view text) {
    uint32_t value = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// 1-based column of the first whole-word occurrence of |token| in |line|, or 0.
uint32_t findColumn(std::string_view line, std::string_view token) {
    if (token.empty()) return 0;
    for (size_t at = line.find(token); at != std::string_view::npos;
         at = line.find(token, at + 1)) {
        bool startOk =
            at == 0 || !isIdentifierChar(line[at - 1]) || !isIdentifierChar(token.front());
        size_t end = at + token.size();
        bool endOk =
            end >= line.size() || !isIdentifierChar(line[end]) || !isIdentifierChar(token.back());
        if (startOk && endOk) return static_cast<uint32_t>(at + 1);
    }
    return 0;
}

bool isSummaryLine(std::string_view body) {
    return body.find("compilation errors") != std::string_view::npos ||
           body.find("compilation warnings") != std::string_view::npos ||
           body.find("parsing failed") != std::string_view::npos ||
           body.find("No code generated") != std::string_view::npos;
}

// "'tok' : message" -> message + " 'tok'"; anything else unchanged.
std::string formatMessage(std::string_view rest, std::string& token) {
    rest = trim(rest);
    if (rest.size() >= 2 && rest.front() == '\'') {
        size_t close = rest.find("' :");
        if (close != std::string_view::npos) {
            token = std::string(rest.substr(1, close - 1));
            std::string message(trim(rest.substr(close + 3)));
            return token.empty() ? message : message + " '" + token + "'";
        }
    }
    return std::string(rest);
}

std::optional<Diagnostic> parseLine(std::string_view line, const includes::SourceMap& sourceMap) {
    Severity severity = Severity::Error;
    std::string_view body = trim(line);
    if (body.empty()) return std::nullopt;
    if (body.starts_with("ERROR:")) {
        body = trim(body.substr(6));
    } else if (body.starts_with("WARNING:")) {
        severity = Severity::Warning;
        body = trim(body.substr(8));
    } else if (body.starts_with("(")) {
        return std::nullopt;  // "(16): error at column 86, ..." columns of the preprocessed text
    }
    if (isSummaryLine(body)) return std::nullopt;
    Diagnostic diagnostic{severity, {}, std::string(body), {}};
    size_t firstColon = body.find(':');
    size_t secondColon =
        firstColon == std::string_view::npos ? firstColon : body.find(':', firstColon + 1);
    if (secondColon == std::string_view::npos) return diagnostic;
    auto file = parseNumber(body.substr(0, firstColon));
    auto lineNumber = parseNumber(body.substr(firstColon + 1, secondColon - firstColon - 1));
    if (!file || !lineNumber || *file >= sourceMap.size()) return diagnostic;
    std::string token;
    diagnostic.message = formatMessage(body.substr(secondColon + 1), token);
    uint32_t column = findColumn(sourceMap.lineText(*file, *lineNumber), token);
    diagnostic.location = {*file, *lineNumber, column};
    return diagnostic;
}

bool sameDiagnostic(const Diagnostic& a, const Diagnostic& b) {
    return a.severity == b.severity && a.location == b.location && a.message == b.message;
}

}  // namespace

std::vector<Diagnostic> parseGlslangLog(std::string_view log,
                                        const includes::SourceMap& sourceMap) {
    std::vector<Diagnostic> diagnostics;
    while (!log.empty()) {
        size_t end = log.find('\n');
        std::string_view line = log.substr(0, end);
        log = end == std::string_view::npos ? std::string_view() : log.substr(end + 1);
        auto diagnostic = parseLine(line, sourceMap);
        if (!diagnostic) continue;
        bool duplicate = false;
        for (const Diagnostic& seen : diagnostics)
            duplicate = duplicate || sameDiagnostic(seen, *diagnostic);
        if (!duplicate) diagnostics.push_back(std::move(*diagnostic));
    }
    return diagnostics;
}

}  // namespace varc::driver
