// SPDX-License-Identifier: Apache-2.0
// Writes the kept declarations and directives of a program with #lines that keep its numbering.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "pruner/Declaration.h"
#include "pruner/LineOriginMap.h"
#include "pruner/ShaderTokenizer.h"

namespace varc::frontend::pruner {

class PrunedTextWriter {
public:
    PrunedTextWriter(const ShaderTokenizer& tokenizer, const LineOriginMap& origins)
        : mTokenizer(tokenizer), mOrigins(origins) {}

    // Writes, in input order, every directive except #line and the parts of each input line
    // covered by a declaration in |kept|: a declaration's first line starts at its first token,
    // its last ends at its last token, lines without its tokens are skipped, and pieces of
    // several kept declarations on one line are joined with a space.
    //
    // Why a #line per gap rather than blank lines: the text must not depend on what was removed.
    // Each code line after the input's first #line is preceded by `#line L` / `#line L S` when
    // the previous output line does not already number it L (in source S), e.g. input
    //     #line 7 1 / float4x4 M; / float4 unused; / <blank> / float4 f() { return M[0]; }
    // keeping M and f gives
    //     #line 7 1 / float4x4 M; / #line 10 1 / float4 f() { return M[0]; }
    // L follows the input's convention (LineOriginMap), so if glslang reads `#line N` as naming
    // the current line instead, input and output are both off by the same one. Lines before the
    // input's first #line are padded with blank lines to their physical line instead, since
    // there no convention-independent directive exists.
    std::string write(const std::vector<const Declaration*>& kept);

private:
    std::vector<std::vector<std::pair<size_t, size_t>>> collectPieces(
        const std::vector<const Declaration*>& kept) const;
    void writeCode(size_t line, const std::string& text);
    void writeDirective(size_t line, const std::string& text);
    void padTo(size_t line);

    const ShaderTokenizer& mTokenizer;
    const LineOriginMap& mOrigins;
    std::string mOut;
    size_t mOutLines = 0;  // lines written so far
    bool mHaveLineDirective = false;
    LineOrigin mNext;  // what the next output line maps to, once a #line is written
};

}  // namespace varc::frontend::pruner
