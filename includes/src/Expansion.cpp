// SPDX-License-Identifier: Apache-2.0
// One IncludeResolver::expand() call: splices files, tracks guards and writes #line mapping.
#include "Expansion.h"

#include <algorithm>

#include "LineDirective.h"
#include "LineScanner.h"
#include "varc/core/Check.h"

namespace varc::includes {

namespace {

std::string fileName(const std::string& path) {
    size_t slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string join(const std::vector<std::string>& items, const char* separator) {
    std::string text;
    for (size_t i = 0; i < items.size(); ++i) {
        if (i > 0) text += separator;
        text += items[i];
    }
    return text;
}

// The name with the delimiters it was written with: "a.cginc" or <a.cginc>.
std::string asWritten(const Directive& directive) {
    return directive.angled ? "<" + directive.argument + ">" : "\"" + directive.argument + "\"";
}

std::string onceMacro(FileId id) { return "VARC_ONCE_" + std::to_string(id); }

}  // namespace

Expansion::Expansion(const FileSystem& fileSystem, SourceMap& sourceMap,
                     const IncludeOptions& options, ScanCache& scans, DiagnosticSink& sink)
    : mFileSystem(fileSystem),
      mSourceMap(sourceMap),
      mScans(scans),
      mSink(sink),
      mLocator(fileSystem, sourceMap, options) {}

std::optional<ExpandedSource> Expansion::run(const std::vector<SourceText>& roots) {
    for (const SourceText& root : roots) {
        VARC_CHECK(root.origin.file < mSourceMap.size())
            << "SourceText origin.file must be registered in the SourceMap";
        mRootFiles.insert(root.origin.file);
    }
    for (size_t i = 0; i < roots.size(); ++i) expandRoot(roots[i], i == 0);
    if (mFailed) return std::nullopt;
    return std::move(mResult);
}

// A root that is a whole registered file (origin 1:1, same text) is treated as a splice of that
// file, so its guard is honoured and a later #include of it is a no-op.
void Expansion::expandRoot(const SourceText& root, bool first) {
    Frame frame;
    frame.file = root.origin.file;
    frame.firstLine = std::max<uint32_t>(root.origin.line, 1);
    frame.firstColumnOffset = root.origin.column > 1 ? root.origin.column - 1 : 0;
    frame.shortName = fileName(mSourceMap.path(frame.file));
    frame.collectPragmas = true;
    bool wholeFile = frame.firstLine == 1 && frame.firstColumnOffset == 0 &&
                     root.text == mSourceMap.contents(frame.file);
    if (wholeFile) {
        frame.scan = &mScans.get(mSourceMap, frame.file);
        frame.guardTransparent = frame.scan->guard.kind == GuardKind::Macro;
        SpliceRecord& record = mSplices[frame.file];
        record.spliced = true;
        record.unconditional = record.unconditional || mDepth == 0;
    } else {
        mRootScans.push_back(std::make_unique<ScannedFile>(LineScanner::scan(root.text)));
        frame.scan = mRootScans.back().get();
    }
    if (first) syncTo(frame.file, frame.firstLine);
    expandFrame(frame);
}

void Expansion::expandFrame(const Frame& frame) {
    mStack.push_back(&frame);
    const std::vector<LogicalLine>& lines = frame.scan->lines;
    for (size_t i = 0; i < lines.size(); ++i) {
        if (lines[i].isDirective) {
            processDirective(frame, i);
        } else {
            emitLines(frame, lines[i].firstLine, lines[i].lastLine);
        }
    }
    if (frame.scan->unterminatedComment) {
        report(Severity::Error, locate(frame, *frame.scan->unterminatedComment),
               "unterminated /* comment");
    }
    mStack.pop_back();
}

void Expansion::processDirective(const Frame& frame, size_t index) {
    const LogicalLine& line = frame.scan->lines[index];
    const Directive& directive = line.directive;
    const IncludeGuard& guard = frame.scan->guard;
    bool guardLine =
        frame.guardTransparent && (index == guard.openLine || index == guard.closeLine);
    switch (directive.kind) {
        case DirectiveKind::Include:
            handleInclude(frame, line);
            return;
        case DirectiveKind::MalformedInclude:
            report(Severity::Error, locate(frame, directive.argumentOffset), directive.error);
            beginReplacement(frame, line);
            endReplacement(frame, line);
            return;
        case DirectiveKind::Pragma:
            if (frame.collectPragmas) collectPragma(frame, directive);
            break;
        case DirectiveKind::If:
        case DirectiveKind::Ifdef:
        case DirectiveKind::Ifndef:
            if (!guardLine) ++mDepth;
            break;
        case DirectiveKind::Endif:
            if (!guardLine && mDepth > 0) --mDepth;
            break;
        default:
            break;
    }
    emitLines(frame, line.firstLine, line.lastLine);
}

void Expansion::handleInclude(const Frame& frame, const LogicalLine& line) {
    const Directive& directive = line.directive;
    SourceLocation where = locate(frame, directive.argumentOffset);
    if (directive.extraTokensOffset) {
        report(Severity::Warning, locate(frame, *directive.extraTokensOffset),
               "extra tokens at end of #include directive");
    }
    std::vector<std::string> searched;
    bool caseDiffers = false;
    std::optional<std::string> path = mLocator.locate(
        directive.argument, parentPath(mSourceMap.path(frame.file)), searched, &caseDiffers);
    if (!path) {
        reportMissing(frame, line, searched);
        return;
    }
    if (caseDiffers) {
        report(Severity::Warning, where,
               "include file " + asWritten(directive) + " found as '" + *path +
                   "', whose name differs in case; this works on case-insensitive file "
                   "systems only");
    }
    std::optional<FileId> id = load(*path);
    const ScannedFile* scan = id ? &mScans.get(mSourceMap, *id) : nullptr;
    if (!id) {
        report(Severity::Error, where,
               "cannot read include file " + asWritten(directive) + " (" + *path + ")");
    } else if (onStack(*id) && scan->guard.kind == GuardKind::None) {
        report(Severity::Error, where, "include cycle: " + cycleChain(*id, directive.argument));
    } else if (scan->guard.kind != GuardKind::None &&
               (onStack(*id) || mSplices[*id].unconditional)) {
        // Already in the output where every variant sees it: the #include becomes a no-op.
        if (directive.withPragmas && frame.collectPragmas) collectPragmasOnce(*id, *scan);
    } else if (mStack.size() >= kMaxIncludeDepth) {
        report(Severity::Error, where,
               "#include nested too deeply: " + asWritten(directive) + " would be file " +
                   std::to_string(mStack.size() + 1) + " of one chain; at most " +
                   std::to_string(kMaxIncludeDepth) + " are allowed");
    } else {
        splice(frame, line, *id, *scan);
        return;
    }
    beginReplacement(frame, line);
    endReplacement(frame, line);
}

// Replaces |line| by the contents of |id|. A `#pragma once` file that may appear twice (its
// first splice sat inside an #if) is wrapped in a VARC_ONCE_<id> guard so the real
// preprocessor keeps only one copy, as it does for #ifndef-guarded files.
void Expansion::splice(const Frame& frame, const LogicalLine& line, FileId id,
                       const ScannedFile& scan) {
    const Directive& directive = line.directive;
    Frame child;
    child.file = id;
    child.scan = &scan;
    child.shortName = directive.argument;
    child.includedFrom = locate(frame, directive.argumentOffset);
    child.collectPragmas =
        frame.collectPragmas && directive.withPragmas && mPragmaFiles.insert(id).second;
    child.guardTransparent = scan.guard.kind == GuardKind::Macro;
    SpliceRecord& record = mSplices[id];
    bool wrap = scan.guard.kind == GuardKind::PragmaOnce && (mDepth > 0 || record.spliced);
    record.spliced = true;
    record.unconditional = record.unconditional || mDepth == 0;
    beginReplacement(frame, line);
    if (wrap) {
        emitSynthetic("#ifndef " + onceMacro(id));
        emitSynthetic("#define " + onceMacro(id));
    }
    expandFrame(child);
    if (wrap) emitSynthetic("#endif // " + onceMacro(id));
    endReplacement(frame, line);
}

// Outside any #if a missing file is an error. Inside one it may be a platform-specific include
// that this build never reaches, so it becomes an #error that only fires in variants whose
// preprocessing gets there.
void Expansion::reportMissing(const Frame& frame, const LogicalLine& line,
                              const std::vector<std::string>& searched) {
    const Directive& directive = line.directive;
    beginReplacement(frame, line);
    if (mDepth > 0) {
        syncTo(frame.file, frame.firstLine + line.firstLine);
        appendLine("#error varc: cannot find include file " + asWritten(directive));
    } else {
        std::string message = "cannot find include file " + asWritten(directive);
        if (!searched.empty()) message += "; searched: " + join(searched, ", ");
        report(Severity::Error, locate(frame, directive.argumentOffset), std::move(message));
    }
    endReplacement(frame, line);
}

// Reads |path| once per SourceMap: a registered file is taken from the map.
std::optional<FileId> Expansion::load(const std::string& path) {
    std::optional<FileId> id = mSourceMap.find(path);
    if (!id) {
        std::optional<std::string> text = mFileSystem.read(path);
        if (!text) return std::nullopt;
        // Most include files saved by Windows editors start with a UTF-8 byte-order mark (some
        // with two, saved by two tools); they are not part of the program text (columns of the
        // first line count from after them).
        while (text->starts_with("\xEF\xBB\xBF")) text->erase(0, 3);
        id = mSourceMap.addFile(path, std::move(*text));
    }
    if (!mRootFiles.count(*id) && mDependencyIds.insert(*id).second) {
        mResult.dependencies.push_back(mSourceMap.path(*id));
    }
    return id;
}

bool Expansion::onStack(FileId id) const {
    return std::any_of(mStack.begin(), mStack.end(),
                       [id](const Frame* frame) { return frame->file == id; });
}

// "a.cginc -> b.cginc -> a.cginc": from the first frame of |id| to the offending |name|.
std::string Expansion::cycleChain(FileId id, const std::string& name) const {
    std::vector<std::string> names;
    auto first = std::find_if(mStack.begin(), mStack.end(),
                              [id](const Frame* frame) { return frame->file == id; });
    for (auto it = first; it != mStack.end(); ++it) names.push_back((*it)->shortName);
    names.push_back(name);
    return join(names, " -> ");
}

// Attaches the include stack, innermost first, as clang does.
void Expansion::report(Severity severity, SourceLocation location, std::string message) {
    Diagnostic diagnostic{severity, location, std::move(message), {}};
    for (size_t i = mStack.size(); i-- > 0;) {
        if (mStack[i]->includedFrom.isKnown()) {
            diagnostic.notes.push_back({mStack[i]->includedFrom, "in file included from here"});
        }
    }
    if (severity == Severity::Error) mFailed = true;
    mSink.report(std::move(diagnostic));
}

SourceLocation Expansion::locate(const Frame& frame, size_t offset) const {
    ScannedFile::Position position = frame.scan->position(offset);
    uint32_t column = position.column + (position.lineIndex == 0 ? frame.firstColumnOffset : 0);
    return {frame.file, frame.firstLine + position.lineIndex, column};
}

void Expansion::collectPragma(const Frame& frame, const Directive& directive) {
    mResult.pragmas.push_back({directive.argument, locate(frame, directive.hashOffset)});
}

// For an #include_with_pragmas whose splice is skipped by the guard: its pragmas still count.
void Expansion::collectPragmasOnce(FileId id, const ScannedFile& scan) {
    if (!mPragmaFiles.insert(id).second) return;
    Frame frame;
    frame.file = id;
    frame.scan = &scan;
    for (const LogicalLine& line : scan.lines) {
        if (line.isDirective && line.directive.kind == DirectiveKind::Pragma) {
            collectPragma(frame, line.directive);
        }
    }
}

void Expansion::emitLines(const Frame& frame, uint32_t first, uint32_t last) {
    for (uint32_t i = first; i <= last; ++i) {
        syncTo(frame.file, frame.firstLine + i);
        appendLine(frame.scan->physicalLine(i));
    }
}

// A line of varc's own making: whatever follows needs a fresh #line.
void Expansion::emitSynthetic(std::string_view text) {
    appendLine(text);
    mOutFile = kNoFile;
}

void Expansion::appendLine(std::string_view text) {
    mResult.text.append(text);
    mResult.text.push_back('\n');
    ++mOutLine;
}

void Expansion::syncTo(FileId file, uint32_t line) {
    if (file == mOutFile && line == mOutLine) return;
    writeLineDirective(mResult.text, line, file);
    mOutFile = file;
    mOutLine = line;
}

// An #include line that starts inside a /* */ comment keeps the comment's closing part, so the
// comment does not swallow what is spliced in.
void Expansion::beginReplacement(const Frame& frame, const LogicalLine& line) {
    if (!line.startsInComment) return;
    size_t begin = frame.scan->lineStarts[line.firstLine];
    syncTo(frame.file, frame.firstLine + line.firstLine);
    emitSynthetic(frame.scan->text.substr(begin, line.commentTailEnd - begin));
}

// An #include line that ends inside a /* comment reopens it, so the lines after it stay
// commented out. Otherwise nothing is written: the next line's #line resynchronises.
void Expansion::endReplacement(const Frame& frame, const LogicalLine& line) {
    if (!line.endsInComment) return;
    size_t lineBegin = frame.scan->lineStarts[line.lastLine];
    std::string_view physical = frame.scan->physicalLine(line.lastLine);
    std::string_view head = "/*";
    if (line.openCommentBegin >= lineBegin) {
        head = physical.substr(line.openCommentBegin - lineBegin);
    }
    syncTo(frame.file, frame.firstLine + line.lastLine);
    appendLine(head);
}

}  // namespace varc::includes
