// SPDX-License-Identifier: Apache-2.0
// The include chain of a line of expanded source, read back from its `#line` directives.
#include "IncludeChain.h"

#include <algorithm>
#include <charconv>
#include <map>
#include <optional>
#include <string_view>

namespace varc::driver {

namespace {

struct Marker {
    uint32_t line = 0;
    FileId file = kNoFile;
};

// `#line <line> <fileId>` exactly as writeLineDirective writes it, else nullopt.
std::optional<Marker> parseMarker(std::string_view text) {
    constexpr std::string_view kPrefix = "#line ";
    if (text.substr(0, kPrefix.size()) != kPrefix) return std::nullopt;
    text.remove_prefix(kPrefix.size());
    size_t space = text.find(' ');
    if (space == std::string_view::npos) return std::nullopt;
    Marker marker;
    auto line = std::from_chars(text.data(), text.data() + space, marker.line);
    auto file = std::from_chars(text.data() + space + 1, text.data() + text.size(), marker.file);
    if (line.ec != std::errc() || line.ptr != text.data() + space || file.ec != std::errc() ||
        file.ptr != text.data() + text.size()) {
        return std::nullopt;
    }
    return marker;
}

// Where each file other than |root| was first included from.
std::map<FileId, SourceLocation> includeSites(const std::string& text, FileId root) {
    std::map<FileId, SourceLocation> sites;
    std::vector<FileId> stack;
    SourceLocation current;  // the location of the next line of text
    size_t begin = 0;
    while (begin < text.size()) {
        size_t end = text.find('\n', begin);
        if (end == std::string::npos) end = text.size();
        if (auto marker = parseMarker(std::string_view(text).substr(begin, end - begin))) {
            auto open = std::find(stack.begin(), stack.end(), marker->file);
            if (marker->file == root) {
                stack.assign(1, root);  // a block of the program text itself
            } else if (open != stack.end()) {
                stack.erase(open + 1, stack.end());  // back in a file still open
            } else {
                if (!stack.empty()) sites.emplace(marker->file, current);
                stack.push_back(marker->file);
            }
            current = {marker->file, marker->line, 0};
        } else {
            ++current.line;
        }
        begin = end + 1;
    }
    return sites;
}

// Whether line |site| names |file|'s file name, as its #include must.
bool namesFile(SourceLocation site, FileId file, const includes::SourceMap& sourceMap) {
    const std::string& path = sourceMap.path(file);
    size_t slash = path.find_last_of('/');
    std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    std::string line = sourceMap.lineText(site.file, site.line);
    return line.find("include") != std::string::npos && line.find(name) != std::string::npos;
}

}  // namespace

std::vector<DiagnosticNote> includeChainNotes(const std::string& expandedText, FileId root,
                                              FileId file, const includes::SourceMap& sourceMap) {
    std::map<FileId, SourceLocation> sites = includeSites(expandedText, root);
    std::vector<DiagnosticNote> notes;
    for (auto site = sites.find(file); site != sites.end() && notes.size() < sites.size() &&
                                       namesFile(site->second, site->first, sourceMap);
         site = sites.find(site->second.file)) {
        notes.push_back({site->second, "in file included from here"});
    }
    return notes;
}

std::vector<Diagnostic> withIncludeChains(std::vector<Diagnostic> diagnostics,
                                          const std::string& expandedText, FileId root,
                                          const includes::SourceMap& sourceMap) {
    for (Diagnostic& diagnostic : diagnostics) {
        if (!diagnostic.location.isKnown() || diagnostic.location.file == root) continue;
        std::vector<DiagnosticNote> notes =
            includeChainNotes(expandedText, root, diagnostic.location.file, sourceMap);
        notes.insert(notes.end(), diagnostic.notes.begin(), diagnostic.notes.end());
        diagnostic.notes = std::move(notes);
    }
    return diagnostics;
}

}  // namespace varc::driver
