// SPDX-License-Identifier: Apache-2.0
// Shared helpers for the includes tests: a resolver harness and the #line mapping checker.
#include "IncludeTestSupport.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <utility>

namespace varc::includes::testing {

namespace {

bool startsWith(std::string_view text, std::string_view prefix) {
    return text.substr(0, prefix.size()) == prefix;
}

// Parses "#line N F"; returns false for any other line.
bool parseLineDirective(std::string_view text, uint32_t& line, FileId& file) {
    if (!startsWith(text, "#line ")) return false;
    std::istringstream in{std::string(text.substr(6))};
    uint64_t parsedLine = 0;
    uint64_t parsedFile = 0;
    if (!(in >> parsedLine >> parsedFile)) return false;
    line = static_cast<uint32_t>(parsedLine);
    file = static_cast<FileId>(parsedFile);
    return true;
}

bool isWrapperLine(std::string_view text) {
    return startsWith(text, "#ifndef VARC_ONCE_") || startsWith(text, "#define VARC_ONCE_") ||
           startsWith(text, "#endif // VARC_ONCE_");
}

}  // namespace

std::string lines(std::initializer_list<std::string_view> items) {
    std::string text;
    for (std::string_view item : items) {
        text += item;
        text += '\n';
    }
    return text;
}

size_t countOf(std::string_view haystack, std::string_view needle) {
    size_t count = 0;
    for (size_t at = haystack.find(needle); at != std::string_view::npos;
         at = haystack.find(needle, at + needle.size())) {
        ++count;
    }
    return count;
}

std::vector<MappedLine> mapLines(const std::string& expanded) {
    std::vector<MappedLine> result;
    FileId file = kNoFile;
    uint32_t line = 0;
    std::istringstream in(expanded);
    std::string text;
    while (std::getline(in, text)) {
        if (parseLineDirective(text, line, file)) continue;
        if (isWrapperLine(text)) {
            result.push_back({text, kNoFile, 0});
            file = kNoFile;
            continue;
        }
        result.push_back({text, file, file == kNoFile ? 0 : line});
        ++line;
    }
    return result;
}

::testing::AssertionResult linesMapBack(const std::string& expanded, const SourceMap& map,
                                        const std::vector<SourceText>& roots) {
    std::map<std::pair<FileId, uint32_t>, uint32_t> firstLineColumn;
    for (const SourceText& root : roots) {
        firstLineColumn[{root.origin.file, root.origin.line}] = root.origin.column;
    }
    if (!startsWith(expanded, "#line ")) {
        return ::testing::AssertionFailure() << "expanded text does not start with #line";
    }
    size_t index = 0;
    for (const MappedLine& mapped : mapLines(expanded)) {
        ++index;
        if (isWrapperLine(mapped.text) || startsWith(mapped.text, "#error varc:")) continue;
        if (mapped.file == kNoFile) {
            return ::testing::AssertionFailure()
                   << "output line " << index << " has no mapping: '" << mapped.text << "'";
        }
        std::string expected = map.lineText(mapped.file, mapped.line);
        auto column = firstLineColumn.find({mapped.file, mapped.line});
        if (column != firstLineColumn.end() && column->second > 1) {
            expected = expected.substr(std::min<size_t>(column->second - 1, expected.size()));
        }
        if (expected != mapped.text) {
            return ::testing::AssertionFailure()
                   << "output line " << index << " '" << mapped.text << "' maps to "
                   << map.format({mapped.file, mapped.line, 0}) << " which is '" << expected << "'";
        }
    }
    return ::testing::AssertionSuccess();
}

std::vector<MappedLine> linesFrom(const std::string& expanded, const SourceMap& map,
                                  const std::string& path) {
    std::vector<MappedLine> result;
    std::optional<FileId> id = map.find(path);
    if (!id) return result;
    for (MappedLine& mapped : mapLines(expanded)) {
        if (mapped.file == *id) result.push_back(std::move(mapped));
    }
    return result;
}

Harness& Harness::file(const std::string& path, std::string contents) {
    fileSystem.add(path, std::move(contents));
    return *this;
}

Harness& Harness::includeDir(const std::string& dir) {
    options.includeDirs.push_back(dir);
    return *this;
}

Harness& Harness::builtinDir(const std::string& dir) {
    options.builtinDir = dir;
    return *this;
}

std::optional<ExpandedSource> Harness::expandFile(const std::string& path) {
    return expand({wholeFile(path)});
}

std::optional<ExpandedSource> Harness::expand(const std::vector<SourceText>& roots) {
    mLastRoots = roots;
    IncludeResolver resolver(fileSystem, sourceMap, options);
    return resolver.expand(roots, diagnostics);
}

SourceText Harness::root(const std::string& path, std::string text, uint32_t line,
                         uint32_t column) {
    std::optional<std::string> contents = fileSystem.read(path);
    FileId file = sourceMap.addFile(path, contents ? *contents : text);
    return {std::move(text), {file, line, column}};
}

SourceText Harness::wholeFile(const std::string& path) {
    std::optional<std::string> contents = fileSystem.read(path);
    EXPECT_TRUE(contents.has_value()) << "no file " << path;
    FileId file = sourceMap.addFile(path, contents.value_or(""));
    return {sourceMap.contents(file), {file, 1, 1}};
}

::testing::AssertionResult Harness::mapsBack(const ExpandedSource& expanded) const {
    return linesMapBack(expanded.text, sourceMap, mLastRoots);
}

FileId Harness::id(const std::string& path) const { return sourceMap.find(path).value_or(kNoFile); }

}  // namespace varc::includes::testing
