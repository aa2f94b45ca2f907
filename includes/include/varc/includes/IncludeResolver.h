// SPDX-License-Identifier: Apache-2.0
// Splices #include files into a program block, with guards, cycle checks and #line mapping.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/core/PragmaLine.h"
#include "varc/includes/FileSystem.h"
#include "varc/includes/SourceMap.h"

namespace varc::includes {

class ScanCache;

// The most files one #include chain may hold open (the shader itself counts): expansion is
// recursive, so a generated chain of thousands of files is refused instead of exhausting the
// stack. Real shaders nest a handful deep.
inline constexpr size_t kMaxIncludeDepth = 64;

// Where `#include "name"` is searched, in order, after the including file's own directory.
struct IncludeOptions {
    std::vector<std::string> includeDirs;  // -I directories, in command-line order
    std::string builtinDir;                // varc's built-in include directory ("" = none)
    // Where `#include "Assets/..."` and `"Packages/..."` (paths written from a Unity project's
    // root) are found; "" = the nearest ancestor of the including file that has them.
    std::string projectRoot;
    // A Unity project's own map (varc --project), tried in order before |projectRoot|: a name
    // that starts with "<prefix>/" is looked up as "<folder>/<rest>". Prefixes are "Assets" and
    // "Packages/<package name>"; a prefix may repeat with other folders (shader overlays).
    struct VirtualRoot {
        std::string prefix;
        std::string folder;
    };
    std::vector<VirtualRoot> virtualRoots;
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
    // The `#pragma` lines Unity honours, in text order: from the root texts themselves and from
    // files pulled in with `#include_with_pragmas` by a root (or by such a file, every link of the
    // chain being #include_with_pragmas). Pragmas in plain #include files, and in anything
    // reached through one, are ignored. Lines in // or /* */ comments never count; #if is not
    // evaluated. A file's pragmas are collected once per expansion.
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
//    The conditional a guard itself opens does not count as "inside a conditional block".
//    A `#pragma once` file that may be spliced twice is wrapped in `#ifndef VARC_ONCE_<id>` /
//    `#define VARC_ONCE_<id>` ... `#endif // VARC_ONCE_<id>` so only one copy is compiled.
//  * Errors: missing file (at the #include, listing the directories searched), include cycle
//    (naming the chain "a.cginc -> b.cginc -> a.cginc"), malformed #include; each with
//    `note: in file included from here` notes for the include stack, innermost first.
//    A missing file inside an #if block is not an error: the #include becomes
//    `#error varc: cannot find include file "x"`, which fails only in variants that reach it.
//  * Directives inside // and /* */ comments are ignored; `\` continuations join lines.
//  * Each file is read once per SourceMap (a registered path is taken from the map) and
//    scanned once per resolver. Not thread-safe.
class IncludeResolver {
public:
    // |fileSystem| and |sourceMap| are borrowed and must outlive the resolver.
    IncludeResolver(const FileSystem& fileSystem, SourceMap& sourceMap, IncludeOptions options);
    ~IncludeResolver();
    IncludeResolver(IncludeResolver&&) noexcept;

    // Splices |roots| in order into one text (e.g. a pass's CGINCLUDE blocks, then its
    // CGPROGRAM block), sharing guard state. The text starts with `#line` for roots[0].origin;
    // each #include line is replaced by the file's text. Returns nullopt after reporting at
    // least one error to |sink| (warnings alone do not fail). Example: root "#include \"b.h\"
    // \nx\n" at shader.shader:5:1 (FileId 0), b.h = "y\n" (FileId 1) gives
    // "#line 5 0\n#line 1 1\ny\n#line 6 0\nx\n".
    std::optional<ExpandedSource> expand(const std::vector<SourceText>& roots,
                                         DiagnosticSink& sink);

private:
    const FileSystem& mFileSystem;
    SourceMap& mSourceMap;
    IncludeOptions mOptions;
    std::unique_ptr<ScanCache> mScanCache;  // scans of included files, by FileId
};

}  // namespace varc::includes
