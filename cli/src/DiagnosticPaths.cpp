// SPDX-License-Identifier: Apache-2.0
// Source paths as CI tools want them: relative to the current folder where possible.
#include "DiagnosticPaths.h"

#include <cctype>
#include <filesystem>
#include <system_error>

namespace varc::cli {

namespace {

bool isUnreserved(unsigned char c) {
    return std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/';
}

}  // namespace

std::string pathForCi(const std::string& path) {
    std::filesystem::path given = std::filesystem::path(path).lexically_normal();
    if (!given.is_absolute()) return given.string();
    std::error_code error;
    std::filesystem::path current = std::filesystem::current_path(error);
    if (error) return given.string();
    std::filesystem::path relative = given.lexically_relative(current);
    if (relative.empty() || *relative.begin() == "..") return given.string();
    return relative.string();
}

std::string formatForCi(SourceLocation location, const includes::SourceMap& sourceMap) {
    if (!location.isKnown()) return "";
    std::string text = pathForCi(sourceMap.path(location.file));
    if (location.line > 0) text += ":" + std::to_string(location.line);
    if (location.line > 0 && location.column > 0) text += ":" + std::to_string(location.column);
    return text;
}

std::string pathUri(const std::string& path) {
    static const char kHex[] = "0123456789ABCDEF";
    std::string ciPath = pathForCi(path);
    std::string uri = !ciPath.empty() && ciPath.front() == '/' ? "file://" : "";
    for (unsigned char c : ciPath) {
        if (isUnreserved(c)) {
            uri += static_cast<char>(c);
        } else {
            uri += '%';
            uri += kHex[c >> 4];
            uri += kHex[c & 15];
        }
    }
    return uri;
}

}  // namespace varc::cli
