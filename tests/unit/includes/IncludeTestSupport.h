// SPDX-License-Identifier: Apache-2.0
// Shared helpers for the includes tests: a resolver harness and the #line mapping checker.
#pragma once

#include <gtest/gtest.h>

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/includes/FileSystem.h"
#include "varc/includes/IncludeResolver.h"
#include "varc/includes/SourceMap.h"

namespace varc::includes::testing {

// Joins |items| as lines, each ending in '\n' (an inline golden without escaping noise).
std::string lines(std::initializer_list<std::string_view> items);

// Counts non-overlapping occurrences of |needle| in |haystack|.
size_t countOf(std::string_view haystack, std::string_view needle);

// One line of expanded text with the source position the #line directives give it.
struct MappedLine {
    std::string text;
    FileId file = kNoFile;  // kNoFile: varc's own line (wrapper guard) or unknown mapping
    uint32_t line = 0;
};

// Walks |expanded| like a C preprocessor does for `#line N F`: the directive itself is not
// returned; each other line gets (F, N), (F, N + 1), ... Lines after varc's VARC_ONCE wrapper
// lines have no mapping until the next #line.
std::vector<MappedLine> mapLines(const std::string& expanded);

// The key property: every non-#line line of |expanded| equals the source line it maps to
// (SourceMap::lineText), the first line of each root compared from its origin column.
// `#error varc:` replacement lines and VARC_ONCE wrapper lines are varc's own and skipped.
::testing::AssertionResult linesMapBack(const std::string& expanded, const SourceMap& map,
                                        const std::vector<SourceText>& roots);

// The expanded lines that map to |path| (in order), for "this file was spliced N times".
std::vector<MappedLine> linesFrom(const std::string& expanded, const SourceMap& map,
                                  const std::string& path);

// An InMemoryFileSystem, a SourceMap and options, with shortcuts to expand.
class Harness {
public:
    Harness& file(const std::string& path, std::string contents);
    Harness& includeDir(const std::string& dir);
    Harness& builtinDir(const std::string& dir);

    // Expands the whole file at |path| (registered first) as the only root.
    std::optional<ExpandedSource> expandFile(const std::string& path);
    // Expands |roots| with one fresh resolver.
    std::optional<ExpandedSource> expand(const std::vector<SourceText>& roots);
    // A root made of |text| that lives in registered |path| at |line|:|column|.
    SourceText root(const std::string& path, std::string text, uint32_t line = 1,
                    uint32_t column = 1);
    // The whole registered file at |path| as a root (registering it from the file system).
    SourceText wholeFile(const std::string& path);
    // Checks linesMapBack for |expanded| against the roots of the last expand call.
    ::testing::AssertionResult mapsBack(const ExpandedSource& expanded) const;
    FileId id(const std::string& path) const;

    InMemoryFileSystem fileSystem;
    SourceMap sourceMap;
    IncludeOptions options;
    DiagnosticList diagnostics;

private:
    std::vector<SourceText> mLastRoots;
};

}  // namespace varc::includes::testing
