// SPDX-License-Identifier: Apache-2.0
// Maps each physical line of a preprocessed program to the (source, line) its #lines give it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "pruner/ShaderTokenizer.h"

namespace varc::frontend::pruner {

struct LineOrigin {
    bool afterLineDirective = false;  // false: no #line above; |line| is the physical line
    bool hasSource = false;           // a #line above named a source string
    std::string_view source;          // that source string as written ("3", "\"a.h\"")
    uint64_t line = 0;

    bool operator==(const LineOrigin&) const = default;
};

class LineOriginMap {
public:
    // Computes the origin of each of |lineCount| physical lines from the `#line` entries of
    // |directives| (sorted by line; the strings must outlive this map). The numbering uses the
    // convention that `#line N` names the line *after* it; callers that write directives with
    // the same convention reproduce the input's mapping even where glslang uses the other one.
    // Returns false on a malformed #line.
    // Example: lines {"a", "#line 10 2", "b", "c"} give {phys 1}, {phys 2}, {2, 10}, {2, 11}.
    bool build(const std::vector<DirectiveLine>& directives, size_t lineCount);

    const LineOrigin& origin(size_t line) const { return mOrigins[line]; }

    // True for `#line ...` and `# line ...`; other directives are kept verbatim by the pruner.
    static bool isLineDirective(std::string_view text);

private:
    std::vector<LineOrigin> mOrigins;
};

}  // namespace varc::frontend::pruner
