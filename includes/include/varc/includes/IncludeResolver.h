// SPDX-License-Identifier: Apache-2.0
// Splices #include files into a program block, with guards, cycle checks and #line mapping.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/core/PragmaLine.h"
#include "varc/includes/FileSystem.h"
#include "varc/includes/SourceMap.h"

namespace varc::includes {

// Where `#include "name"` is searched, in order, after the including file's own directory.
struct IncludeOptions {
    std::vector<std::string> includeDirs;  // -I directories, in command-line order
    std::string builtinDir;                // varc's built-in include directory ("" = none)
};

// A piece of source to expand: text that lives at |origin| (a whole file, or a CGPROGRAM
// block starting at some line and column of a .shader file).
struct SourceText {
    std::string text;
    SourceLocation origin;  // location of text[0]; origin.file must be registered
};

struct ExpandedSource {
    // The spliced text. Every switch between files is marked with `#line <line> <fileId>`
    // (the number of the *next* line), so any later line maps back to its origin.
    std::string text;
    // The `#pragma` lines Unity honours: from the root text itself or from a file pulled in with
    // `#include_with_pragmas` directly from the root. Pragmas in plain #include files are ignored.
    std::vector<PragmaLine> pragmas;
    // Every file read (not the root), normalised paths, in first-read order, for depfiles and
    // cache keys.
    std::vector<std::string> dependencies;
};

// Expands includes in source text. Rules:
//  * `#include "name"` and `#include <name>` (spaces allowed in the name) are looked up
//    relative to the including file, then each -I dir, then the built-in dir.
//  * `#include_with_pragmas "name"` splices the same way and also collects its #pragma lines.
//  * A file guarded by `#pragma once` or by `#ifndef X`/`#if !defined(X)` + `#define X` ...
//    `#endif` around the whole file is spliced once per expansion (again only if the first
//    splice sat inside a conditional block, since that one may have been compiled out).
//  * Errors: missing file (at the #include, listing the directories searched), include cycle
//    (naming the chain "a.cginc -> b.cginc -> a.cginc"), malformed #include; each with
//    `note: in file included from ...` notes for the include stack.
class IncludeResolver {
public:
    IncludeResolver(const FileSystem& fileSystem, SourceMap& sourceMap, IncludeOptions options);

    // Splices |roots| in order into one text (e.g. a pass's CGINCLUDE blocks, then its
    // CGPROGRAM block), sharing guard state. The text starts with `#line` for roots[0].origin.
    // Returns nullopt after reporting at least one error to |sink|.
    std::optional<ExpandedSource> expand(const std::vector<SourceText>& roots,
                                         DiagnosticSink& sink);

private:
    const FileSystem& mFileSystem;
    SourceMap& mSourceMap;
    IncludeOptions mOptions;
};

}  // namespace varc::includes
