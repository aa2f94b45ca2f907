// SPDX-License-Identifier: Apache-2.0
// A GLSLPROGRAM's `#version` directive, put where glslang needs it and mapped to a version Vulkan
// SPIR-V accepts.
#include "varc/driver/GlslVersionDirective.h"

#include <cstdlib>

namespace varc::driver {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t'; }

// Where the line starting at |start| has a `#version` directive: the offset after "version", or
// npos for any other line.
size_t versionDirectiveEnd(std::string_view text, size_t start) {
    size_t at = start;
    while (at < text.size() && isBlank(text[at])) ++at;
    if (at >= text.size() || text[at] != '#') return std::string_view::npos;
    ++at;
    while (at < text.size() && isBlank(text[at])) ++at;
    constexpr std::string_view kVersion = "version";
    if (text.substr(at, kVersion.size()) != kVersion) return std::string_view::npos;
    at += kVersion.size();
    if (at < text.size() && !isBlank(text[at]) && text[at] != '\n' && text[at] != '\r')
        return std::string_view::npos;
    return at;
}

// "310 es" for "300 es", "" for "100", else |arguments| as written (without a trailing '\r').
std::string mappedArguments(std::string_view arguments) {
    while (!arguments.empty() && (isBlank(arguments.front()))) arguments.remove_prefix(1);
    while (!arguments.empty() && (isBlank(arguments.back()) || arguments.back() == '\r'))
        arguments.remove_suffix(1);
    int number = std::atoi(std::string(arguments).c_str());
    if (number == 100) return "";
    if (number == 300 && arguments.find("es") != std::string_view::npos) return "310 es";
    return std::string(arguments);
}

}  // namespace

std::string hoistGlslVersion(std::string_view text) {
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        size_t argumentsAt = versionDirectiveEnd(text, start);
        if (argumentsAt != std::string_view::npos) {
            std::string arguments = mappedArguments(text.substr(argumentsAt, end - argumentsAt));
            std::string directive = arguments.empty() ? "" : "#version " + arguments;
            if (start == 0) return directive + std::string(text.substr(end));  // first already
            std::string result = directive.empty() ? "" : directive + "\n";
            // The directive's line stays, empty: the lines after it keep their numbers. The line
            // added above shifts only what precedes varc's first `#line` marker.
            result.append(text.substr(0, start));
            result.append(text.substr(end));
            return result;
        }
        start = end + 1;
    }
    return std::string(text);
}

}  // namespace varc::driver
