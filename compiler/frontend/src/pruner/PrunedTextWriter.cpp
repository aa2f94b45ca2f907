// SPDX-License-Identifier: Apache-2.0
// Writes the kept declarations and directives of a program with #lines that keep its numbering.
#include "pruner/PrunedTextWriter.h"

#include <string_view>

#include "varc/core/Trim.h"

namespace varc::frontend::pruner {

std::string PrunedTextWriter::write(const std::vector<const Declaration*>& kept) {
    mOut.clear();
    mOutLines = 0;
    mHaveLineDirective = false;
    const auto pieces = collectPieces(kept);
    const std::vector<DirectiveLine>& directives = mTokenizer.directives();
    size_t nextDirective = 0;
    const std::string_view code(mTokenizer.code());
    for (size_t line = 0; line < mTokenizer.lineCount(); ++line) {
        if (nextDirective < directives.size() && directives[nextDirective].line == line) {
            const DirectiveLine& directive = directives[nextDirective++];
            if (!LineOriginMap::isLineDirective(directive.text)) {
                writeDirective(line, directive.text);
            }
            continue;
        }
        std::string text;
        for (const auto& [begin, end] : pieces[line]) {
            if (!text.empty()) text += ' ';
            text += trimRight(code.substr(begin, end - begin), " \t\r");
        }
        if (!text.empty()) writeCode(line, text);
    }
    return std::move(mOut);
}

// For each input line, the [begin, end) offsets of the kept text on it, in order.
std::vector<std::vector<std::pair<size_t, size_t>>> PrunedTextWriter::collectPieces(
    const std::vector<const Declaration*>& kept) const {
    std::vector<std::vector<std::pair<size_t, size_t>>> pieces(mTokenizer.lineCount());
    const std::vector<Token>& tokens = mTokenizer.tokens();
    for (const Declaration* decl : kept) {
        const Token& first = tokens[decl->begin];
        const Token& last = tokens[decl->end - 1];
        const size_t declEnd = mTokenizer.offsetOf(last) + last.text.size();
        for (size_t i = decl->begin; i < decl->end; ++i) {
            const size_t line = tokens[i].line;
            if (i > decl->begin && tokens[i - 1].line == line) continue;  // line already added
            const size_t begin =
                line == first.line ? mTokenizer.offsetOf(first) : mTokenizer.lineBegin(line);
            const size_t end = line == last.line ? declEnd : mTokenizer.lineEnd(line);
            pieces[line].emplace_back(begin, end);
        }
    }
    return pieces;
}

void PrunedTextWriter::writeCode(size_t line, const std::string& text) {
    const LineOrigin& origin = mOrigins.origin(line);
    if (!origin.afterLineDirective) {
        padTo(line);
    } else if (!mHaveLineDirective || !(mNext == origin)) {
        mOut += "#line " + std::to_string(origin.line);
        if (origin.hasSource) {
            mOut += ' ';
            mOut += origin.source;
        }
        mOut += '\n';
        ++mOutLines;
        mHaveLineDirective = true;
        mNext = origin;
    }
    mOut += text;
    mOut += '\n';
    ++mOutLines;
    ++mNext.line;
}

void PrunedTextWriter::writeDirective(size_t line, const std::string& text) {
    if (!mOrigins.origin(line).afterLineDirective) padTo(line);
    mOut += text;
    mOut += '\n';
    ++mOutLines;
    ++mNext.line;
}

void PrunedTextWriter::padTo(size_t line) {
    while (mOutLines < line) {
        mOut += '\n';
        ++mOutLines;
    }
}

}  // namespace varc::frontend::pruner
