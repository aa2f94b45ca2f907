// SPDX-License-Identifier: Apache-2.0
// One IncludeResolver::expand() call: splices files, tracks guards and writes #line mapping.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "IncludeLocator.h"
#include "ScanCache.h"
#include "ScannedFile.h"
#include "varc/includes/IncludeResolver.h"

namespace varc::includes {

// The state of one expansion. Files are spliced recursively, one Frame per file on the include
// stack. Output lines are numbered as they are written (mOutFile/mOutLine): a `#line` is
// written only when the next line is not the one the reader already expects, which happens
// exactly at switches between files and after a removed #include line.
class Expansion {
public:
    // All arguments are borrowed for the duration of run().
    Expansion(const FileSystem& fileSystem, SourceMap& sourceMap, const IncludeOptions& options,
              ScanCache& scans, DiagnosticSink& sink);

    // Expands |roots| in order; see IncludeResolver::expand.
    std::optional<ExpandedSource> run(const std::vector<SourceText>& roots);

private:
    struct Frame {
        FileId file = kNoFile;
        const ScannedFile* scan = nullptr;
        uint32_t firstLine = 1;          // line number of physical line 0
        uint32_t firstColumnOffset = 0;  // added to columns on physical line 0
        std::string shortName;           // the name as written; the file name for roots
        SourceLocation includedFrom;     // the #include in the parent; unknown for roots
        bool collectPragmas = false;
        bool guardTransparent = false;  // its Macro guard lines are not counted as conditionals
    };
    struct SpliceRecord {
        bool spliced = false;
        bool unconditional = false;  // spliced outside every #if: later includes are no-ops
    };

    void expandRoot(const SourceText& root, bool first);
    void expandFrame(const Frame& frame);
    void processDirective(const Frame& frame, size_t index);
    void handleInclude(const Frame& frame, const LogicalLine& line);
    void splice(const Frame& frame, const LogicalLine& line, FileId id, const ScannedFile& scan);
    void reportMissing(const Frame& frame, const LogicalLine& line,
                       const std::vector<std::string>& searched);
    std::optional<FileId> load(const std::string& path);
    bool onStack(FileId id) const;
    std::string cycleChain(FileId id, const std::string& name) const;
    void report(Severity severity, SourceLocation location, std::string message);
    SourceLocation locate(const Frame& frame, size_t offset) const;
    void collectPragma(const Frame& frame, const Directive& directive);
    void collectPragmasOnce(FileId id, const ScannedFile& scan);

    void emitLines(const Frame& frame, uint32_t first, uint32_t last);
    void emitSynthetic(std::string_view text);
    void appendLine(std::string_view text);
    void syncTo(FileId file, uint32_t line);
    void beginReplacement(const Frame& frame, const LogicalLine& line);
    void endReplacement(const Frame& frame, const LogicalLine& line);

    const FileSystem& mFileSystem;
    SourceMap& mSourceMap;
    ScanCache& mScans;
    DiagnosticSink& mSink;
    IncludeLocator mLocator;

    std::vector<const Frame*> mStack;
    std::unordered_map<FileId, SpliceRecord> mSplices;
    std::unordered_set<FileId> mPragmaFiles;  // included files whose pragmas were collected
    std::unordered_set<FileId> mRootFiles;
    std::unordered_set<FileId> mDependencyIds;
    std::vector<std::unique_ptr<ScannedFile>> mRootScans;
    size_t mDepth = 0;  // #if/#ifdef/#ifndef nesting across the whole output
    FileId mOutFile = kNoFile;
    uint32_t mOutLine = 0;
    ExpandedSource mResult;
    bool mFailed = false;
};

}  // namespace varc::includes
